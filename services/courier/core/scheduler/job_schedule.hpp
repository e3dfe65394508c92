#pragma once
// A schedule for a SchedulingProblem: per courier the ordered stops with their predicted times,
// per job its predicted completion, the objective terms, whether an engine proved it optimal, the
// jobs left out and the assumptions the schedule rests on (each room entered, with the predicted
// arrival: the executor watches these, a door seen closed breaks one).
#include "services/courier/core/scheduler/scheduling_problem.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace autonomy::courier::scheduling {

// Lexicographic: late_jobs, then lateness_s, completion_s, travel_s, interruptions. Doubles are
// compared with a 1e-6 s tolerance (sums of the same times in another order are equal).
struct Objective {
  int late_jobs = 0;
  double lateness_s = 0.0;    // sum over jobs of max(0, completion - deadline)
  double completion_s = 0.0;  // sum over jobs of (completion - now)
  double travel_s = 0.0;      // sum of travel times driven
  int interruptions = 0;      // visits: maximal runs of consecutive stops at one location

  Objective& operator+=(const Objective& o);
  friend Objective operator+(Objective a, const Objective& b) { return a += b; }
};

// -1, 0, +1 as a is better than, equal to (within tolerance) or worse than b. Inline: the
// engines' inner loops compare objectives millions of times.
inline int compare(const Objective& a, const Objective& b) {
  constexpr double kTolerance = 1e-6;
  auto time = [](double x, double y) {
    return x < y - kTolerance ? -1 : x > y + kTolerance ? 1 : 0;
  };
  if (a.late_jobs != b.late_jobs) return a.late_jobs < b.late_jobs ? -1 : 1;
  if (int c = time(a.lateness_s, b.lateness_s)) return c;
  if (int c = time(a.completion_s, b.completion_s)) return c;
  if (int c = time(a.travel_s, b.travel_s)) return c;
  if (a.interruptions != b.interruptions) return a.interruptions < b.interruptions ? -1 : 1;
  return 0;
}
inline bool better(const Objective& a, const Objective& b) {
  return compare(a, b) < 0;
}
// +inf in every term: worse than any schedule.
Objective worst_objective();

struct ScheduledStop {
  int job = -1;
  StopKind kind = StopKind::kPickup;
  int location = -1;
  int person = -1;
  double arrival_s = 0.0;
  double handover_start_s = 0.0;  // > arrival_s when waiting for the person's presence
  double finish_s = 0.0;
  bool same_visit_as_previous = false;  // merged: no travel, no new interruption
};

struct CourierRoute {
  int courier = -1;
  std::vector<ScheduledStop> stops;
};

struct JobOutcome {
  int job = -1;
  int courier = -1;
  double completion_s = 0.0;  // the delivery's finish
  double lateness_s = 0.0;
  bool late = false;
};

// "Room `room` is open when courier `courier` gets there at `arrival_s`": one per entry into a
// room (consecutive stops in one room are one entry). Stops in locations without a room make none.
struct RoomAssumption {
  int courier = -1;
  std::string room;
  int location = -1;  // the first location entered in that room
  double arrival_s = 0.0;
  int first_stop = 0;  // index into the courier's route
};

enum class UnschedulableReason : std::uint8_t {
  kUnreachable,    // pickup or delivery cannot be reached (+inf travel)
  kNobodyPresent,  // the person is not present long enough for the handover at any time a
                   // courier can be there (never again, or gone before the earliest arrival)
  kClash,          // doable on its own, not together with the jobs kept before it
};
const char* to_string(UnschedulableReason r);

struct UnschedulableJob {
  int job = -1;
  UnschedulableReason reason = UnschedulableReason::kUnreachable;
  std::string detail;  // "delivery A-120 desk cannot be reached from courier r1's location"
};

enum class ScheduleStatus : std::uint8_t {
  kOk,
  kInfeasible,      // no order satisfies the constraints (or the given order breaks one)
  kInvalidProblem,  // problem_error() is not empty
  kNoSolution,      // the budget ran out before any complete schedule was found
};
const char* to_string(ScheduleStatus s);

struct [[nodiscard]] JobSchedule {
  ScheduleStatus status = ScheduleStatus::kNoSolution;
  std::string reason;  // why not ok
  std::string engine;
  std::vector<CourierRoute> routes;  // one per courier, in courier order
  std::vector<JobOutcome> outcomes;  // one per scheduled job, in job order
  Objective objective;
  bool proved_optimal = false;
  std::vector<UnschedulableJob> unschedulable;
  std::vector<RoomAssumption> assumptions;  // per courier, in route order
  std::uint64_t work = 0;                   // engine-specific effort (nodes, evaluations)

  bool ok() const { return status == ScheduleStatus::kOk; }
  // The stop order per courier (what evaluate_order takes back).
  std::vector<std::vector<StopRef>> order() const;
};

}  // namespace autonomy::courier::scheduling
