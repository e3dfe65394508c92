// Executive figures (issue 12): per-tick dispatch decision time on a 1,000-token flexible plan,
// in its dispatchable form (Muscettola, Morris and Pollack 1998: propagation to neighbours over
// the filtered edges) beside the same dispatcher propagating every executed time through the
// full all-pairs network (every other timepoint a neighbour), measured in the same run; and the
// time to build the dispatchable form. Tsamardinos, Muscettola and Morris (1998) report the
// filtered form faster to dispatch by about two orders of magnitude.
// Issue 28: the construction of the dispatchable form at 1,000 and 2,000 tokens (goal: under
// 100 ms at 1,000), beside the construction it replaced (one Dijkstra per timepoint, n x n
// closure) in the same run, with a check that both give the same edges and windows.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "dispatchable_every_timepoint.hpp"
#include "dispatcher.hpp"

using namespace autonomy::executive;
using autonomy::planner::FlexiblePlan;
using autonomy::planner::PlanToken;
using Clock = std::chrono::steady_clock;

namespace {

double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

// `lines` timelines of tokens that meet, each lasting [10, 20] (one in four fixed at 15), and
// every fourth token waiting for the end of the previous-index token on the line before (within
// 0..30): a spacecraft-like mix of rigid and flexible links across timelines.
FlexiblePlan synthetic_plan(int lines, int per_line, std::mt19937* rng) {
  FlexiblePlan plan;
  plan.horizon = 40 * per_line + 1000;
  std::uniform_int_distribution<int> coin(0, 3);
  for (int l = 0; l < lines; ++l) {
    autonomy::planner::PlanTimeline line{"sc.line" + std::to_string(l), {}};
    for (int k = 0; k < per_line; ++k) {
      PlanToken t;
      t.id = static_cast<std::uint32_t>(plan.tokens.size());
      t.object = "sc";
      t.attribute = "line" + std::to_string(l);
      t.predicate = "p";
      t.start_lb = 0;
      t.start_ub = k == 0 ? 0 : plan.horizon;
      t.end_lb = 0;
      t.end_ub = plan.horizon;
      bool fixed = coin(*rng) == 0;
      t.duration_lb = fixed ? 15 : 10;
      t.duration_ub = fixed ? 15 : 20;
      if (!line.tokens.empty())
        plan.constraints.push_back(
            {std::to_string(line.tokens.back()) + ".end", std::to_string(t.id) + ".start", 0, 0});
      if (l > 0 && k % 4 == 3) {
        std::uint32_t other = static_cast<std::uint32_t>((l - 1) * per_line + k - 1);
        plan.constraints.push_back(
            {std::to_string(other) + ".end", std::to_string(t.id) + ".start", 0, 30});
      }
      line.tokens.push_back(t.id);
      plan.tokens.push_back(t);
    }
    plan.timelines.push_back(line);
  }
  return plan;
}

struct TickFigures {
  double mean_us = 0, p99_us = 0, max_us = 0;
  std::size_t ticks = 0, executed = 0;
  bool finished = false, broken = false;
};

// Runs the plan tick by tick (1 time unit each) until every timepoint is executed. Every
// eighth token's end is the world's (observed at its earliest time plus 2 when that is
// inside its window), as a turn's end is.
TickFigures dispatch_all(const FlexiblePlan& plan, const DispatchableNetwork& net) {
  Dispatcher d(plan, net, 0);
  for (std::size_t i = 7; i < plan.tokens.size(); i += 8) d.set_observed(i, false, true);
  std::vector<double> us;
  TickFigures f;
  for (Time now = 0; now <= plan.horizon && !d.finished() && !d.broken(); ++now) {
    auto t0 = Clock::now();
    for (std::size_t i = 7; i < plan.tokens.size(); i += 8)
      if (d.executed(i, true) && !d.executed(i, false) &&
          now == std::min(d.lower(i, false) + 2, d.upper(i, false)))
        d.observe(i, false, now);
    f.executed += d.step(now).size();
    us.push_back(ms_since(t0) * 1000.0);
  }
  f.finished = d.finished();
  f.broken = d.broken();
  f.ticks = us.size();
  std::sort(us.begin(), us.end());
  for (double u : us) f.mean_us += u / static_cast<double>(us.size());
  f.p99_us = us[us.size() * 99 / 100];
  f.max_us = us.back();
  return f;
}

bool same_network(const DispatchableNetwork& a, const DispatchableNetwork& b) {
  if (a.edges.size() != b.edges.size() || a.closed_edges != b.closed_edges ||
      a.earliest != b.earliest || a.latest != b.latest)
    return false;
  for (std::size_t i = 0; i < a.edges.size(); ++i)
    if (a.edges[i].from != b.edges[i].from || a.edges[i].to != b.edges[i].to ||
        a.edges[i].weight != b.edges[i].weight)
      return false;
  return true;
}

// Construction time of the dispatchable form (best of `runs`) against the per-timepoint
// construction it replaced (one run: seconds). Returns false if the two differ.
bool construction_row(int lines, int per_line, int runs) {
  std::mt19937 rng(3);
  FlexiblePlan plan = synthetic_plan(lines, per_line, &rng);
  std::string error;
  double best = 1e300;
  std::optional<DispatchableNetwork> net;
  for (int r = 0; r < runs; ++r) {
    auto t0 = Clock::now();
    net = make_dispatchable(plan, &error);
    best = std::min(best, ms_since(t0));
  }
  auto t0 = Clock::now();
  auto old = make_dispatchable_every_timepoint(plan, &error);
  double old_ms = ms_since(t0);
  if (!net || !old) {
    std::fprintf(stderr, "executive_bench: plan rejected: %s\n", error.c_str());
    return false;
  }
  bool same = same_network(*net, *old);
  std::printf("  %5zu tokens %5zu timepoints: %8.1f ms (best of %d)   per-timepoint closure %8.1f ms"
              "   %.1fx   %zu of %zu closure edges kept, %s\n",
              plan.tokens.size(), net->names.size(), best, runs, old_ms, old_ms / best,
              net->edges.size(), net->closed_edges, same ? "same network" : "NETWORKS DIFFER");
  return same;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Executive benchmarks: dispatch per tick, dispatchable vs full network"};
  int lines = 10, per_line = 100;
  bool quick = false;
  app.add_option("--lines", lines, "timelines of the synthetic plan");
  app.add_option("--tokens-per-line", per_line, "tokens per timeline");
  app.add_flag("--quick", quick, "a 200-token plan instead");
  CLI11_PARSE(app, argc, argv);
  if (quick) per_line = 20;

  std::mt19937 rng(3);
  FlexiblePlan plan = synthetic_plan(lines, per_line, &rng);
  std::printf("executive_bench: %zu tokens on %d timelines, %zu constraints, %zu timepoints\n",
              plan.tokens.size(), lines, plan.constraints.size(), 2 * plan.tokens.size() + 1);

  std::string error;
  auto t0 = Clock::now();
  auto full = make_dispatchable(plan, &error, false);
  double full_ms = ms_since(t0);
  t0 = Clock::now();
  auto filtered = make_dispatchable(plan, &error, true);
  double filtered_ms = ms_since(t0);
  if (!full || !filtered) {
    std::fprintf(stderr, "executive_bench: plan rejected: %s\n", error.c_str());
    return 1;
  }
  std::printf("build: all-pairs closure %.0f ms (%zu edges); dispatchable form %.0f ms (%zu edges, "
              "%.1f%% of the closure)\n",
              full_ms, full->edges.size(), filtered_ms, filtered->edges.size(),
              100.0 * static_cast<double>(filtered->edges.size()) /
                  static_cast<double>(full->edges.size()));

  TickFigures fast = dispatch_all(plan, *filtered);
  TickFigures slow = dispatch_all(plan, *full);
  auto row = [](const char* name, const TickFigures& f) {
    std::printf("  %-34s %7zu ticks %6zu events  mean %8.2f us  p99 %8.2f us  max %9.2f us  %s\n",
                name, f.ticks, f.executed, f.mean_us, f.p99_us, f.max_us,
                f.broken ? "BROKEN" : f.finished ? "finished" : "unfinished");
  };
  std::printf("per-tick dispatch decision:\n");
  row("dispatchable form (neighbours)", fast);
  row("full network (every timepoint)", slow);
  std::printf("ratio full / dispatchable: mean %.1fx, p99 %.1fx (goal: under 100 us per tick)\n",
              slow.mean_us / fast.mean_us, slow.p99_us / fast.p99_us);

  std::printf("dispatchable form construction, %d timelines (issue 28 goal: under 100 ms at "
              "1,000 tokens):\n", lines);
  bool same = true;
  for (int tokens : quick ? std::vector<int>{1000} : std::vector<int>{1000, 2000})
    same &= construction_row(lines, tokens / lines, 5);
  return fast.finished && slow.finished && same ? 0 : 1;
}
