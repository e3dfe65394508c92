// Job-shop anytime figures (issue 29): the planner's engines against MiniZinc with Gecode on
// the standard disjunctive model, in the same run, on instance files given on the command line
// (OR-Library format, each with its known optimum): the best makespan at each checkpoint, the
// time of a proof, every plan validated; the curves as CSV and as an SVG picture.
//
//   jobshop_bench --instance la06:926 --instance ft10:930 --seconds 30 --svg curves.svg
//
// An instance is FILE:OPTIMUM; a FILE without a directory is looked for in --jobshop-dir.
// Gecode's times count from minizinc's start (flattening, about 0.3 s, included); the
// planner's from make_plan's (the model is built before). The machine is shared: compare
// figures of one run only.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "anytime_svg.hpp"
#include "jobshop_file.hpp"
#include "minizinc_baseline.hpp"
#include "plan_validator.hpp"
#include "planner.hpp"

using namespace autonomy::planner;
using namespace autonomy::bench;
using Clock = std::chrono::steady_clock;

namespace {

// The best makespan at time t of an improving curve; -1 before the first.
long at(const std::vector<std::pair<double, long>>& curve, double t) {
  long best = -1;
  for (const auto& [s, m] : curve)
    if (s <= t) best = m;
  return best;
}

std::string gap_text(long makespan, long optimum) {
  if (makespan < 0) return "-";
  char text[64];
  std::snprintf(text, sizeof text, "%ld (+%.1f%%)", makespan,
                100.0 * double(makespan - optimum) / double(optimum));
  return text;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Job-shop anytime curves: planner engines against MiniZinc with Gecode"};
  std::vector<std::string> instances;
  std::vector<std::string> engines{"chronological", "lns"};
  std::vector<double> checkpoints{1, 10, 60};
  std::string jobshop_dir = "services/planner/examples/jobshop", minizinc_model = "bench/jobshop.mzn";
  std::string csv_file, svg_file;
  int seconds = 60;
  unsigned seed = 1;
  std::size_t neighbourhood_decisions = EngineOptions{}.neighbourhood_decisions;
  bool no_gecode = false, not_first_not_last = false;
  app.add_option("--instance", instances, "FILE:OPTIMUM (repeatable)")->required();
  app.add_option("--jobshop-dir", jobshop_dir, "where a FILE without a directory is");
  app.add_option("--engines", engines, "planner engines")->capture_default_str();
  app.add_option("--seconds", seconds, "time limit per instance and solver")->capture_default_str();
  app.add_option("--checkpoints", checkpoints, "times the best makespans are reported at");
  app.add_option("--seed", seed, "the engines' seed")->capture_default_str();
  app.add_option("--neighbourhood-decisions", neighbourhood_decisions,
                 "lns: the decision budget of each neighbourhood")
      ->capture_default_str();
  app.add_option("--minizinc-model", minizinc_model, "the disjunctive job-shop model");
  app.add_flag("--no-gecode", no_gecode, "leave the MiniZinc baseline out");
  app.add_flag("--not-first-not-last", not_first_not_last,
               "also run each engine with not-first/not-last propagation (solver name +nfnl)");
  app.add_option("--csv", csv_file, "write every curve point here (instance,solver,seconds,makespan)");
  app.add_option("--svg", svg_file, "write the curves here as a picture");
  CLI11_PARSE(app, argc, argv);
  if (seconds <= 0 || neighbourhood_decisions == 0) {
    std::fprintf(stderr, "--seconds and --neighbourhood-decisions must be positive\n");
    return 2;
  }
  const bool gecode = !no_gecode && minizinc_with_gecode() &&
                      std::filesystem::exists(minizinc_model);
  if (!no_gecode && !gecode)
    std::printf("baseline skipped: minizinc with Gecode or %s not found (bench/install-minizinc.sh)\n",
                minizinc_model.c_str());

  std::vector<AnytimePanel> panels;
  std::string table = "| instance | optimum | solver |";
  for (double c : checkpoints) {
    char head[32];
    std::snprintf(head, sizeof head, " at %g s |", c);
    table += head;
  }
  table += " proved |\n|---|---|---|";
  for (std::size_t i = 0; i <= checkpoints.size(); ++i) table += "---|";
  table += "\n";
  for (const std::string& spec : instances) {
    const std::size_t colon = spec.rfind(':');
    long optimum = 0;
    if (colon == std::string::npos ||
        std::sscanf(spec.c_str() + colon + 1, "%ld", &optimum) != 1 || optimum <= 0) {
      std::fprintf(stderr, "--instance %s: expected FILE:OPTIMUM with a positive optimum\n",
                   spec.c_str());
      return 2;
    }
    std::string file = spec.substr(0, colon);
    if (file.find('/') == std::string::npos) file = jobshop_dir + "/" + file;
    const std::string name = std::filesystem::path(file).filename().string();
    auto shop = read_jobshop_file(file);
    if (!shop) return 2;
    const DomainModel* model = &shop->model;
    const PlanningProblem* problem = &shop->problem;
    const JobShopInstance* inst = &shop->instance;
    AnytimePanel panel{name, optimum, {}};
    std::vector<double> proofs;
    std::vector<std::pair<std::string, bool>> runs;  // engine, with not-first/not-last
    for (const std::string& engine : engines) {
      runs.push_back({engine, false});
      if (not_first_not_last) runs.push_back({engine, true});
    }
    for (const auto& [engine, nfnl] : runs) {
      AnytimeSeries series{engine + (nfnl ? "+nfnl" : ""), {}};
      PlanningOptions options;
      options.engine = engine;
      options.not_first_not_last = nfnl;
      options.engine_options.seed = seed;
      options.engine_options.neighbourhood_decisions = neighbourhood_decisions;
      const auto start = Clock::now();
      auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };
      options.termination.stop = [&] { return elapsed() > seconds; };
      options.on_improvement = [&](const FlexiblePlan& p) {
        series.points.push_back({elapsed(), long(p.makespan)});
      };
      const PlanResult r = make_plan(*model, *problem, options);
      const double s = elapsed();
      if (r.status == PlanStatus::kInvalidRequest) {
        std::fprintf(stderr, "%s\n", r.explanation.c_str());
        return 2;
      }
      if (r.plan && !validate_plan(*model, *problem, *r.plan).empty()) {
        std::fprintf(stderr, "%s: invalid schedule from %s\n", name.c_str(), engine.c_str());
        return 3;
      }
      if (r.plan && r.plan->makespan < optimum) {
        std::fprintf(stderr, "%s: %s found %lld, below the optimum given (%ld)\n", name.c_str(),
                     engine.c_str(), static_cast<long long>(r.plan->makespan), optimum);
        return 3;
      }
      proofs.push_back(r.status == PlanStatus::kOptimal ? s : -1);
      panel.series.push_back(std::move(series));
    }
    if (gecode) {
      const Baseline b = run_minizinc(minizinc_model, *inst, name, seconds);
      panel.series.push_back({"gecode", b.curve});
      proofs.push_back(b.ran && b.proved ? b.seconds : -1);
    }
    for (std::size_t k = 0; k < panel.series.size(); ++k) {
      const AnytimeSeries& series = panel.series[k];
      table += "| " + name + " | " + std::to_string(optimum) + " | " + series.solver + " |";
      for (double c : checkpoints) table += " " + gap_text(at(series.points, c), optimum) + " |";
      char proof[32] = "no";
      if (proofs[k] >= 0) std::snprintf(proof, sizeof proof, "%.2f s", proofs[k]);
      table += std::string(" ") + proof + " |\n";
    }
    std::printf("%s done\n", name.c_str());
    std::fflush(stdout);
    panels.push_back(std::move(panel));
  }
  std::printf("\n%s", table.c_str());
  if (!csv_file.empty()) {
    std::ofstream csv(csv_file);
    csv << "instance,solver,seconds,makespan\n";
    for (const AnytimePanel& p : panels)
      for (const AnytimeSeries& s : p.series)
        for (const auto& [t, m] : s.points)
          csv << p.instance << ',' << s.solver << ',' << t << ',' << m << '\n';
    if (!csv) {
      std::fprintf(stderr, "cannot write %s\n", csv_file.c_str());
      return 2;
    }
  }
  if (!svg_file.empty()) {
    std::ofstream svg(svg_file);
    svg << anytime_svg(panels, seconds);
    if (!svg) {
      std::fprintf(stderr, "cannot write %s\n", svg_file.c_str());
      return 2;
    }
  }
  return 0;
}
