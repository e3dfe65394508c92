#pragma once
// Internal to the constructions of the dispatchable form (dispatchable_network.cpp and the
// reference in dispatchable_every_timepoint.cpp): the plan's distance graph and its potentials.
#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "dispatchable_network.hpp"

namespace autonomy::executive::dispatchable_graph {

struct Arc {
  std::size_t to;
  Time weight;
};

// The plan's distance graph as it was written: a few edges per timepoint (a 1,000-token plan
// has 2,001 timepoints); parallel edges keep the tightest weight.
struct SparseGraph {
  std::vector<std::vector<Arc>> out;

  explicit SparseGraph(std::size_t n) : out(n) {}
  void add(std::size_t from, std::size_t to, Time weight) {
    for (Arc& a : out[from])
      if (a.to == to) {
        a.weight = std::min(a.weight, weight);
        return;
      }
    out[from].push_back({to, weight});
  }
};

struct PlanGraph {
  SparseGraph graph;
  std::vector<Time> potentials;  // every w + h[from] - h[to] >= 0 (Bellman-Ford)
};

// Fills net's names, token and is_start (origin, then each token's start and end) and builds
// the distance graph with its potentials. nullopt (and the reason) when a constraint names an
// unknown timepoint or the constraints are inconsistent (a negative cycle).
std::optional<PlanGraph> plan_graph(const planner::FlexiblePlan& plan, DispatchableNetwork* net,
                                    std::string* error);

}  // namespace autonomy::executive::dispatchable_graph
