#pragma once
// Scheduling engines behind one work method (in the manner of OMPL's Planner::solve): an engine
// takes a problem and a budget and returns a JobSchedule. Engines are created by name.
//
//   exact  - branch and bound over partial routes with dominance (proved_optimal when it finishes
//            inside the budget); several couriers by enumerating job assignments.
//   large  - greedy dispatch, then local search (stop moves, job relocation between couriers,
//            ruin and recreate) until the budget says stop; anytime, never proves optimality.
//   paper  - FAXBOT's SCHEDULE-DELIVERIES: hallway sort, then conflict removal (the baseline).
//
// The budget is work units plus an optional stop predicate the engines poll every few hundred
// units: the library reads no clock; a caller who wants a wall-clock budget passes a predicate
// (wall_clock_budget.hpp). An engine that runs out returns its best schedule so far (not proved),
// or kNoSolution when it has none.
#include "services/courier/core/scheduler/job_schedule.hpp"
#include "services/courier/core/scheduler/scheduling_problem.hpp"

#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace autonomy::courier::scheduling {

struct SearchBudget {
  std::uint64_t max_work = std::numeric_limits<std::uint64_t>::max();
  std::function<bool()> stop;  // true = stop now; polled, may be empty
  std::uint64_t seed = 1;      // for the randomised engines (same seed + work = same answer)

  bool exhausted(std::uint64_t work) const { return work >= max_work || (stop && stop()); }
};

class SchedulerEngine {
 public:
  virtual ~SchedulerEngine() = default;
  virtual const char* name() const = 0;
  // Never throws for a bad problem: kInvalidProblem with problem_error()'s text.
  virtual JobSchedule solve(const SchedulingProblem& problem, const SearchBudget& budget) = 0;
};

// "exact", "large" or "paper"; nullptr for another name.
std::unique_ptr<SchedulerEngine> make_scheduler_engine(const std::string& name);
std::vector<std::string> scheduler_engine_names();

// The executor's opportunity check: is doing `stops` first on `courier` (e.g. job J's delivery
// behind a door just seen open) harmless? Solves the problem as it is and with the stops forced
// first (after any prefix the courier already has), with the same engine and budget each.
struct OpportunityCheck {
  bool keeps_deadlines = false;  // every job on time without the detour is on time with it
  JobSchedule without_detour;
  JobSchedule with_detour;
};
OpportunityCheck check_opportunity(const SchedulingProblem& problem, int courier,
                                   const std::vector<StopRef>& stops, SchedulerEngine& engine,
                                   const SearchBudget& budget);

}  // namespace autonomy::courier::scheduling
