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
// Cost of an added constraint (issue 29): in proportion to the bounds it changes and the arcs
// leaving the changed timepoints, never to the network's size. The propagation's queue,
// predecessor links and flags are kept between calls (grown with the timepoints, never
// cleared wholesale: predecessor links carry the number of the propagation that wrote them).
//
// Undo: every change (timepoint, constraint, bound, removal) is on a trail; undo_to(mark)
// restores the network exactly as it was at mark(), which is what a chronological search
// engine needs. A bound is trailed once after each mark (its value at the mark is all an undo
// needs): a chain appended without marks, whose every link moves the latest time of every
// timepoint before it, keeps a trail as long as the chain, not its square. A failed
// add_constraint() rolls back from its own log of the call's changes.
// remove_constraint() takes out any constraint (not only the last) and recomputes all bounds
// (a whole-network pass: removal is rare, no search uses it).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <tuple>
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
  // (ids are never reused). Requires lb <= ub (else inconsistent at once). Throws
  // std::out_of_range when from or to is not a timepoint of the network.
  [[nodiscard]] TemporalResult add_constraint(TimepointId from, TimepointId to, Time lb, Time ub,
                                              TemporalConstraintId* id = nullptr);
  // Takes out any active constraint and recomputes all bounds (label-correcting from every
  // timepoint); undo_to() a mark taken before puts it back.
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
  // Const for its callers, though it notes the trail's length: bounds changed after the
  // latest mark are trailed once.
  Mark mark() const {
    latest_mark_trail_ = trail_.size();
    return {trail_.size(), earliest_.size(), constraints_.size()};
  }
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
  // An edge as its endpoints' adjacency lists hold it: the weight inline, so a relaxation
  // reads one list and no edge table.
  struct Arc {
    TimepointId other;  // out-list: the edge's head; in-list: its tail
    Time weight;
    std::size_t edge;
  };
  // One trail entry: a bound's old value, or a constraint taken out by remove_constraint().
  enum class Undo : std::uint8_t { kLatest, kEarliest, kRemoval };
  struct TrailEntry {
    std::size_t what;  // timepoint, or constraint for kRemoval
    Time old_value;
    Undo kind;
  };
  // Where the latest phase walks (out-arcs, tightening latest times) and where the earliest
  // phase walks (in-arcs, raising earliest times).
  enum class Phase : std::uint8_t { kLatest, kEarliest };

  bool closes_negative_cycle(std::size_t edge, std::vector<TemporalConstraintId>* conflict);
  void explain_latest(TimepointId t, std::vector<TemporalConstraintId>* conflict) const;
  void explain_earliest(TimepointId t, std::vector<TemporalConstraintId>* conflict) const;
  bool propagate_edge(std::size_t edge, std::vector<TemporalConstraintId>* conflict);
  bool run_queue(Phase phase, TimepointId seed, std::vector<TemporalConstraintId>* conflict);
  void enqueue(TimepointId t);
  void clear_queue();
  void trace_conflict(Phase phase, TimepointId start,
                      std::vector<TemporalConstraintId>* conflict) const;
  void set_latest(TimepointId t, Time v);
  void set_earliest(TimepointId t, Time v);
  void add_arcs(std::size_t edge);
  void erase_arcs(std::size_t edge);
  void recompute();
  std::vector<TemporalConstraintId> negative_cycle() const;
  void check_timepoint(TimepointId t, const char* what) const;
  bool explain_ = false;

  Time horizon_;
  std::vector<Time> earliest_, latest_;
  std::vector<std::vector<Arc>> out_, in_;
  std::vector<Edge> edges_;
  std::vector<Constraint> constraints_;
  std::vector<std::size_t> first_edge_;  // per constraint: its first edge, kNoEdge if none
  std::vector<TrailEntry> trail_;
  std::size_t propagations_ = 0;

  // The latest mark's trail length (also the target of the latest undo): a bound with a
  // trail entry at or after it needs no other.
  mutable std::size_t latest_mark_trail_ = 0;
  // Every bound change of the current add_constraint(), in order, to roll a failure back.
  std::vector<TrailEntry> call_log_;

  // Per-timepoint bookkeeping, kept between calls (never cleared wholesale).
  static constexpr std::size_t kNoEdge = static_cast<std::size_t>(-1);
  static constexpr std::size_t kNoEntry = static_cast<std::size_t>(-1);
  static constexpr TimepointId kNoTimepoint = static_cast<TimepointId>(-1);
  struct Bookkeeping {
    std::uint64_t pred_stamp = 0;  // the search or phase that set pred_edge; older is stale
    std::size_t pred_edge = kNoEdge;
    Time distance = 0;  // from the cycle check's start, when pred_stamp is current
    std::size_t latest_entry = kNoEntry, earliest_entry = kNoEntry;  // newest trail entries
    bool queued = false;
  };
  bool trailed_since_mark(std::size_t entry, TimepointId t, Undo kind) const;
  std::vector<Bookkeeping> book_;
  std::uint64_t stamp_ = 0;
  std::vector<TimepointId> queue_;  // FIFO: entries from queue_head_ on are pending
  std::size_t queue_head_ = 0;
  std::vector<std::tuple<Time, Time, TimepointId>> heap_;  // the cycle check's (f, g, node)
};

}  // namespace autonomy::planner
