#pragma once
// Internal to the scheduler library: which jobs every schedule leaves out, and an order that does
// all the others. The rule (docs/courier-scheduling.md, "Jobs left out"), in this order:
//   1. Unreachable (+inf travel from every courier that could do the job) or nobody present
//      again long enough for the handover.
//   2. Missed even on its own: no courier that may do the job can do it alone, driving straight
//      from where it stands after its forced prefix to the pickup and on to the delivery (travel,
//      presence windows, handover times; other jobs, capacity and look-alikes ignored), i.e. the
//      person leaves before the earliest arrival. Reported as nobody_present with the times.
//   3. Clash: when the jobs left after 1 and 2 cannot all be done together, they are admitted one
//      by one, objects aboard first, then in job order (the courier: the order the commands were
//      accepted); a job is kept when it and the jobs kept before it (with what the forced prefixes
//      picked up) can all be done, otherwise it is left out (UnschedulableReason::kClash). An
//      object left out stays aboard. So the kept set is maximal: no job left out can be added.
// Jobs with a stop in a forced prefix are never left out by 2 or 3 (the prefix is a command; when
// it cannot be done the problem is infeasible). Feasibility is decided by a complete depth-first
// search over stop orders (all couriers) with a fixed work limit per question, so the answer
// depends on the problem only: a question the limit cuts off counts as "cannot", and the job's
// detail says it was not proved. No clock, no budget: engines and evaluate_order agree.
#include "services/courier/core/scheduler/job_schedule.hpp"
#include "services/courier/core/scheduler/scheduling_problem.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace autonomy::courier::scheduling::detail {

struct JobSelection {
  std::vector<UnschedulableJob> unschedulable;  // in job order
  // When `feasible`: per courier its forced prefix, then stops doing every job kept.
  std::vector<std::vector<StopRef>> witness;
  // False when even the forced prefixes and the deliveries of what they pick up cannot be done.
  bool feasible = false;
  // Every feasibility question was answered inside the work limit (when !feasible: proved).
  bool proved = true;
  std::string reason;  // why not feasible
  std::uint64_t work = 0;
};

JobSelection select_jobs(const SchedulingProblem& problem);

}  // namespace autonomy::courier::scheduling::detail
