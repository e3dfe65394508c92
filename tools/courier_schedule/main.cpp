// courier_schedule: reads a courier scheduling problem (JSON, schema in
// docs/courier-scheduling.md), runs one engine and prints the schedule, its objective terms and
// whether it is proved optimal as JSON on stdout, so that other tools can check it.
//
//   courier_schedule problem.json [--engine exact|large|paper] [--budget-ms 200] [--seed 1]
//
// Exit status: 0 a schedule; 3 no schedule (infeasible, or the budget ran out first; the JSON
// says which); 2 bad input (the file, the JSON path at fault, on stderr); CLI11's codes for bad
// arguments.
#include "services/courier/core/scheduler/schedule_json.hpp"
#include "services/courier/core/scheduler/scheduler_engine.hpp"
#include "services/courier/core/scheduler/wall_clock_budget.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

int main(int argc, char** argv) {
  using namespace autonomy::courier::scheduling;
  CLI::App app{
      "Schedules courier jobs: reads a problem (JSON: couriers, jobs, a travel-time matrix or a\n"
      "map with places, presence windows, handover times), runs an engine and prints the\n"
      "schedule as JSON. Exit 0 with a schedule, 3 without one, 2 on bad input."};
  std::string path;
  std::string engine_name = "exact";
  double budget_ms = 1000.0;
  std::uint64_t seed = 1;
  bool compact = false;
  app.add_option("problem", path, "problem JSON file")->required();
  app.add_option("--engine", engine_name, "exact | large | paper")
      ->check(CLI::IsMember(scheduler_engine_names()));
  app.add_option("--budget-ms", budget_ms,
                 "wall-clock budget (exact stops unproved, large "
                 "returns its best so far)")
      ->check(CLI::PositiveNumber);
  app.add_option("--seed", seed, "seed of the randomised engine (large)");
  app.add_flag("--compact", compact, "one-line JSON");
  CLI11_PARSE(app, argc, argv);

  std::ifstream in(path, std::ios::binary);
  if (!in) {
    std::cerr << "courier_schedule: cannot read " << path << "\n";
    return 2;
  }
  std::stringstream text;
  text << in.rdbuf();
  const std::string base_dir = std::filesystem::path(path).parent_path().string();
  const ParsedProblem parsed = problem_from_json_text(text.str(), path, base_dir);
  if (!parsed.ok()) {
    std::cerr << "courier_schedule: " << parsed.error << "\n";
    return 2;
  }
  auto engine = make_scheduler_engine(engine_name);
  const auto t0 = std::chrono::steady_clock::now();
  const JobSchedule schedule = engine->solve(
      parsed.problem,
      wall_clock_budget(std::chrono::microseconds(static_cast<long long>(budget_ms * 1000.0)),
                        seed));
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  nlohmann::json out = schedule_to_json(parsed.problem, schedule);
  out["elapsed_ms"] = ms;
  std::cout << (compact ? out.dump() : out.dump(2)) << "\n";
  return schedule.ok() ? 0 : 3;
}
