#pragma once
// Why each job went to its courier, in words a user reads in the job status: "assigned to rhino2:
// 3 min earlier than rhino1". The engines choose the assignment by the fleet's lexicographic
// objective (late jobs, lateness, completion, travel, visits); this names, per job, the best other
// courier and what moving the job there would cost: the job itself later ("3 min earlier than
// rhino1"), or, when the other courier would be as quick for this job, which objective term the
// rest of the fleet would lose ("rhino1 would be 1 min earlier but 2 other jobs late").
//
// The comparison is one local move: the job's stops are taken out of its courier's route and put
// into the other courier's route at the best positions (every pickup/delivery position pair,
// capped at kMaxInsertionTries route simulations per other courier, then appended at the end).
// It explains the schedule, it does not re-solve it.
#include "services/courier/core/scheduler/job_schedule.hpp"
#include "services/courier/core/scheduler/scheduling_problem.hpp"

#include <optional>
#include <string>
#include <vector>

namespace autonomy::courier::scheduling {

struct AllocationReason {
  int job = -1;
  int courier = -1;           // where the schedule put it
  int alternative = -1;       // the best other courier, -1 when no other can do it
  double completion_s = 0.0;  // on `courier`
  std::optional<double> alternative_completion_s;  // on `alternative`, after the best insertion
  Objective fleet_difference;  // fleet objective with the move minus the schedule's (per term)
  std::string text;            // "assigned to rhino2: 3 min earlier than rhino1"
};

constexpr int kMaxInsertionTries = 400;

// One entry per job the schedule does; empty when the problem has one courier or the schedule is
// not ok. Jobs aboard a courier say so ("aboard rhino1": no choice).
std::vector<AllocationReason> explain_allocation(const SchedulingProblem& problem,
                                                 const JobSchedule& schedule);

// "40 s", "3 min", "1 h 05 min" for a positive duration.
std::string duration_text(double seconds);

}  // namespace autonomy::courier::scheduling
