#pragma once
// Feasibility and cost of a GIVEN stop order: the referee every engine's answer is measured by,
// and what the executor uses to predict a modified plan ("deliver J first").
#include "services/courier/core/scheduler/job_schedule.hpp"
#include "services/courier/core/scheduler/scheduling_problem.hpp"

#include <vector>

namespace autonomy::courier::scheduling {

// The jobs every schedule leaves out, in job order, by the rule in docs/courier-scheduling.md
// ("Jobs left out"): unreachable; nobody present again; missed even on its own (the person leaves
// before any courier that may do the job can get there, from where it stands after its forced
// prefix); and, when the others cannot all be done together, each job that cannot be done with
// the jobs admitted before it (objects aboard first, then job order). Jobs with a stop in a forced
// prefix are only left out for the first two reasons. Depends on the problem only (a fixed search
// limit, no budget, no clock): every engine and evaluate_order leave out the same jobs. When even
// the forced prefixes cannot be done, engines say kInfeasible.
std::vector<UnschedulableJob> find_unschedulable(const SchedulingProblem& problem);

// The schedule of `order` (one stop list per courier, forced prefixes included). Feasible when:
// every job not in find_unschedulable() appears exactly once per stop it needs (pickup only when
// waiting, delivery always), on one courier (a job aboard on its own courier), pickup before
// delivery, within capacity, no look-alike aboard at a pickup, every travel finite, every handover
// inside a presence window, and each courier's route starts with its forced prefix. Otherwise
// status kInfeasible and the reason names the courier, the stop index and the broken rule.
JobSchedule evaluate_order(const SchedulingProblem& problem,
                           const std::vector<std::vector<StopRef>>& order);
// The same with the jobs left out already known (find_unschedulable(problem)'s answer): no search.
JobSchedule evaluate_order(const SchedulingProblem& problem,
                           const std::vector<std::vector<StopRef>>& order,
                           std::vector<UnschedulableJob> unschedulable);

}  // namespace autonomy::courier::scheduling
