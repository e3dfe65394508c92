#include "temporal_network.hpp"

#include <algorithm>
#include <deque>
#include <functional>
#include <queue>
#include <stdexcept>
#include <string>

namespace autonomy::planner {

TemporalNetwork::TemporalNetwork(Time horizon) : horizon_(std::min(horizon, kInfinity)) {
  earliest_.push_back(0);
  latest_.push_back(0);
  out_.emplace_back();
  in_.emplace_back();
  book_.emplace_back();
}

TimepointId TemporalNetwork::add_timepoint() {
  earliest_.push_back(0);
  latest_.push_back(horizon_);
  out_.emplace_back();
  in_.emplace_back();
  book_.emplace_back();
  return earliest_.size() - 1;
}

void TemporalNetwork::check_timepoint(TimepointId t, const char* what) const {
  if (t >= earliest_.size())
    throw std::out_of_range(std::string("TemporalNetwork::add_constraint: ") + what +
                            " timepoint " + std::to_string(t) +
                            " does not exist (the network has " +
                            std::to_string(earliest_.size()) + ")");
}

bool TemporalNetwork::trailed_since_mark(std::size_t entry, TimepointId t, Undo kind) const {
  return entry != kNoEntry && entry >= latest_mark_trail_ && entry < trail_.size() &&
         trail_[entry].what == t && trail_[entry].kind == kind;
}

void TemporalNetwork::set_latest(TimepointId t, Time v) {
  call_log_.push_back({t, latest_[t], Undo::kLatest});
  std::size_t& entry = book_[t].latest_entry;
  if (!trailed_since_mark(entry, t, Undo::kLatest)) {
    entry = trail_.size();
    trail_.push_back({t, latest_[t], Undo::kLatest});
  }
  latest_[t] = v;
}

void TemporalNetwork::set_earliest(TimepointId t, Time v) {
  call_log_.push_back({t, earliest_[t], Undo::kEarliest});
  std::size_t& entry = book_[t].earliest_entry;
  if (!trailed_since_mark(entry, t, Undo::kEarliest)) {
    entry = trail_.size();
    trail_.push_back({t, earliest_[t], Undo::kEarliest});
  }
  earliest_[t] = v;
}

void TemporalNetwork::add_arcs(std::size_t e) {
  const Edge& ed = edges_[e];
  out_[ed.from].push_back({ed.to, ed.weight, e});
  in_[ed.to].push_back({ed.from, ed.weight, e});
}

// The arcs of the newest edges are last in their lists, so on undo the search from the back
// stops at once; only removal and its undo find them elsewhere.
void TemporalNetwork::erase_arcs(std::size_t e) {
  auto erase_from = [e](std::vector<Arc>& list) {
    for (std::size_t i = list.size(); i-- > 0;) {
      if (list[i].edge == e) {
        list.erase(list.begin() + static_cast<std::ptrdiff_t>(i));
        return;
      }
    }
  };
  erase_from(out_[edges_[e].from]);
  erase_from(in_[edges_[e].to]);
}

TemporalResult TemporalNetwork::add_constraint(TimepointId from, TimepointId to, Time lb, Time ub,
                                               TemporalConstraintId* id_out) {
  check_timepoint(from, "from");
  check_timepoint(to, "to");
  const TemporalConstraintId id = constraints_.size();
  if (id_out) *id_out = id;
  TemporalResult result;
  if (lb > ub || lb >= kInfinity || ub <= -kInfinity) {
    constraints_.push_back({from, to, lb, ub, false});
    first_edge_.push_back(kNoEdge);
    result.consistent = false;
    result.conflict = {id};
    return result;
  }
  const Mark before{trail_.size(), earliest_.size(), constraints_.size()};  // not a user mark
  call_log_.clear();
  constraints_.push_back({from, to, lb, ub, true});
  first_edge_.push_back(edges_.size());
  auto add_edge = [&](TimepointId a, TimepointId b, Time w) {
    if (w >= kInfinity) return;
    edges_.push_back({a, b, w, id});
    add_arcs(edges_.size() - 1);
  };
  add_edge(from, to, ub);
  add_edge(to, from, -lb);
  std::vector<TemporalConstraintId> conflict;
  bool ok = true;
  // Each edge is checked for a cycle before it moves any bound (the check is cheaper than a
  // propagation that runs round the cycle); the propagation's own contradiction tests stay
  // as the safety net.
  for (std::size_t e = first_edge_.back(); ok && e < edges_.size(); ++e)
    ok = !closes_negative_cycle(e, &conflict) && propagate_edge(e, &conflict);
  if (!ok) {
    if (explain_) conflict = negative_cycle();  // with the new constraint still in
    // The call's changes in reverse: every bound as it was before the call (the trail has
    // only the first change of each since the latest mark, and those entries go too).
    for (auto c = call_log_.rbegin(); c != call_log_.rend(); ++c)
      (c->kind == Undo::kLatest ? latest_ : earliest_)[c->what] = c->old_value;
    trail_.resize(before.trail);
    const std::size_t latest_mark = latest_mark_trail_;
    undo_to(before);
    latest_mark_trail_ = latest_mark;  // `before` was no mark of the caller's
    constraints_.push_back({from, to, lb, ub, false});
    first_edge_.push_back(kNoEdge);
    result.consistent = false;
    result.conflict = std::move(conflict);
    // The closing constraint first, then the rest of the cycle.
    result.conflict.erase(std::remove(result.conflict.begin(), result.conflict.end(), id),
                          result.conflict.end());
    result.conflict.insert(result.conflict.begin(), id);
  }
  return result;
}

void TemporalNetwork::enqueue(TimepointId t) {
  if (book_[t].queued) return;
  book_[t].queued = true;
  queue_.push_back(t);
}

// Empties the queue; after a failed phase its pending entries still carry their flags.
void TemporalNetwork::clear_queue() {
  for (std::size_t i = queue_head_; i < queue_.size(); ++i) book_[queue_[i]].queued = false;
  queue_.clear();
  queue_head_ = 0;
}

// Walks this phase's predecessor links back from `start`, collecting constraint ids: the
// path of tightenings that ended in the contradiction. Bounded by the timepoint count, and
// stopped at a constraint met twice (the walk has gone round the cycle).
void TemporalNetwork::trace_conflict(Phase phase, TimepointId start,
                                     std::vector<TemporalConstraintId>* conflict) const {
  TimepointId t = start;
  for (std::size_t i = 0; i < earliest_.size(); ++i) {
    const Bookkeeping& b = book_[t];
    if (b.pred_stamp != stamp_ || b.pred_edge == kNoEdge) break;
    const Edge& ed = edges_[b.pred_edge];
    if (std::find(conflict->begin(), conflict->end(), ed.constraint) != conflict->end()) break;
    conflict->push_back(ed.constraint);
    t = phase == Phase::kLatest ? ed.from : ed.to;
  }
}

// Incremental propagation of one new edge a->b (b - a <= w): b's latest time and a's earliest
// time may tighten through it, and from there whatever depends on them (a FIFO
// label-correcting search that visits only timepoints whose bound changes). Any further
// tightening of the seed's own bound is a walk from the seed back to itself of negative
// length, i.e. a negative cycle through the new edge (the network was consistent without
// it); a latest time below an earliest time is a negative cycle through the origin. Either
// way: inconsistent.
bool TemporalNetwork::propagate_edge(std::size_t e, std::vector<TemporalConstraintId>* conflict) {
  const Edge ed = edges_[e];
  ++propagations_;
  if (latest_[ed.from] < kInfinity && latest_[ed.from] + ed.weight < latest_[ed.to]) {
    ++stamp_;
    set_latest(ed.to, latest_[ed.from] + ed.weight);
    book_[ed.to].pred_stamp = stamp_, book_[ed.to].pred_edge = e;
    if (latest_[ed.to] < earliest_[ed.to]) {
      trace_conflict(Phase::kLatest, ed.to, conflict);
      return false;
    }
    enqueue(ed.to);
    if (!run_queue(Phase::kLatest, ed.to, conflict)) return false;
  }
  ++propagations_;
  if (earliest_[ed.to] - ed.weight > earliest_[ed.from]) {
    ++stamp_;
    set_earliest(ed.from, earliest_[ed.to] - ed.weight);
    book_[ed.from].pred_stamp = stamp_, book_[ed.from].pred_edge = e;
    if (earliest_[ed.from] > latest_[ed.from]) {
      trace_conflict(Phase::kEarliest, ed.from, conflict);
      return false;
    }
    enqueue(ed.from);
    if (!run_queue(Phase::kEarliest, ed.from, conflict)) return false;
  }
  return true;
}

// Runs the queue to a fixed point. Latest times flow forward along out-arcs
// (latest(y) <= latest(x) + w), earliest times backward along in-arcs
// (earliest(x) >= earliest(y) - w). `seed` is the timepoint the new edge tightened (a further
// tightening of it is a negative cycle), kNoTimepoint when there is none (recompute()).
bool TemporalNetwork::run_queue(Phase phase, TimepointId seed,
                                std::vector<TemporalConstraintId>* conflict) {
  const bool forward = phase == Phase::kLatest;
  while (queue_head_ < queue_.size()) {
    const TimepointId x = queue_[queue_head_++];
    book_[x].queued = false;
    if (forward && latest_[x] >= kInfinity) continue;
    for (const Arc& arc : forward ? out_[x] : in_[x]) {
      ++propagations_;
      const TimepointId y = arc.other;
      bool contradiction;
      if (forward) {
        const Time v = latest_[x] + arc.weight;
        if (v >= latest_[y]) continue;
        set_latest(y, v);
        contradiction = y == seed || v < earliest_[y];
      } else {
        const Time v = earliest_[x] - arc.weight;
        if (v <= earliest_[y]) continue;
        set_earliest(y, v);
        contradiction = y == seed || v > latest_[y];
      }
      book_[y].pred_stamp = stamp_, book_[y].pred_edge = arc.edge;
      if (contradiction) {
        trace_conflict(phase, y, conflict);
        clear_queue();
        return false;
      }
      enqueue(y);
    }
  }
  clear_queue();
  return true;
}

void TemporalNetwork::undo_to(const Mark& m) {
  while (trail_.size() > m.trail) {
    const TrailEntry& c = trail_.back();
    switch (c.kind) {
      case Undo::kLatest:
        latest_[c.what] = c.old_value;
        break;
      case Undo::kEarliest:
        earliest_[c.what] = c.old_value;
        break;
      case Undo::kRemoval:
        constraints_[c.what].active = true;
        for (std::size_t e = first_edge_[c.what];
             e < edges_.size() && edges_[e].constraint == c.what; ++e)
          add_arcs(e);
        break;
    }
    trail_.pop_back();
  }
  while (constraints_.size() > m.constraints) {
    const TemporalConstraintId id = constraints_.size() - 1;
    if (first_edge_[id] != kNoEdge) {
      // Its edges are the last ones; a removed constraint's arcs are already out of the lists.
      const bool in_lists = constraints_[id].active;
      while (edges_.size() > first_edge_[id]) {
        if (in_lists) erase_arcs(edges_.size() - 1);
        edges_.pop_back();
      }
    }
    first_edge_.pop_back();
    constraints_.pop_back();
  }
  earliest_.resize(m.timepoints);
  latest_.resize(m.timepoints);
  out_.resize(m.timepoints);
  in_.resize(m.timepoints);
  book_.resize(m.timepoints);
  // Bounds changed from here on are trailed again (the caller may undo to m once more).
  latest_mark_trail_ = m.trail;
}

void TemporalNetwork::remove_constraint(TemporalConstraintId id) {
  if (id >= constraints_.size() || !constraints_[id].active) return;
  constraints_[id].active = false;
  for (std::size_t e = first_edge_[id]; e < edges_.size() && edges_[e].constraint == id; ++e)
    erase_arcs(e);
  trail_.push_back({id, 0, Undo::kRemoval});
  recompute();
  call_log_.clear();  // no rollback of a removal
}

// All bounds from scratch: the network was consistent with the removed constraint, so it is
// without it, and a label-correcting search seeded with every timepoint terminates.
void TemporalNetwork::recompute() {
  for (TimepointId t = 0; t < earliest_.size(); ++t) {
    const Time l = t == origin() ? 0 : horizon_;
    if (earliest_[t] != 0) set_earliest(t, 0);
    if (latest_[t] != l) set_latest(t, l);
  }
  std::vector<TemporalConstraintId> unused;
  for (Phase phase : {Phase::kLatest, Phase::kEarliest}) {
    ++stamp_;
    for (TimepointId t = 0; t < earliest_.size(); ++t) enqueue(t);
    run_queue(phase, kNoTimepoint, &unused);
  }
}

TimeBounds TemporalNetwork::window_distance(TimepointId from, TimepointId to) const {
  return {earliest_[to] - latest_[from],
          latest_[to] >= kInfinity ? kInfinity : latest_[to] - earliest_[from]};
}

// Bellman-Ford from a virtual source joined to every timepoint: after n rounds a timepoint
// that still improves lies downstream of a negative cycle; walking n predecessor links back
// from it lands on the cycle, which is then read off.
std::vector<TemporalConstraintId> TemporalNetwork::negative_cycle() const {
  struct E {
    TimepointId from, to;
    Time w;
    TemporalConstraintId c;
  };
  std::vector<E> all;
  for (const Edge& e : edges_)
    if (constraints_[e.constraint].active) all.push_back({e.from, e.to, e.weight, e.constraint});
  for (TimepointId t = 1; t < earliest_.size(); ++t) {
    if (horizon_ < kInfinity) all.push_back({origin(), t, horizon_, kHorizonConstraint});
    all.push_back({t, origin(), 0, kHorizonConstraint});
  }
  const std::size_t n = earliest_.size();
  std::vector<Time> dist(n, 0);
  std::vector<std::size_t> pred(n, SIZE_MAX);
  TimepointId last = SIZE_MAX;
  for (std::size_t round = 0; round <= n; ++round) {
    last = SIZE_MAX;
    for (std::size_t i = 0; i < all.size(); ++i) {
      if (dist[all[i].from] + all[i].w < dist[all[i].to]) {
        dist[all[i].to] = dist[all[i].from] + all[i].w;
        pred[all[i].to] = i;
        last = all[i].to;
      }
    }
    if (last == SIZE_MAX) return {};
  }
  for (std::size_t i = 0; i < n; ++i) last = all[pred[last]].from;
  std::vector<TemporalConstraintId> cycle;
  TimepointId t = last;
  do {
    const E& e = all[pred[t]];
    if (std::find(cycle.begin(), cycle.end(), e.c) == cycle.end()) cycle.push_back(e.c);
    t = e.from;
  } while (t != last && cycle.size() <= all.size());
  return cycle;
}

Time TemporalNetwork::shortest_distance(TimepointId from, TimepointId to, Time cutoff) const {
  const std::size_t n = latest_.size();
  // Potentials need finite latest times; without a horizon, the label-correcting search.
  if (horizon_ >= kInfinity) return shortest_distances(from)[to];
  for (TimepointId t : {from, to})
    if (latest_[t] >= kInfinity || latest_[t] <= -kInfinity) return shortest_distances(from)[to];
  // Reduced distance r(y) = d(from, y) + latest(from) - latest(y) >= 0.
  auto reduced = [&](TimepointId x, TimepointId y, Time w) { return w + latest_[x] - latest_[y]; };
  const Time reduced_cutoff =
      cutoff >= kInfinity ? kInfinity : cutoff + latest_[from] - latest_[to];
  std::vector<Time> dist(n, kInfinity);
  std::vector<char> done(n, 0);
  using Entry = std::pair<Time, TimepointId>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> heap;
  dist[from] = 0;
  heap.push({0, from});
  auto relax = [&](TimepointId x, TimepointId y, Time w) {
    const Time r = reduced(x, y, w);
    if (r < 0) return false;  // stale potentials: not expected, answered the slow way
    const Time v = dist[x] + r;
    if (v < dist[y]) {
      dist[y] = v;
      heap.push({v, y});
    }
    return true;
  };
  while (!heap.empty()) {
    auto [d, x] = heap.top();
    heap.pop();
    if (done[x]) continue;
    if (x == to) return d - latest_[from] + latest_[to];
    if (d > reduced_cutoff) return cutoff + 1;
    done[x] = 1;
    for (const Arc& arc : out_[x])
      if (!relax(x, arc.other, arc.weight)) return shortest_distances(from)[to];
    if (x != origin()) relax(x, origin(), 0);
    if (x == origin())
      for (TimepointId t = 1; t < n; ++t) relax(x, t, horizon_);
  }
  return kInfinity;
}

std::vector<Time> TemporalNetwork::shortest_distances(TimepointId from) const {
  std::vector<Time> dist(earliest_.size(), kInfinity);
  std::vector<char> queued(earliest_.size(), 0);
  std::deque<TimepointId> queue{from};
  dist[from] = 0;
  // The implicit origin edges (0 <= t <= horizon) are part of the network too.
  auto relax = [&](TimepointId y, Time v) {
    if (v < dist[y]) {
      dist[y] = v;
      if (!queued[y]) {
        queued[y] = 1;
        queue.push_back(y);
      }
    }
  };
  while (!queue.empty()) {
    TimepointId x = queue.front();
    queue.pop_front();
    queued[x] = 0;
    for (const Arc& arc : out_[x]) relax(arc.other, dist[x] + arc.weight);
    if (x != origin()) relax(origin(), dist[x]);
    if (x == origin() && horizon_ < kInfinity)
      for (TimepointId t = 1; t < earliest_.size(); ++t) relax(t, dist[x] + horizon_);
  }
  return dist;
}

}  // namespace autonomy::planner
