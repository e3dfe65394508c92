#pragma once
// Feasibility and cost of a GIVEN stop order: the referee every engine's answer is measured by,
// and what the executor uses to predict a modified plan ("deliver J first").
#include "services/courier/core/scheduler/job_schedule.hpp"
#include "services/courier/core/scheduler/scheduling_problem.hpp"

#include <vector>

namespace autonomy::courier::scheduling {

// Jobs no schedule can contain, in job order: pickup or delivery unreachable from every courier
// that could do the job (+inf travel; a job aboard can only be done by its courier), or a person
// who is never present again long enough for the handover. Necessary conditions only: a problem
// without such jobs may still be infeasible (engines then say kInfeasible).
std::vector<UnschedulableJob> find_unschedulable(const SchedulingProblem& problem);

// The schedule of `order` (one stop list per courier, forced prefixes included). Feasible when:
// every job not in find_unschedulable() appears exactly once per stop it needs (pickup only when
// waiting, delivery always), on one courier (a job aboard on its own courier), pickup before
// delivery, within capacity, no look-alike aboard at a pickup, every travel finite, every handover
// inside a presence window, and each courier's route starts with its forced prefix. Otherwise
// status kInfeasible and the reason names the courier, the stop index and the broken rule.
JobSchedule evaluate_order(const SchedulingProblem& problem,
                           const std::vector<std::vector<StopRef>>& order);

}  // namespace autonomy::courier::scheduling
