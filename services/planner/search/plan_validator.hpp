#pragma once
// A check of a plan against the model and the problem that shares nothing with the search:
// every timepoint is fixed at its earliest time (always a solution of a consistent simple
// temporal network) and then the timelines, durations, parameter constraints, configuration
// constraints, goals, relations and resources are checked on those fixed times.
#include <string>
#include <vector>

#include "domain_model.hpp"
#include "flexible_plan.hpp"

namespace autonomy::planner {

// Every violation found, in words; empty when the plan is valid.
std::vector<std::string> validate_plan(const DomainModel& model, const PlanningProblem& problem,
                                       const FlexiblePlan& plan);

}  // namespace autonomy::planner
