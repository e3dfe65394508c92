#pragma once
// The paper's constraint network manager (section 5): variables with domains, constraints as
// procedures behind one interface, propagation to a fixed point, an undo trail.
//
// A ConstraintProcedure only narrows the domains of its scope and must never remove a value
// that belongs to an allowed assignment; applied to singleton domains it accepts (leaves them)
// or rejects (empties one). That is all the network needs to know about a constraint.
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "domain.hpp"

namespace autonomy::planner {

using VariableId = std::size_t;
using ConstraintId = std::size_t;
class ConstraintNetwork;

class ConstraintProcedure {
 public:
  virtual ~ConstraintProcedure() = default;
  virtual const std::vector<VariableId>& scope() const = 0;
  // Narrows domains through network.narrow(); returns false when a domain became empty.
  virtual bool propagate(ConstraintNetwork& network) = 0;
  virtual std::string name() const = 0;
};

struct PropagationResult {
  bool consistent = true;
  ConstraintId failed = 0;          // the procedure that emptied a domain (when not consistent)
  bool failed_on_restrict = false;  // a restrict() call itself emptied the domain
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

  // Runs queued procedures until nothing changes (or a domain empties).
  [[nodiscard]] PropagationResult propagate();

  struct Mark {
    std::size_t trail, variables, constraints;
  };
  Mark mark() const { return {trail_.size(), domains_.size(), constraints_.size()}; }
  void undo_to(const Mark& m);

  struct Statistics {
    std::size_t procedure_calls = 0, narrowings = 0, failures = 0;
  };
  const Statistics& statistics() const { return stats_; }

 private:
  void enqueue_constraints_of(VariableId v);
  bool changed(VariableId v, Domain old);

  std::vector<Domain> domains_;
  std::vector<std::string> names_;
  std::vector<std::vector<ConstraintId>> constraints_of_;
  std::vector<std::unique_ptr<ConstraintProcedure>> constraints_;
  struct Change {
    VariableId v;
    Domain old;
  };
  std::vector<Change> trail_;
  std::vector<ConstraintId> agenda_;
  std::vector<char> queued_;
  ConstraintId running_ = SIZE_MAX;
  bool emptied_ = false;
  Statistics stats_;
};

}  // namespace autonomy::planner
