#include "planner.hpp"

namespace autonomy::planner {

const char* to_string(PlanStatus status) {
  switch (status) {
    case PlanStatus::kOptimal:
      return "optimal";
    case PlanStatus::kPlanFound:
      return "plan found";
    case PlanStatus::kInfeasible:
      return "infeasible";
    case PlanStatus::kOutOfBudget:
      return "out of budget";
    case PlanStatus::kInvalidRequest:
      return "invalid request";
  }
  return "?";
}

namespace {
void add(SearchStatistics& total, const SearchStatistics& s) {
  total.decisions += s.decisions;
  total.backtracks += s.backtracks;
  total.dead_ends += s.dead_ends;
  total.plans += s.plans;
  total.temporal_propagations += s.temporal_propagations;
  total.procedure_calls += s.procedure_calls;
}
}  // namespace

PlanResult make_plan(const DomainModel& model, const PlanningProblem& problem,
                     const PlanningOptions& options) {
  PlanResult result;
  auto engine = make_search_engine(options.engine, options.engine_options);
  if (!engine) {
    result.status = PlanStatus::kInvalidRequest;
    result.explanation = "unknown search engine '" + options.engine + "'";
    return result;
  }
  TokenNetwork net(model, problem);
  // Propagation honours the budget and cancellation too (before any search starts, a model's
  // parameter constraints can take long: issue 29).
  net.set_stop(options.termination.stop);
  if (!net.initialize()) {
    result.status = net.interrupted() ? PlanStatus::kOutOfBudget : PlanStatus::kInfeasible;
    result.explanation = net.conflict();
    return result;
  }
  const bool optimise = problem.objective == pb::Problem::MAKESPAN;
  // The termination budget spans the whole run, not each restart.
  Termination left = options.termination;
  TokenNetwork::Mark root = net.mark();
  while (true) {
    SearchOutcome out = engine->solve(net, left);
    add(result.statistics, out.statistics);
    // A propagation the stop condition cut short failed without proving anything.
    if (out.status == SearchStatus::kExhausted && net.interrupted())
      out.status = SearchStatus::kOutOfBudget;
    if (left.max_decisions != static_cast<std::size_t>(-1))
      left.max_decisions -= std::min(left.max_decisions, out.statistics.decisions);
    if (out.status != SearchStatus::kPlanFound) {
      if (!result.plan) {
        result.status = out.status == SearchStatus::kExhausted ? PlanStatus::kInfeasible
                                                               : PlanStatus::kOutOfBudget;
        if (result.status == PlanStatus::kInfeasible)
          result.explanation = "every choice of slots, merges and values fails (search exhausted)";
      } else {
        result.status =
            out.status == SearchStatus::kExhausted ? PlanStatus::kOptimal : PlanStatus::kPlanFound;
      }
      return result;
    }
    result.plan = extract_plan(net);
    ++result.improvements;
    if (options.on_improvement) options.on_improvement(*result.plan);
    if (!optimise) {
      result.status = PlanStatus::kPlanFound;
      return result;
    }
    // Back to the root and ask for something strictly better.
    net.undo_to(root);
    if (!net.bound_makespan(result.plan->makespan - 1)) {
      result.status = PlanStatus::kOptimal;
      return result;
    }
    root = net.mark();
  }
}

}  // namespace autonomy::planner
