#include "constraint_network.hpp"

#include <algorithm>

namespace autonomy::planner {

VariableId ConstraintNetwork::add_variable(Domain domain, std::string name) {
  domains_.push_back(std::move(domain));
  names_.push_back(std::move(name));
  constraints_of_.emplace_back();
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
  trail_.push_back({v, std::move(old)});
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
  std::size_t head = 0;
  while (result.consistent && head < agenda_.size()) {
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
  domains_.resize(m.variables, Domain::real(0, 0));
  names_.resize(m.variables);
  constraints_of_.resize(m.variables);
  for (ConstraintId c : agenda_)
    if (c < queued_.size()) queued_[c] = 0;
  agenda_.clear();
  emptied_ = false;
}

}  // namespace autonomy::planner
