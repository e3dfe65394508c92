#include "planner.hpp"

#include <algorithm>

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

// The problem with only the goals in `keep` (initial values stay); relations that name a goal
// left out go with it.
PlanningProblem with_goals(const PlanningProblem& p, const std::vector<bool>& keep) {
  PlanningProblem out = p;
  out.facts.clear();
  out.relations.clear();
  out.objective = pb::Problem::NONE;  // feasibility only
  std::vector<int> index(p.facts.size(), -1);
  for (std::size_t f = 0; f < p.facts.size(); ++f) {
    if (!p.facts[f].initial && !keep[f]) continue;
    index[f] = int(out.facts.size());
    out.facts.push_back(p.facts[f]);
  }
  for (const FactRelationDef& r : p.relations) {
    if (index[r.from] < 0 || index[r.to] < 0) continue;
    FactRelationDef copy = r;
    copy.from = index[r.from];
    copy.to = index[r.to];
    out.relations.push_back(copy);
  }
  return out;
}

// Deletion filtering over the goals: each goal left out in turn stays out when the others are
// still proved infeasible (exhausted search); an undecided test (budget) keeps it. What stays
// cannot all hold together; it is minimal when every test was decided.
std::string explain_exhausted(const DomainModel& model, const PlanningProblem& problem,
                              const PlanningOptions& options) {
  std::vector<bool> keep(problem.facts.size(), true);
  std::size_t goals = 0, left = options.explanation_decisions;
  for (const FactDef& f : problem.facts) goals += !f.initial;
  if (goals < 2 || left == 0) return {};
  PlanningOptions inner = options;
  inner.on_improvement = nullptr;
  inner.explanation_decisions = 0;
  for (std::size_t f = 0; f < problem.facts.size() && left > 0; ++f) {
    if (problem.facts[f].initial) continue;
    if (options.termination.stop && options.termination.stop()) break;
    keep[f] = false;
    inner.termination.max_decisions = std::min(left, options.termination.max_decisions);
    const PlanResult r = make_plan(model, with_goals(problem, keep), inner);
    left -= std::min(left, r.statistics.decisions + 1);
    if (r.status != PlanStatus::kInfeasible) keep[f] = true;
  }
  std::string text;
  for (std::size_t f = 0; f < problem.facts.size(); ++f) {
    if (problem.facts[f].initial || !keep[f]) continue;
    text += (text.empty() ? "" : "; ") + std::string("goal ") +
            (problem.facts[f].label.empty() ? std::to_string(f) : problem.facts[f].label) + " (" +
            problem.facts[f].where + ")";
  }
  return text;
}

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
  net.set_not_first_not_last(options.not_first_not_last);
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
        if (result.status == PlanStatus::kInfeasible) {
          result.explanation = "every choice of slots, merges and values fails (search exhausted)";
          const std::string goals = explain_exhausted(model, problem, options);
          if (!goals.empty())
            result.explanation = "search exhausted: no plan achieves together: " + goals;
        }
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
