#pragma once
// One planning run: model + problem in, flexible plan (or the reason there is none) out.
// With a makespan objective the run is anytime: every better plan is handed to the callback,
// the bound is tightened below it, and an exhausted search proves the last plan optimal.
#include <functional>
#include <optional>
#include <string>

#include "flexible_plan.hpp"
#include "search_engine.hpp"

namespace autonomy::planner {

struct PlanningOptions {
  std::string engine = "chronological";
  EngineOptions engine_options;
  Termination termination;
  std::function<void(const FlexiblePlan&)> on_improvement;
  // An exhausted search names a small set of goals that cannot all hold (deletion filtering:
  // each goal left out in turn, kept out while the rest stays infeasible), within this many
  // decisions in all and the termination's stop condition; 0: no explanation.
  std::size_t explanation_decisions = 20000;
  // Not-first/not-last propagation on timelines (TokenNetwork::set_not_first_not_last).
  bool not_first_not_last = false;
};

enum class PlanStatus {
  kOptimal,        // the objective's best value, proved by an exhausted search
  kPlanFound,      // a plan (no objective, or the budget ended before the proof)
  kInfeasible,     // no plan exists (explanation says why when it is the problem's own)
  kOutOfBudget,    // no plan found within the budget
  kInvalidRequest  // e.g. an unknown engine name
};
const char* to_string(PlanStatus status);

struct PlanResult {
  PlanStatus status = PlanStatus::kInfeasible;
  std::optional<FlexiblePlan> plan;
  std::string explanation;
  SearchStatistics statistics;
  std::size_t improvements = 0;
};

PlanResult make_plan(const DomainModel& model, const PlanningProblem& problem,
                     const PlanningOptions& options);

}  // namespace autonomy::planner
