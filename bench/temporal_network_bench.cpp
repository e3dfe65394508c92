// The planner's temporal network, cost per added constraint (issue 29): "adding a constraint
// costs in proportion to what it changes, not to the network's size".
//  - random: 10,000 timepoints joined by a random forest of precedences (like a plan's token
//    network), then 100,000 random constraints between random timepoints; the mean cost per
//    added constraint over the first 10k, 30k, 60k and 100k of them (consistent or not: a
//    rejected one is propagated up to its cycle and undone);
//  - chain: timepoints appended one by one under a horizon, each at least 1 after the previous
//    one, so that every link pulls in the latest time of every timepoint before it (the work
//    is the length of the chain: what a plan's precedences under a horizon do);
//  - chain after the random network: the same chain hung from one of its timepoints.
// Every figure is checked against a from-scratch Bellman-Ford of the same network (a
// benchmark that computes the wrong thing is void); the recomputation is also timed, as the
// cost the incremental network saves. The bench uses only the network's public interface, so
// the same source built against an older temporal_network.cpp gives that version's figures.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <random>
#include <vector>

#include "temporal_network.hpp"

using namespace autonomy::planner;
using BenchClock = std::chrono::steady_clock;

namespace {

struct BenchEdge {
  TimepointId from, to;
  Time weight;
};

// The network's edges beside it, for the from-scratch check.
struct CheckedNetwork {
  explicit CheckedNetwork(Time horizon) : tn(horizon) {}
  TemporalNetwork tn;
  std::vector<BenchEdge> edges;
  bool add(TimepointId a, TimepointId b, Time lb, Time ub) {
    if (!tn.add_constraint(a, b, lb, ub)) return false;
    if (ub < kInfinity) edges.push_back({a, b, ub});
    if (lb > -kInfinity) edges.push_back({b, a, -lb});
    return true;
  }
};

// All bounds from scratch (label-correcting passes to a fixed point); false on a mismatch
// with the incremental network. `seconds` gets the recomputation's time.
bool matches_recomputation(const CheckedNetwork& net, double* seconds) {
  const std::size_t n = net.tn.timepoint_count();
  const Time horizon = net.tn.horizon();
  const auto start = BenchClock::now();
  std::vector<Time> latest(n, horizon), earliest(n, 0);
  latest[0] = 0;
  for (bool changed = true; changed;) {
    changed = false;
    for (const BenchEdge& e : net.edges) {
      if (latest[e.from] + e.weight < latest[e.to])
        latest[e.to] = latest[e.from] + e.weight, changed = true;
      if (earliest[e.to] - e.weight > earliest[e.from])
        earliest[e.from] = earliest[e.to] - e.weight, changed = true;
    }
  }
  *seconds = std::chrono::duration<double>(BenchClock::now() - start).count();
  for (TimepointId t = 1; t < n; ++t) {
    if (latest[t] != net.tn.latest(t) || earliest[t] != net.tn.earliest(t)) {
      std::fprintf(stderr, "mismatch at timepoint %zu: [%lld, %lld] against [%lld, %lld]\n", t,
                   static_cast<long long>(net.tn.earliest(t)),
                   static_cast<long long>(net.tn.latest(t)), static_cast<long long>(earliest[t]),
                   static_cast<long long>(latest[t]));
      return false;
    }
  }
  return true;
}

double micros_since(BenchClock::time_point start) {
  return std::chrono::duration<double, std::micro>(BenchClock::now() - start).count();
}

// Appends `length` timepoints, each at least 1 after the previous one (the first after
// `anchor`); returns the mean microseconds per link.
double append_chain(CheckedNetwork& net, TimepointId anchor, std::size_t length,
                    std::size_t* rejected) {
  TimepointId previous = anchor;
  double total = 0;
  for (std::size_t i = 0; i < length; ++i) {
    const TimepointId next = net.tn.add_timepoint();
    const auto start = BenchClock::now();
    const bool ok = net.add(previous, next, 1, kInfinity);
    total += micros_since(start);
    *rejected += !ok;
    previous = next;
  }
  return total / double(length);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Temporal network: cost per added constraint"};
  std::size_t timepoints = 10000, chain = 10000, hung_chain = 2000;
  std::vector<std::size_t> checkpoints{10000, 30000, 60000, 100000};
  unsigned seed = 5;
  app.add_option("--timepoints", timepoints, "timepoints of the random network");
  app.add_option("--edges", checkpoints, "added random constraints at which the mean is printed");
  app.add_option("--chain", chain, "length of the chain appended under a horizon on its own");
  app.add_option("--hung-chain", hung_chain, "length of the chain hung from the random network");
  app.add_option("--seed", seed);
  CLI11_PARSE(app, argc, argv);
  if (timepoints < 2 || checkpoints.empty()) {
    std::fprintf(stderr, "need --timepoints >= 2 and at least one --edges figure\n");
    return 2;
  }
  std::sort(checkpoints.begin(), checkpoints.end());

  // Random network: the forest, then random constraints (as planner_bench draws them).
  const Time horizon = 100 * Time(timepoints);
  std::mt19937 rng(seed);
  CheckedNetwork net(horizon);
  for (std::size_t i = 1; i <= timepoints; ++i) {
    net.tn.add_timepoint();
    if (i > 1) net.add(std::uniform_int_distribution<std::size_t>(1, i - 1)(rng), i, 1, 50);
  }
  std::uniform_int_distribution<std::size_t> any(1, timepoints);
  std::uniform_int_distribution<Time> gap(0, 40);
  // Consistent and rejected constraints timed apart: a rejected one costs the search that
  // finds its cycle, which can be long in a dense network however it is done.
  double total_us = 0, consistent_us = 0;
  std::size_t added = 0, accepted = 0;
  for (std::size_t checkpoint : checkpoints) {
    while (added < checkpoint) {
      const TimepointId a = any(rng), b = any(rng);
      if (a == b) continue;
      const Time lb = gap(rng);
      const auto start = BenchClock::now();
      const bool consistent = net.add(a, b, lb, 2000);
      const double us = micros_since(start);
      total_us += us;
      if (consistent) consistent_us += us, ++accepted;
      ++added;
    }
    double recompute_s = 0;
    if (!matches_recomputation(net, &recompute_s)) return 1;
    std::printf(
        "random: %zu timepoints, %zu added constraints: %.1f us per added constraint; %zu "
        "consistent %.1f us each, %zu rejected %.1f us each; from-scratch recomputation %.1f ms\n",
        timepoints, added, total_us / double(added), accepted,
        accepted ? consistent_us / double(accepted) : 0.0, added - accepted,
        added > accepted ? (total_us - consistent_us) / double(added - accepted) : 0.0, recompute_s * 1e3);
    std::fflush(stdout);
  }

  std::size_t rejected = 0;
  const double hung_us = append_chain(net, any(rng), hung_chain, &rejected);
  double recompute_s = 0;
  if (!matches_recomputation(net, &recompute_s)) return 1;
  std::printf(
      "chain of %zu hung from the random network under horizon %lld: %.1f us per link (%zu "
      "rejected)\n",
      hung_chain, static_cast<long long>(horizon), hung_us, rejected);
  std::fflush(stdout);

  CheckedNetwork line(100 * Time(chain));
  rejected = 0;
  const double chain_us = append_chain(line, TemporalNetwork::origin(), chain, &rejected);
  if (!matches_recomputation(line, &recompute_s)) return 1;
  std::printf(
      "chain of %zu appended under horizon %lld: %.1f us per link (%zu rejected); from-scratch "
      "recomputation %.1f ms\n",
      chain, static_cast<long long>(100 * Time(chain)), chain_us, rejected, recompute_s * 1e3);
  return 0;
}
