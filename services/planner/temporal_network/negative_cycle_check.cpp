// Does a new edge a->b (b - a <= w) close a negative cycle? Asked before the edge is
// propagated, so that a rejected constraint costs a goal-directed search instead of a
// propagation through everything downstream of it and back (issue 29: at 10k timepoints and
// 10k random constraints a rejected one relaxed ~19,000 arcs by propagation, ~6,400 by this
// search; a consistent one ~70), and so that the conflict is the exact cycle.
//
// A negative cycle through the new edge is a path b ~> a shorter than -w. Through the origin
// the shortest such path is known at once: -earliest(b) + latest(a). Elsewhere, A* from b to
// a, the origin left out (its paths are the first case), with the lower bound on d(v, a)
//   h(v) = max(latest(a) - latest(v), earliest(a) - earliest(v))
// (the triangle inequality through the origin, both ways; each term is a consistent
// heuristic because the bounds are shortest paths of the network, and so is their maximum).
// Nodes whose lower bound reaches -w are never expanded, and in the common case h(b) >= -w
// answers before any search.
#include <algorithm>
#include <functional>
#include <tuple>

#include "temporal_network.hpp"

namespace autonomy::planner {

bool TemporalNetwork::closes_negative_cycle(std::size_t e,
                                            std::vector<TemporalConstraintId>* conflict) {
  const Edge ed = edges_[e];
  const TimepointId a = ed.from, b = ed.to;
  ++propagations_;
  if (latest_[a] < kInfinity && latest_[a] + ed.weight < earliest_[b]) {
    // Through the origin: latest(a)'s support, the new edge, earliest(b)'s support.
    conflict->push_back(ed.constraint);
    explain_latest(a, conflict);
    explain_earliest(b, conflict);
    return true;
  }
  if (a == origin() || b == origin()) return false;
  const Time limit = -ed.weight;  // a path b ~> a shorter than this closes the cycle
  auto lower_bound_to_a = [&](TimepointId v) {
    Time h = earliest_[a] - earliest_[v];
    if (latest_[a] < kInfinity && latest_[v] < kInfinity) h = std::max(h, latest_[a] - latest_[v]);
    return h;
  };
  if (lower_bound_to_a(b) >= limit) return false;
  ++stamp_;
  heap_.clear();
  auto reach = [&](TimepointId v, Time g, std::size_t via) {
    Bookkeeping& k = book_[v];
    if (k.pred_stamp == stamp_ && k.distance <= g) return;
    const Time f = g + lower_bound_to_a(v);
    if (f >= limit) return;
    k.pred_stamp = stamp_;
    k.pred_edge = via;
    k.distance = g;
    heap_.push_back({f, g, v});
    std::push_heap(heap_.begin(), heap_.end(), std::greater<>());
  };
  reach(b, 0, kNoEdge);
  while (!heap_.empty()) {
    std::pop_heap(heap_.begin(), heap_.end(), std::greater<>());
    const Time g = std::get<1>(heap_.back());
    const TimepointId x = std::get<2>(heap_.back());
    heap_.pop_back();
    if (g != book_[x].distance) continue;  // superseded by a shorter path
    if (x == a) {
      conflict->push_back(ed.constraint);
      trace_conflict(Phase::kLatest, a, conflict);
      return true;
    }
    if (x == origin()) continue;
    for (const Arc& arc : out_[x]) {
      ++propagations_;
      reach(arc.other, g + arc.weight, arc.edge);
    }
  }
  return false;
}

namespace {
bool named(const std::vector<TemporalConstraintId>& conflict, TemporalConstraintId c) {
  return std::find(conflict.begin(), conflict.end(), c) != conflict.end();
}
}  // namespace

// Why latest(t) is what it is: the tight arcs back to the origin (or the horizon), each
// constraint once (the new one, already named, is not its own support).
void TemporalNetwork::explain_latest(TimepointId t,
                                     std::vector<TemporalConstraintId>* conflict) const {
  for (std::size_t steps = 0; t != origin() && steps < earliest_.size(); ++steps) {
    const Arc* tight = nullptr;
    for (const Arc& arc : in_[t])
      if (latest_[arc.other] < kInfinity && latest_[arc.other] + arc.weight == latest_[t] &&
          !named(*conflict, edges_[arc.edge].constraint)) {
        tight = &arc;
        break;
      }
    if (!tight) {
      if (latest_[t] == horizon_) conflict->push_back(kHorizonConstraint);
      return;
    }
    conflict->push_back(edges_[tight->edge].constraint);
    t = tight->other;
  }
}

// Why earliest(t) is what it is: the tight arcs forward to the origin (or time 0).
void TemporalNetwork::explain_earliest(TimepointId t,
                                       std::vector<TemporalConstraintId>* conflict) const {
  for (std::size_t steps = 0; t != origin() && steps < earliest_.size(); ++steps) {
    const Arc* tight = nullptr;
    for (const Arc& arc : out_[t])
      if (earliest_[arc.other] - arc.weight == earliest_[t] &&
          !named(*conflict, edges_[arc.edge].constraint)) {
        tight = &arc;
        break;
      }
    if (!tight) return;  // earliest(t) is 0: nothing to name
    conflict->push_back(edges_[tight->edge].constraint);
    t = tight->other;
  }
}

}  // namespace autonomy::planner
