#include "constraint_network.hpp"

#include <algorithm>

namespace autonomy::planner {

VariableId ConstraintNetwork::add_variable(Domain domain, std::string name) {
  domains_.push_back(std::move(domain));
  names_.push_back(std::move(name));
  constraints_of_.emplace_back();
  last_trailed_.push_back(SIZE_MAX);
  return domains_.size() - 1;
}

ConstraintId ConstraintNetwork::add_constraint(std::unique_ptr<ConstraintProcedure> procedure) {
  const ConstraintId id = constraints_.size();
  for (VariableId v : procedure->scope()) constraints_of_[v].push_back(id);
  constraints_.push_back(std::move(procedure));
  queued_.push_back(1);
  agenda_.push_back(id);
  return id;
}

bool ConstraintNetwork::changed(VariableId v, Domain old) {
  // Already trailed since the latest mark (an entry that an undo has not taken back): that
  // entry holds the value to restore.
  const std::size_t last = last_trailed_[v];
  if (!(last != SIZE_MAX && last >= trail_floor_ && last < trail_.size() && trail_[last].v == v)) {
    last_trailed_[v] = trail_.size();
    trail_.push_back({v, std::move(old)});
  }
  ++stats_.narrowings;
  enqueue_constraints_of(v);
  if (domains_[v].empty()) emptied_ = true;
  return !domains_[v].empty();
}

bool ConstraintNetwork::narrow(VariableId v, const Domain& d) {
  Domain old = domains_[v];
  if (!domains_[v].intersect(d)) return !domains_[v].empty();
  return changed(v, std::move(old));
}

bool ConstraintNetwork::narrow_bounds(VariableId v, double lo, double hi) {
  Domain old = domains_[v];
  if (!domains_[v].restrict_bounds(lo, hi)) return !domains_[v].empty();
  return changed(v, std::move(old));
}

bool ConstraintNetwork::remove_value(VariableId v, std::int64_t value) {
  Domain old = domains_[v];
  if (!domains_[v].remove(value)) return !domains_[v].empty();
  return changed(v, std::move(old));
}

void ConstraintNetwork::enqueue_constraints_of(VariableId v) {
  for (ConstraintId c : constraints_of_[v]) {
    // The running procedure is not re-queued for its own reductions: procedures narrow to
    // their own fixed point or are idempotent enough that another call adds nothing.
    if (c == running_ || queued_[c]) continue;
    queued_[c] = 1;
    agenda_.push_back(c);
  }
}

PropagationResult ConstraintNetwork::propagate() {
  PropagationResult result;
  if (emptied_) {
    result.consistent = false;
    result.failed_on_restrict = true;
  }
  std::size_t head = 0, calls = 0;
  std::size_t next_stop_check = 256, next_cycle_check = 16 * constraints_.size() + 1024;
  while (result.consistent && head < agenda_.size()) {
    if (++calls >= next_stop_check) {
      next_stop_check = calls + 256;
      if (stop_ && stop_()) {
        result.consistent = false;
        result.interrupted = true;
        break;
      }
    }
    // Far more calls than constraints: bounds may be stepping through a cycle of differences.
    if (calls >= next_cycle_check) {
      next_cycle_check = 2 * calls;
      result.cycle = positive_cycle();
      if (!result.cycle.empty()) {
        result.consistent = false;
        result.failed = result.cycle.front();
        break;
      }
    }
    if (head > 4096 && 2 * head > agenda_.size()) {  // the agenda stays as long as its queue
      agenda_.erase(agenda_.begin(), agenda_.begin() + long(head));
      head = 0;
    }
    ConstraintId c = agenda_[head++];
    queued_[c] = 0;
    running_ = c;
    ++stats_.procedure_calls;
    bool ok = constraints_[c]->propagate(*this) && !emptied_;
    running_ = SIZE_MAX;
    if (!ok) {
      result.consistent = false;
      result.failed = c;
    }
  }
  for (std::size_t i = head; i < agenda_.size(); ++i) queued_[agenda_[i]] = 0;
  agenda_.clear();
  if (!result.consistent) ++stats_.failures;
  emptied_ = false;
  return result;
}

std::vector<ConstraintId> ConstraintNetwork::positive_cycle() const {
  // Longest paths from a virtual source to every variable (Bellman-Ford): a distance still
  // growing after as many rounds as there are variables lies on or behind a positive cycle.
  struct Edge {
    std::size_t a, b;
    double offset;
    ConstraintId c;
  };
  std::vector<Edge> edges;
  std::vector<std::size_t> index(domains_.size(), SIZE_MAX);
  std::size_t n = 0;
  std::vector<DifferenceEdge> found;
  for (ConstraintId c = 0; c < constraints_.size(); ++c) {
    found.clear();
    constraints_[c]->differences(&found);
    for (const DifferenceEdge& e : found) {
      if (index[e.a] == SIZE_MAX) index[e.a] = n++;
      if (index[e.b] == SIZE_MAX) index[e.b] = n++;
      edges.push_back({index[e.a], index[e.b], e.offset, c});
    }
  }
  std::vector<double> distance(n, 0);
  std::vector<std::size_t> through(n, SIZE_MAX);  // the edge that last raised the distance
  std::size_t raised = SIZE_MAX;
  for (std::size_t round = 0; round <= n; ++round) {
    raised = SIZE_MAX;
    for (std::size_t k = 0; k < edges.size(); ++k) {
      const Edge& e = edges[k];
      if (distance[e.a] + e.offset > distance[e.b]) {
        distance[e.b] = distance[e.a] + e.offset;
        through[e.b] = k;
        raised = e.b;
      }
    }
    if (raised == SIZE_MAX) return {};
    if (stop_ && stop_()) return {};  // the caller's next check ends the propagation
  }
  // Walk back n steps to be on the cycle, then once around it.
  std::size_t v = raised;
  for (std::size_t i = 0; i < n; ++i) {
    if (through[v] == SIZE_MAX) return {};
    v = edges[through[v]].a;
  }
  std::vector<ConstraintId> cycle;
  std::size_t u = v;
  do {
    if (through[u] == SIZE_MAX) return {};
    cycle.push_back(edges[through[u]].c);
    u = edges[through[u]].a;
  } while (u != v && cycle.size() <= n);
  std::reverse(cycle.begin(), cycle.end());
  return cycle;
}

void ConstraintNetwork::undo_to(const Mark& m) {
  while (trail_.size() > m.trail) {
    domains_[trail_.back().v] = std::move(trail_.back().old);
    trail_.pop_back();
  }
  while (constraints_.size() > m.constraints) {
    for (VariableId v : constraints_.back()->scope()) {
      auto& list = constraints_of_[v];
      if (!list.empty() && list.back() == constraints_.size() - 1) list.pop_back();
    }
    constraints_.pop_back();
    queued_.pop_back();
  }
  trail_floor_ = std::min(trail_floor_, m.trail);
  domains_.resize(m.variables, Domain::real(0, 0));
  last_trailed_.resize(m.variables);
  names_.resize(m.variables);
  constraints_of_.resize(m.variables);
  for (ConstraintId c : agenda_)
    if (c < queued_.size()) queued_[c] = 0;
  agenda_.clear();
  emptied_ = false;
}

}  // namespace autonomy::planner
