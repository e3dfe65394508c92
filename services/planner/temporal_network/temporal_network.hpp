#pragma once
// Simple temporal network (Dechter, Meiri and Pearl 1991): timepoints and distance constraints
// lb <= t_to - t_from <= ub. Every timepoint lies in [0, horizon] from the origin (timepoint 0),
// and the network keeps for each one its earliest and latest time (the shortest paths to and
// from the origin), updated incrementally on every added constraint.
//
// Why eager propagation: because every timepoint is bounded from the origin, a negative cycle
// drives some latest time below its earliest time while the bounds are propagated, so the
// constraint that closes the cycle is the one whose addition fails (the paper's "inconsistency
// detected at the constraint that closes it"), at no cost beyond the propagation itself.
//
// Undo: every change (timepoint, constraint, bound) is on a trail; undo_to(mark) restores the
// network exactly as it was at mark(), which is what a chronological search engine needs.
// remove_constraint() takes out any constraint (not only the last) and recomputes the bounds.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace autonomy::planner {

using Time = std::int64_t;
// "No bound": large enough for any horizon, small enough that sums of two never overflow.
inline constexpr Time kInfinity = Time{1} << 52;

using TimepointId = std::size_t;
using TemporalConstraintId = std::size_t;

struct TimeBounds {
  Time earliest = 0;
  Time latest = kInfinity;
};

// Result of adding a constraint: either consistent, or the cycle it closed.
struct TemporalResult {
  bool consistent = true;
  // When inconsistent: the constraints of one negative cycle (the new one among them), as far
  // as the propagation's predecessor links can name them.
  std::vector<TemporalConstraintId> conflict;
  explicit operator bool() const { return consistent; }
};

class TemporalNetwork {
 public:
  explicit TemporalNetwork(Time horizon = kInfinity);

  static constexpr TimepointId origin() { return 0; }
  Time horizon() const { return horizon_; }

  TimepointId add_timepoint();
  std::size_t timepoint_count() const { return earliest_.size(); }

  // Adds lb <= to - from <= ub (lb may be -kInfinity, ub kInfinity). On an inconsistency the
  // constraint is NOT kept and the bounds are as before the call; the id is still consumed
  // (ids are never reused). Requires lb <= ub (else inconsistent at once).
  [[nodiscard]] TemporalResult add_constraint(TimepointId from, TimepointId to, Time lb, Time ub,
                                              TemporalConstraintId* id = nullptr);
  // Takes out any active constraint and recomputes all bounds (Bellman-Ford from the origin).
  void remove_constraint(TemporalConstraintId id);

  TimeBounds bounds(TimepointId t) const { return {earliest_[t], latest_[t]}; }
  Time earliest(TimepointId t) const { return earliest_[t]; }
  Time latest(TimepointId t) const { return latest_[t]; }
  // Bounds on to - from implied by the two timepoints' windows (a relaxation of the minimal
  // network's entry, exact when one of them is the origin).
  TimeBounds window_distance(TimepointId from, TimepointId to) const;

  // Exact shortest path from -> to (ub of to - from in the minimal network), by a
  // single-source search; kInfinity when unconstrained.
  // Dijkstra on edge weights made non-negative by the latest times (exact shortest paths from
  // the origin, so w(x, y) + latest(x) - latest(y) >= 0); with a cutoff it stops once every
  // path left is longer, and then returns some value above the cutoff.
  Time shortest_distance(TimepointId from, TimepointId to, Time cutoff = kInfinity) const;
  // The same from one timepoint to every timepoint (one search for many questions).
  std::vector<Time> shortest_distances(TimepointId from) const;

  struct Constraint {
    TimepointId from, to;
    Time lb, ub;
    bool active;
  };
  const std::vector<Constraint>& constraints() const { return constraints_; }

  // Undo trail.
  struct Mark {
    std::size_t trail, timepoints, constraints;
  };
  Mark mark() const { return {trail_.size(), earliest_.size(), constraints_.size()}; }
  void undo_to(const Mark& m);

  std::size_t propagations() const { return propagations_; }

  // When on, a failed add_constraint() names the constraints of one negative cycle exactly
  // (a Bellman-Ford pass over the whole network, only on failure); when off (the default, for
  // search), only the closing constraint and what the propagation's links show.
  void set_explain_conflicts(bool on) { explain_ = on; }
  // In a conflict: the implicit "every timepoint within [0, horizon]" constraint.
  static constexpr TemporalConstraintId kHorizonConstraint = static_cast<TemporalConstraintId>(-1);

 private:
  struct Edge {  // to - from <= weight, from a constraint (each constraint gives two edges)
    TimepointId from, to;
    Time weight;
    TemporalConstraintId constraint;
  };
  struct BoundChange {
    TimepointId t;
    bool latest;  // which bound changed
    Time old_value;
  };
  bool propagate_from(const std::vector<TimepointId>& seeds_latest,
                      const std::vector<TimepointId>& seeds_earliest, TemporalConstraintId added,
                      std::vector<TemporalConstraintId>* conflict);
  void set_latest(TimepointId t, Time v);
  void set_earliest(TimepointId t, Time v);
  void recompute();
  std::vector<TemporalConstraintId> negative_cycle() const;
  bool explain_ = false;

  Time horizon_;
  std::vector<Time> earliest_, latest_;
  std::vector<std::vector<std::size_t>> out_, in_;  // edge indices
  std::vector<Edge> edges_;
  std::vector<Constraint> constraints_;
  std::vector<BoundChange> trail_;
  std::vector<std::size_t> edge_count_at_constraint_;  // edges_.size() before constraint i
  std::size_t propagations_ = 0;
};

}  // namespace autonomy::planner
