#pragma once
// The paper's constraint network manager (section 5): variables with domains, constraints as
// procedures behind one interface, propagation to a fixed point, an undo trail.
//
// A ConstraintProcedure only narrows the domains of its scope and must never remove a value
// that belongs to an allowed assignment; applied to singleton domains it accepts (leaves them)
// or rejects (empties one). That is all the network needs to know about a constraint.
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "domain.hpp"

namespace autonomy::planner {

using VariableId = std::size_t;
using ConstraintId = std::size_t;
class ConstraintNetwork;

// A relation a + offset <= b between two variables' values.
struct DifferenceEdge {
  VariableId a, b;
  double offset;
};

class ConstraintProcedure {
 public:
  virtual ~ConstraintProcedure() = default;
  virtual const std::vector<VariableId>& scope() const = 0;
  // Narrows domains through network.narrow(); returns false when a domain became empty.
  virtual bool propagate(ConstraintNetwork& network) = 0;
  virtual std::string name() const = 0;
  // The relations a + offset <= b the procedure implies, if any. Bounds propagation steps
  // through a cycle of them whose offsets add up above 0 (a < b, b < a) one offset at a time,
  // 10^9 steps on a range of 10^9; the network finds such a cycle instead (no values satisfy
  // it).
  virtual void differences(std::vector<DifferenceEdge>* out) const { (void)out; }
};

struct PropagationResult {
  bool consistent = true;
  ConstraintId failed = 0;          // the procedure that emptied a domain (when not consistent)
  bool failed_on_restrict = false;  // a restrict() call itself emptied the domain
  bool interrupted = false;         // the stop condition ended it: nothing is proved
  std::vector<ConstraintId> cycle;  // a cycle of differences no values satisfy (the failure)
  explicit operator bool() const { return consistent; }
};

class ConstraintNetwork {
 public:
  VariableId add_variable(Domain domain, std::string name = {});
  ConstraintId add_constraint(std::unique_ptr<ConstraintProcedure> procedure);

  const Domain& domain(VariableId v) const { return domains_[v]; }
  const std::string& name(VariableId v) const { return names_[v]; }
  std::size_t variable_count() const { return domains_.size(); }
  const ConstraintProcedure& constraint(ConstraintId c) const { return *constraints_[c]; }
  std::size_t constraint_count() const { return constraints_.size(); }

  // Intersects v's domain with d (a decision or a procedure's reduction); trailed, and the
  // constraints on v are queued. Returns false when the domain is empty afterwards.
  bool narrow(VariableId v, const Domain& d);
  bool narrow_bounds(VariableId v, double lo, double hi);
  bool remove_value(VariableId v, std::int64_t value);

  // Runs queued procedures until nothing changes (or a domain empties, or stop says so).
  [[nodiscard]] PropagationResult propagate();
  // Asked every few hundred procedure calls of a propagation (a deadline, a cancellation):
  // true ends it inconsistent and `interrupted`; the caller undoes as after any failure.
  void set_stop(std::function<bool()> stop) { stop_ = std::move(stop); }

  struct Mark {
    std::size_t trail, variables, constraints;
  };
  // A variable's domain is trailed once per mark (its value when the mark was taken): a long
  // propagation that narrows the same variables again and again does not grow the trail.
  Mark mark() const {
    trail_floor_ = trail_.size();
    return {trail_.size(), domains_.size(), constraints_.size()};
  }
  void undo_to(const Mark& m);

  struct Statistics {
    std::size_t procedure_calls = 0, narrowings = 0, failures = 0;
  };
  const Statistics& statistics() const { return stats_; }

 private:
  void enqueue_constraints_of(VariableId v);
  bool changed(VariableId v, Domain old);
  // The constraints of a cycle of differences whose offsets add up above 0, or none.
  std::vector<ConstraintId> positive_cycle() const;

  std::vector<Domain> domains_;
  std::vector<std::string> names_;
  std::vector<std::vector<ConstraintId>> constraints_of_;
  std::vector<std::unique_ptr<ConstraintProcedure>> constraints_;
  struct Change {
    VariableId v;
    Domain old;
  };
  std::vector<Change> trail_;
  std::vector<std::size_t> last_trailed_;  // per variable: its latest trail entry
  mutable std::size_t trail_floor_ = 0;    // the trail's size at the latest mark
  std::function<bool()> stop_;
  std::vector<ConstraintId> agenda_;
  std::vector<char> queued_;
  ConstraintId running_ = SIZE_MAX;
  bool emptied_ = false;
  Statistics stats_;
};

}  // namespace autonomy::planner
