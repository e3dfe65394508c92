#pragma once
// The textbook dynamic program for one courier, kept as the baseline the exact engine is measured
// against (bench/courier_bench.cpp) and as a cross-check in tests: states are (stops done, last
// stop), expanded breadth first by the number of stops done; each state keeps its Pareto labels
// (time, lexicographic cost), since with deadlines and presence windows one label per state is
// not exact. No bounds, no incumbent: every label is expanded.
#include "services/courier/core/scheduler/job_schedule.hpp"
#include "services/courier/core/scheduler/scheduling_problem.hpp"

#include <cstdint>
#include <vector>

namespace autonomy::courier::scheduling {

struct ReferenceDpResult {
  bool feasible = false;
  Objective best;
  std::vector<StopRef> route;  // forced prefix included
  std::uint64_t labels = 0;    // labels created
};

// One courier (index `courier`) doing every schedulable job it may do; up to 26 jobs (else not
// feasible).
ReferenceDpResult reference_dp(const SchedulingProblem& problem, int courier = 0);

}  // namespace autonomy::courier::scheduling
