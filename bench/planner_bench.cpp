// Planner figures (issue 11): the temporal network's incremental propagation per added
// constraint at 10,000 timepoints, against recomputing all bounds by Bellman-Ford (the same
// network, the same run); and job-shop solve times of the chronological engine.
#include <CLI/CLI.hpp>
#include <array>
#include <chrono>
#include <cstdio>
#include <random>
#include <vector>

#include "jobshop_instance.hpp"
#include "planner.hpp"
#include "planner_language.hpp"
#include "temporal_network.hpp"

using namespace autonomy::planner;
using Clock = std::chrono::steady_clock;

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
  std::string jobshop_dir = "services/planner/examples/jobshop";
  app.add_option("--timepoints", timepoints);
  app.add_option("--added", added, "constraints timed on the incremental network");
  app.add_option("--baseline-added", baseline_added, "constraints timed with full recomputation");
  app.add_option("--jobshop-dir", jobshop_dir);
  CLI11_PARSE(app, argc, argv);

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

  for (const char* name : {"ft06", "la01", "la02", "la03", "la04", "la05"}) {
    Diagnostics errors;
    auto text = read_text_file(jobshop_dir + "/" + name, &errors);
    auto inst = text ? parse_jobshop(*text, name, &errors) : std::nullopt;
    if (!inst) {
      std::fprintf(stderr, "%s", to_string(errors).c_str());
      return 2;
    }
    auto model = build_domain_model(jobshop_model(*inst), &errors);
    auto problem = build_problem(*model, jobshop_problem(*inst), &errors);
    PlanningOptions options;
    const auto start = Clock::now();
    options.termination.stop = [&] { return Clock::now() - start > std::chrono::seconds(30); };
    PlanResult r = make_plan(*model, *problem, options);
    const double s = std::chrono::duration<double>(Clock::now() - start).count();
    std::printf("%s: makespan %lld, %s, %.3f s, %zu decisions\n", name,
                r.plan ? static_cast<long long>(r.plan->makespan) : -1LL, to_string(r.status), s,
                r.statistics.decisions);
  }
  return 0;
}
