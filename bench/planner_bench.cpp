// Planner figures (issue 11), each against a baseline measured in the same run:
//  - the temporal network's incremental propagation per added constraint at 10,000
//    timepoints, against recomputing all bounds by Bellman-Ford;
//  - the DS1-like day (about 100 goals) and the rover, planned by the chronological engine,
//    beside the Remote Agent's 11 min 25 s on board Deep Space One (May 1999);
//  - the DS1-like day by every engine (iterative sampling gives up on it), against the
//    chronological engine;
//  - job-shop ft06 and la01-la05 by every engine within one decision budget: the makespans;
//  - job-shop ft06 and la01-la05 to a proof of optimality, against MiniZinc with Gecode on
//    the standard disjunctive model (bench/jobshop.mzn; bench/install-minizinc.sh installs it;
//    skipped, with how to install it, when minizinc is absent).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "jobshop_file.hpp"
#include "jobshop_instance.hpp"
#include "minizinc_baseline.hpp"
#include "plan_validator.hpp"
#include "planner.hpp"
#include "planner_language.hpp"
#include "temporal_network.hpp"

using namespace autonomy::planner;
using Clock = std::chrono::steady_clock;
using autonomy::bench::Baseline;
using autonomy::bench::minizinc_with_gecode;
using autonomy::bench::read_jobshop_file;
using autonomy::bench::run_minizinc;

namespace {

struct Edge {
  TimepointId from, to;
  Time w;
};

// The baseline: every bound recomputed from scratch (label-correcting passes to a fixed point).
void bellman_ford(std::size_t n, const std::vector<Edge>& edges, Time horizon,
                  std::vector<Time>& latest, std::vector<Time>& earliest) {
  latest.assign(n, horizon);
  earliest.assign(n, 0);
  latest[0] = 0;
  for (bool changed = true; changed;) {
    changed = false;
    for (const Edge& e : edges) {
      if (latest[e.from] + e.w < latest[e.to]) latest[e.to] = latest[e.from] + e.w, changed = true;
      if (earliest[e.to] - e.w > earliest[e.from])
        earliest[e.from] = earliest[e.to] - e.w, changed = true;
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Planner benchmarks"};
  std::size_t timepoints = 10000, added = 2000, baseline_added = 20;
  std::string examples = "services/planner/examples", jobshop_dir;
  std::string minizinc_model = "bench/jobshop.mzn";
  int jobshop_seconds = 30, repeats = 5;
  std::vector<std::string> jobshop_engines{"chronological", "discrepancy"};
  app.add_option("--timepoints", timepoints);
  app.add_option("--added", added, "constraints timed on the incremental network");
  app.add_option("--baseline-added", baseline_added, "constraints timed with full recomputation");
  app.add_option("--examples-dir", examples, "the planner's examples (ds1.model, rover.model)");
  app.add_option("--jobshop-dir", jobshop_dir, "default: <examples-dir>/jobshop");
  app.add_option("--minizinc-model", minizinc_model, "the disjunctive job-shop model");
  app.add_option("--jobshop-seconds", jobshop_seconds, "time limit per instance and solver");
  app.add_option("--jobshop-engines", jobshop_engines, "planner engines timed on job-shop");
  app.add_option("--repeats", repeats, "runs per model (the median is printed)");
  std::size_t budget_decisions = 20000, ds1_decisions = 200000;
  app.add_option("--budget-decisions", budget_decisions,
                 "decision budget of the every-engine job-shop comparison");
  app.add_option("--ds1-decisions", ds1_decisions, "decision budget of each engine on the DS1 day");
  CLI11_PARSE(app, argc, argv);
  if (jobshop_dir.empty()) jobshop_dir = examples + "/jobshop";

  const Time horizon = 100 * Time(timepoints);
  std::mt19937 rng(5);
  TemporalNetwork tn(horizon);
  std::vector<Edge> edges;
  auto add = [&](TimepointId a, TimepointId b, Time lb, Time ub) {
    if (!tn.add_constraint(a, b, lb, ub)) return false;
    edges.push_back({a, b, ub});
    edges.push_back({b, a, -lb});
    return true;
  };
  // A random forest of precedences with durations, like a plan's token network.
  for (std::size_t i = 1; i <= timepoints; ++i) {
    tn.add_timepoint();
    if (i > 1) {
      std::uniform_int_distribution<std::size_t> earlier(1, i - 1);
      add(earlier(rng), i, 1, 50);
    }
  }
  std::uniform_int_distribution<std::size_t> any(1, timepoints);
  std::uniform_int_distribution<Time> gap(0, 40);
  std::vector<std::array<Time, 4>> candidates;
  while (candidates.size() < added + baseline_added) {
    TimepointId a = any(rng), b = any(rng);
    if (a != b) candidates.push_back({Time(a), Time(b), gap(rng), 2000});
  }
  std::size_t accepted = 0;
  auto t0 = Clock::now();
  for (std::size_t k = 0; k < added; ++k)
    accepted += add(candidates[k][0], candidates[k][1], candidates[k][2], candidates[k][3]);
  const double incremental_us =
      std::chrono::duration<double, std::micro>(Clock::now() - t0).count() / double(added);
  // Baseline on the same network: the next (consistent) constraints, each followed by a full
  // recomputation; only the recomputation is timed.
  std::vector<Time> latest, earliest;
  double full_total = 0;
  std::size_t timed = 0;
  for (std::size_t k = added; k < added + baseline_added; ++k) {
    if (!add(candidates[k][0], candidates[k][1], candidates[k][2], candidates[k][3])) continue;
    const auto b0 = Clock::now();
    bellman_ford(timepoints + 1, edges, horizon, latest, earliest);
    full_total += std::chrono::duration<double, std::micro>(Clock::now() - b0).count();
    ++timed;
    // Same answer as the incremental network (a benchmark that computes the wrong thing is void).
    for (TimepointId t = 1; t <= timepoints; ++t)
      if (latest[t] != tn.latest(t) || earliest[t] != tn.earliest(t)) {
        std::fprintf(stderr, "mismatch at timepoint %zu\n", t);
        return 1;
      }
  }
  const double full_us = full_total / double(std::max<std::size_t>(timed, 1));
  std::printf(
      "temporal network, %zu timepoints: incremental %.1f us per added constraint (%zu of %zu "
      "consistent), "
      "full Bellman-Ford %.1f us, ratio %.0fx\n",
      timepoints, incremental_us, accepted, added, full_us, full_us / incremental_us);

  // The shipped models, planned from their files; every plan validated (a benchmark that
  // computes the wrong thing is void).
  constexpr double kRemoteAgentSeconds = 11 * 60 + 25;  // one horizon on board DS1, May 1999
  for (const auto& [model_name, problem_name] :
       {std::pair{"ds1.model", "ds1-day.problem"}, std::pair{"rover.model", "rover.problem"}}) {
    Diagnostics errors;
    const std::string mf = examples + "/" + model_name, pf = examples + "/" + problem_name;
    auto mt = read_text_file(mf, &errors);
    auto pt = read_text_file(pf, &errors);
    auto m = mt ? parse_model(*mt, mf, &errors) : std::nullopt;
    auto model = m ? build_domain_model(*m, &errors) : std::nullopt;
    auto p = (model && pt) ? parse_problem(*pt, pf, &errors) : std::nullopt;
    auto problem = p ? build_problem(*model, *p, &errors) : std::nullopt;
    if (!problem) {
      std::fprintf(stderr, "%s", to_string(errors).c_str());
      return 2;
    }
    std::size_t goals = 0;
    for (const FactDef& f : problem->facts) goals += !f.initial;
    std::vector<double> times;
    PlanResult r;
    for (int k = 0; k < std::max(repeats, 1); ++k) {
      const auto start = Clock::now();
      r = make_plan(*model, *problem, {});
      times.push_back(std::chrono::duration<double>(Clock::now() - start).count());
    }
    if (!r.plan || !validate_plan(*model, *problem, *r.plan).empty()) {
      std::fprintf(stderr, "%s: no valid plan (%s)\n", problem_name, to_string(r.status));
      return 3;
    }
    std::sort(times.begin(), times.end());
    const double median = times[times.size() / 2];
    std::printf(
        "%s (%zu goals): planned in %.3f s (median of %zu, min %.3f s), %zu tokens, "
        "%zu decisions, %zu backtracks",
        problem_name, goals, median, times.size(), times.front(), r.plan->tokens.size(),
        r.statistics.decisions, r.statistics.backtracks);
    if (std::string(model_name) == "ds1.model")
      std::printf("; Remote Agent on board DS1 (1999): 11 min 25 s, %.0fx",
                  kRemoteAgentSeconds / median);
    std::printf("\n");
    if (std::string(model_name) != "ds1.model") continue;
    // The day by every engine, against the chronological engine's median above.
    for (const std::string& engine : search_engine_names()) {
      PlanningOptions options;
      options.engine = engine;
      options.termination.max_decisions = ds1_decisions;
      std::vector<double> engine_times;
      PlanResult er;
      for (int k = 0; k < std::max(repeats, 1); ++k) {
        const auto start = Clock::now();
        er = make_plan(*model, *problem, options);
        engine_times.push_back(std::chrono::duration<double>(Clock::now() - start).count());
      }
      if (er.plan && !validate_plan(*model, *problem, *er.plan).empty()) {
        std::fprintf(stderr, "%s: invalid plan from %s\n", problem_name, engine.c_str());
        return 3;
      }
      std::sort(engine_times.begin(), engine_times.end());
      const double m = engine_times[engine_times.size() / 2];
      std::printf("%s%s %s", engine == search_engine_names().front() ? "" : " | ", "ds1 day",
                  engine.c_str());
      if (er.plan)
        std::printf(": %.3f s (%.2fx chronological), %zu decisions, %zu backtracks", m, m / median,
                    er.statistics.decisions, er.statistics.backtracks);
      else
        std::printf(": no plan (%s in %zu decisions, %.3f s)", to_string(er.status),
                    er.statistics.decisions, m);
    }
    std::printf("\n");
  }

  // Job-shop at one decision budget for every engine (deterministic: the same figures on any
  // machine): the makespan each finds, against the optimum.
  for (const auto& [name, optimum] :
       {std::pair{"ft06", 55}, std::pair{"la01", 666}, std::pair{"la02", 655},
        std::pair{"la03", 597}, std::pair{"la04", 590}, std::pair{"la05", 593}}) {
    auto shop = read_jobshop_file(jobshop_dir + "/" + name);
    if (!shop) return 2;
    const DomainModel* model = &shop->model;
    const PlanningProblem* problem = &shop->problem;
    std::printf("%s in %zu decisions (optimum %d):", name, budget_decisions, optimum);
    for (const std::string& engine : search_engine_names()) {
      PlanningOptions options;
      options.engine = engine;
      options.termination.max_decisions = budget_decisions;
      const auto start = Clock::now();
      PlanResult r = make_plan(*model, *problem, options);
      const double sec = std::chrono::duration<double>(Clock::now() - start).count();
      if (r.plan && !validate_plan(*model, *problem, *r.plan).empty()) {
        std::fprintf(stderr, "%s: invalid schedule from %s\n", name, engine.c_str());
        return 3;
      }
      if (!r.plan) {
        std::printf(" %s none (%s)", engine.c_str(), to_string(r.status));
        continue;
      }
      std::printf(" %s %lld (+%.1f%%%s, %.2f s)", engine.c_str(),
                  static_cast<long long>(r.plan->makespan),
                  100.0 * double(r.plan->makespan - optimum) / optimum,
                  r.status == PlanStatus::kOptimal ? ", proved" : "", sec);
    }
    std::printf("\n");
  }

  const bool baseline = minizinc_with_gecode();
  if (!baseline)
    std::printf(
        "job-shop baseline skipped: minizinc with Gecode not found (install it with "
        "bench/install-minizinc.sh: Debian packages minizinc, flatzinc, libgecode49)\n");
  else if (!std::filesystem::exists(minizinc_model))
    std::printf("job-shop baseline skipped: no model at %s (--minizinc-model)\n",
                minizinc_model.c_str());
  const bool with_baseline = baseline && std::filesystem::exists(minizinc_model);
  for (const char* name : {"ft06", "la01", "la02", "la03", "la04", "la05"}) {
    auto shop = read_jobshop_file(jobshop_dir + "/" + name);
    if (!shop) return 2;
    const DomainModel* model = &shop->model;
    const PlanningProblem* problem = &shop->problem;
    const JobShopInstance* inst = &shop->instance;
    // Each engine to the proof (or the limit); the ratio is against the faster proof.
    double best = -1;
    bool best_proved = false;
    for (const std::string& engine : jobshop_engines) {
      PlanningOptions options;
      options.engine = engine;
      const auto start = Clock::now();
      options.termination.stop = [&] {
        return Clock::now() - start > std::chrono::seconds(jobshop_seconds);
      };
      PlanResult r = make_plan(*model, *problem, options);
      const double s = std::chrono::duration<double>(Clock::now() - start).count();
      if (r.plan && !validate_plan(*model, *problem, *r.plan).empty()) {
        std::fprintf(stderr, "%s: invalid schedule from %s\n", name, engine.c_str());
        return 3;
      }
      std::printf("%s%s %s: makespan %lld, %s, %.3f s, %zu decisions",
                  engine == jobshop_engines.front() ? "" : " | ", name, engine.c_str(),
                  r.plan ? static_cast<long long>(r.plan->makespan) : -1LL, to_string(r.status), s,
                  r.statistics.decisions);
      const bool proved = r.status == PlanStatus::kOptimal;
      if (best < 0 || (proved && !best_proved) || (proved == best_proved && s < best)) {
        best = s;
        best_proved = proved;
      }
    }
    if (with_baseline) {
      Baseline b = run_minizinc(minizinc_model, *inst, name, jobshop_seconds);
      if (!b.ran) {
        std::printf(" | minizinc gecode failed to run");
      } else {
        std::printf(" | minizinc gecode makespan %ld, %s, %.3f s", b.makespan,
                    b.proved ? "optimal" : "not proved", b.seconds);
        if (b.solve_seconds >= 0) std::printf(" (solve %.3f s)", b.solve_seconds);
        std::printf(" | ratio gecode/planner %.1fx", b.seconds / best);
        if (b.solve_seconds >= 0) std::printf(" (solve alone %.2fx)", b.solve_seconds / best);
        if (!(b.proved && best_proved)) std::printf(" (not both proved: times are limits)");
      }
    }
    std::printf("\n");
  }
  return 0;
}
