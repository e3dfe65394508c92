#include "temporal_network.hpp"

#include <algorithm>
#include <deque>
#include <functional>
#include <queue>

namespace autonomy::planner {

TemporalNetwork::TemporalNetwork(Time horizon) : horizon_(std::min(horizon, kInfinity)) {
  earliest_.push_back(0);
  latest_.push_back(0);
  out_.emplace_back();
  in_.emplace_back();
}

TimepointId TemporalNetwork::add_timepoint() {
  earliest_.push_back(0);
  latest_.push_back(horizon_);
  out_.emplace_back();
  in_.emplace_back();
  return earliest_.size() - 1;
}

void TemporalNetwork::set_latest(TimepointId t, Time v) {
  trail_.push_back({t, true, latest_[t]});
  latest_[t] = v;
}

void TemporalNetwork::set_earliest(TimepointId t, Time v) {
  trail_.push_back({t, false, earliest_[t]});
  earliest_[t] = v;
}

namespace {
// Walks predecessor edges back from `start`, collecting constraint ids, at most `limit` steps
// (the links may be stale from earlier propagations, so the walk is bounded).
void trace(const std::vector<std::size_t>& pred,
           const std::vector<TemporalConstraintId>& edge_constraint, TimepointId start,
           const std::vector<TimepointId>& edge_from, std::size_t limit,
           std::vector<TemporalConstraintId>* out) {
  TimepointId t = start;
  for (std::size_t i = 0; i < limit && pred[t] != SIZE_MAX; ++i) {
    std::size_t e = pred[t];
    TemporalConstraintId c = edge_constraint[e];
    if (std::find(out->begin(), out->end(), c) != out->end()) break;
    out->push_back(c);
    t = edge_from[e];
  }
}
}  // namespace

TemporalResult TemporalNetwork::add_constraint(TimepointId from, TimepointId to, Time lb, Time ub,
                                               TemporalConstraintId* id_out) {
  const TemporalConstraintId id = constraints_.size();
  if (id_out) *id_out = id;
  TemporalResult result;
  if (lb > ub || lb >= kInfinity || ub <= -kInfinity) {
    constraints_.push_back({from, to, lb, ub, false});
    result.consistent = false;
    result.conflict = {id};
    return result;
  }
  const Mark before = mark();
  constraints_.push_back({from, to, lb, ub, true});
  edge_count_at_constraint_.push_back(edges_.size());
  auto add_edge = [&](TimepointId a, TimepointId b, Time w) {
    if (w >= kInfinity) return;
    edges_.push_back({a, b, w, id});
    out_[a].push_back(edges_.size() - 1);
    in_[b].push_back(edges_.size() - 1);
  };
  add_edge(from, to, ub);
  add_edge(to, from, -lb);
  std::vector<TemporalConstraintId> conflict;
  bool ok = true;
  for (std::size_t e = edge_count_at_constraint_.back(); ok && e < edges_.size(); ++e) {
    ok = propagate_from({edges_[e].to}, {edges_[e].from}, id, &conflict);
  }
  if (!ok) {
    if (explain_) conflict = negative_cycle();  // with the new constraint still in
    undo_to(before);
    constraints_.push_back({from, to, lb, ub, false});
    result.consistent = false;
    result.conflict = std::move(conflict);
    // The closing constraint first, then the rest of the cycle.
    result.conflict.erase(std::remove(result.conflict.begin(), result.conflict.end(), id),
                          result.conflict.end());
    result.conflict.insert(result.conflict.begin(), id);
  }
  return result;
}

// Incremental propagation (a FIFO label-correcting search from the changed timepoints). The
// seeds are the endpoints of one new edge a->b: b's latest time and a's earliest time may
// tighten through it. Any further tightening of a seed's own bound means a walk from the seed
// back to itself of negative length, i.e. a negative cycle through the new edge; a latest time
// below an earliest time is a negative cycle through the origin. Either way: inconsistent.
bool TemporalNetwork::propagate_from(const std::vector<TimepointId>& seeds_latest,
                                     const std::vector<TimepointId>& seeds_earliest,
                                     TemporalConstraintId /*added*/,
                                     std::vector<TemporalConstraintId>* conflict) {
  const std::size_t n = earliest_.size();
  std::vector<std::size_t> pred(n, SIZE_MAX);
  std::vector<TemporalConstraintId> edge_constraint(edges_.size());
  std::vector<TimepointId> edge_from(edges_.size()), edge_to(edges_.size());
  auto fill_edge_tables = [&]() {
    for (std::size_t e = 0; e < edges_.size(); ++e) {
      edge_constraint[e] = edges_[e].constraint;
      edge_from[e] = edges_[e].from;
      edge_to[e] = edges_[e].to;
    }
  };
  std::deque<TimepointId> queue;
  std::vector<char> queued(n, 0);
  // Latest times, forward along out-edges.
  for (TimepointId seed : seeds_latest) {
    // The seed is tightened through its in-edges first (the new edge among them).
    for (std::size_t e : in_[seed]) {
      const Edge& ed = edges_[e];
      ++propagations_;
      if (latest_[ed.from] >= kInfinity) continue;
      Time v = latest_[ed.from] + ed.weight;
      if (v < latest_[seed]) {
        set_latest(seed, v);
        pred[seed] = e;
      }
    }
    if (latest_[seed] < earliest_[seed]) {
      fill_edge_tables();
      trace(pred, edge_constraint, seed, edge_from, n, conflict);
      return false;
    }
    queue.push_back(seed);
    queued[seed] = 1;
    while (!queue.empty()) {
      TimepointId x = queue.front();
      queue.pop_front();
      queued[x] = 0;
      if (latest_[x] >= kInfinity) continue;
      for (std::size_t e : out_[x]) {
        const Edge& ed = edges_[e];
        ++propagations_;
        Time v = latest_[x] + ed.weight;
        if (v < latest_[ed.to]) {
          set_latest(ed.to, v);
          pred[ed.to] = e;
          if (ed.to == seed || v < earliest_[ed.to]) {
            fill_edge_tables();
            trace(pred, edge_constraint, ed.to, edge_from, n, conflict);
            return false;
          }
          if (!queued[ed.to]) {
            queued[ed.to] = 1;
            queue.push_back(ed.to);
          }
        }
      }
    }
  }
  // Earliest times, backward along in-edges: from <= to - weight... i.e. for edge a->b with
  // weight w (b - a <= w), earliest(a) >= earliest(b) - w.
  std::fill(pred.begin(), pred.end(), SIZE_MAX);
  for (TimepointId seed : seeds_earliest) {
    for (std::size_t e : out_[seed]) {
      const Edge& ed = edges_[e];
      ++propagations_;
      Time v = earliest_[ed.to] - ed.weight;
      if (v > earliest_[seed]) {
        set_earliest(seed, v);
        pred[seed] = e;
      }
    }
    if (earliest_[seed] > latest_[seed]) {
      fill_edge_tables();
      trace(pred, edge_constraint, seed, edge_to, n, conflict);
      return false;
    }
    queue.push_back(seed);
    queued[seed] = 1;
    while (!queue.empty()) {
      TimepointId x = queue.front();
      queue.pop_front();
      queued[x] = 0;
      for (std::size_t e : in_[x]) {
        const Edge& ed = edges_[e];
        ++propagations_;
        Time v = earliest_[x] - ed.weight;
        if (v > earliest_[ed.from]) {
          set_earliest(ed.from, v);
          pred[ed.from] = e;
          if (ed.from == seed || v > latest_[ed.from]) {
            fill_edge_tables();
            trace(pred, edge_constraint, ed.from, edge_to, n, conflict);
            return false;
          }
          if (!queued[ed.from]) {
            queued[ed.from] = 1;
            queue.push_back(ed.from);
          }
        }
      }
    }
  }
  return true;
}

void TemporalNetwork::undo_to(const Mark& m) {
  while (trail_.size() > m.trail) {
    const BoundChange& c = trail_.back();
    (c.latest ? latest_ : earliest_)[c.t] = c.old_value;
    trail_.pop_back();
  }
  while (constraints_.size() > m.constraints) {
    if (constraints_.back().active) {
      // Active constraints were added last, their edges are at the ends of the lists.
      std::size_t first = edge_count_at_constraint_.back();
      edge_count_at_constraint_.pop_back();
      while (edges_.size() > first) {
        const Edge& e = edges_.back();
        out_[e.from].pop_back();
        in_[e.to].pop_back();
        edges_.pop_back();
      }
    }
    constraints_.pop_back();
  }
  earliest_.resize(m.timepoints);
  latest_.resize(m.timepoints);
  out_.resize(m.timepoints);
  in_.resize(m.timepoints);
}

void TemporalNetwork::remove_constraint(TemporalConstraintId id) {
  if (id >= constraints_.size() || !constraints_[id].active) return;
  constraints_[id].active = false;
  for (auto& lists : {&out_, &in_}) {
    for (auto& list : *lists) {
      list.erase(std::remove_if(list.begin(), list.end(),
                                [&](std::size_t e) { return edges_[e].constraint == id; }),
                 list.end());
    }
  }
  recompute();
}

void TemporalNetwork::recompute() {
  for (TimepointId t = 0; t < earliest_.size(); ++t) {
    Time e = 0, l = t == origin() ? 0 : horizon_;
    if (earliest_[t] != e) set_earliest(t, e);
    if (latest_[t] != l) set_latest(t, l);
  }
  // The network was consistent with the removed constraint, so it is without it: plain
  // label-correcting passes from every timepoint terminate.
  bool changed = true;
  while (changed) {
    changed = false;
    for (const Edge& ed : edges_) {
      if (!constraints_[ed.constraint].active) continue;
      if (latest_[ed.from] < kInfinity && latest_[ed.from] + ed.weight < latest_[ed.to]) {
        set_latest(ed.to, latest_[ed.from] + ed.weight);
        changed = true;
      }
      if (earliest_[ed.to] - ed.weight > earliest_[ed.from]) {
        set_earliest(ed.from, earliest_[ed.to] - ed.weight);
        changed = true;
      }
    }
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
    for (std::size_t e : out_[x])
      if (!relax(x, edges_[e].to, edges_[e].weight)) return shortest_distances(from)[to];
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
    for (std::size_t e : out_[x]) relax(edges_[e].to, dist[x] + edges_[e].weight);
    if (x != origin()) relax(origin(), dist[x]);
    if (x == origin() && horizon_ < kInfinity)
      for (TimepointId t = 1; t < earliest_.size(); ++t) relax(t, dist[x] + horizon_);
  }
  return dist;
}

}  // namespace autonomy::planner
