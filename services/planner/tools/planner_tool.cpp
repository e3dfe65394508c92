// planner_tool: plans a model + problem (or an OR-Library job-shop instance) and prints the
// flexible plan as JSON; --svg writes a Gantt chart of the timelines with each token's
// flexibility drawn. The wall clock is read here, at the edge, for --seconds.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>

#include "gantt_svg.hpp"
#include "jobshop_instance.hpp"
#include "plan_json.hpp"
#include "plan_validator.hpp"
#include "planner.hpp"
#include "planner_language.hpp"

using namespace autonomy::planner;

int main(int argc, char** argv) {
  CLI::App app{"Plans a model and a problem; prints the flexible plan as JSON."};
  std::string model_file, problem_file, jobshop_file, svg_file, json_file, engine = "chronological";
  double seconds = 0;
  std::size_t max_decisions = 0;
  bool quiet = false;
  app.add_option("--model", model_file, "model file (planner language)");
  app.add_option("--problem", problem_file, "problem file (planner language)");
  app.add_option("--jobshop", jobshop_file,
                 "an OR-Library job-shop instance instead of model + problem");
  std::string engines;
  for (const std::string& n : search_engine_names()) engines += (engines.empty() ? "" : ", ") + n;
  unsigned seed = 1;
  app.add_option("--engine", engine, "search engine: " + engines)->capture_default_str();
  app.add_option("--seed", seed, "seed of the sampling, repair and lns engines")->capture_default_str();
  std::size_t first_dives = EngineOptions{}.first_dives;
  app.add_option("--first-dives", first_dives,
                 "lns: greedy dives for the first plan of a makespan problem (0: chronological)")
      ->capture_default_str();
  app.add_option("--seconds", seconds, "time budget (0: none)");
  app.add_option("--max-decisions", max_decisions, "decision budget (0: none)");
  app.add_option("--svg", svg_file, "write a Gantt chart of the plan here");
  app.add_option("--json", json_file, "write the plan here instead of standard output");
  app.add_flag("--quiet", quiet, "no plan on standard output, only the summary");
  bool backjumping = false;
  app.add_flag("--backjumping", backjumping,
               "chronological: conflict-directed backjumping instead of chronological backtracking");
  bool not_first_not_last = false;
  app.add_flag("--not-first-not-last", not_first_not_last,
               "not-first/not-last propagation on timelines beside edge finding");
  CLI11_PARSE(app, argc, argv);

  Diagnostics errors;
  std::optional<pb::Model> model_msg;
  std::optional<pb::Problem> problem_msg;
  if (!jobshop_file.empty()) {
    auto text = read_text_file(jobshop_file, &errors);
    auto inst = text ? parse_jobshop(*text, jobshop_file, &errors) : std::nullopt;
    if (inst) {
      model_msg = jobshop_model(*inst);
      problem_msg = jobshop_problem(*inst);
    }
  } else if (!model_file.empty() && !problem_file.empty()) {
    auto mt = read_text_file(model_file, &errors);
    auto pt = read_text_file(problem_file, &errors);
    if (mt) model_msg = parse_model(*mt, model_file, &errors);
    if (pt) problem_msg = parse_problem(*pt, problem_file, &errors);
  } else {
    std::cerr << "give --model and --problem, or --jobshop\n";
    return 2;
  }
  std::optional<DomainModel> model;
  std::optional<PlanningProblem> problem;
  if (model_msg && problem_msg && errors.empty()) model = build_domain_model(*model_msg, &errors);
  if (model) problem = build_problem(*model, *problem_msg, &errors);
  if (!problem) {
    std::cerr << to_string(errors);
    return 2;
  }

  if (backjumping && engine != "chronological") {
    std::cerr << "--backjumping is an option of --engine chronological, not of '" << engine << "'\n";
    return 2;
  }
  PlanningOptions options;
  options.engine = engine;
  options.engine_options.seed = seed;
  options.engine_options.first_dives = first_dives;
  options.engine_options.backjumping = backjumping;
  options.not_first_not_last = not_first_not_last;
  if (max_decisions) options.termination.max_decisions = max_decisions;
  const auto started = std::chrono::steady_clock::now();
  auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  };
  if (seconds > 0) options.termination.stop = [&] { return elapsed() > seconds; };
  options.on_improvement = [&](const FlexiblePlan& p) {
    std::fprintf(stderr, "plan: makespan %lld at %.3f s\n", static_cast<long long>(p.makespan),
                 elapsed());
  };
  PlanResult r = make_plan(*model, *problem, options);
  const double took = elapsed();
  std::fprintf(stderr, "status: %s\n", to_string(r.status));
  if (!r.explanation.empty()) std::fprintf(stderr, "why: %s\n", r.explanation.c_str());
  std::fprintf(stderr,
               "decisions %zu, backtracks %zu, dead ends %zu, temporal propagations %zu, "
               "procedure calls %zu, %.3f s\n",
               r.statistics.decisions, r.statistics.backtracks, r.statistics.dead_ends,
               r.statistics.temporal_propagations, r.statistics.procedure_calls, took);
  if (!r.plan) return r.status == PlanStatus::kInvalidRequest ? 2 : 1;
  std::printf("makespan %lld%s\n", static_cast<long long>(r.plan->makespan),
              r.status == PlanStatus::kOptimal ? " (proved optimal)" : "");
  for (const std::string& v : validate_plan(*model, *problem, *r.plan))
    std::fprintf(stderr, "INVALID: %s\n", v.c_str());
  const std::string json = plan_json(*r.plan);
  if (!json_file.empty()) {
    std::ofstream(json_file) << json;
  } else if (!quiet) {
    std::cout << json;
  }
  if (!svg_file.empty()) {
    std::ofstream out(svg_file);
    out << gantt_svg(*r.plan);
    if (!out) {
      std::cerr << svg_file << ": cannot write\n";
      return 2;
    }
  }
  return 0;
}
