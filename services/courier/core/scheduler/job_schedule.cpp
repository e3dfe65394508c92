#include "services/courier/core/scheduler/job_schedule.hpp"

namespace autonomy::courier::scheduling {

Objective& Objective::operator+=(const Objective& o) {
  late_jobs += o.late_jobs;
  lateness_s += o.lateness_s;
  completion_s += o.completion_s;
  travel_s += o.travel_s;
  interruptions += o.interruptions;
  return *this;
}

Objective worst_objective() {
  Objective o;
  o.late_jobs = 1 << 30;
  o.lateness_s = o.completion_s = o.travel_s = kNoRoute;
  o.interruptions = 1 << 30;
  return o;
}

const char* to_string(UnschedulableReason r) {
  switch (r) {
    case UnschedulableReason::kUnreachable:
      return "unreachable";
    case UnschedulableReason::kNobodyPresent:
      return "nobody_present";
    case UnschedulableReason::kClash:
      return "clash";
  }
  return "?";
}

const char* to_string(ScheduleStatus s) {
  switch (s) {
    case ScheduleStatus::kOk:
      return "ok";
    case ScheduleStatus::kInfeasible:
      return "infeasible";
    case ScheduleStatus::kInvalidProblem:
      return "invalid_problem";
    case ScheduleStatus::kNoSolution:
      return "no_solution";
  }
  return "?";
}

std::vector<std::vector<StopRef>> JobSchedule::order() const {
  std::vector<std::vector<StopRef>> out;
  out.reserve(routes.size());
  for (const CourierRoute& r : routes) {
    auto& stops = out.emplace_back();
    stops.reserve(r.stops.size());
    for (const ScheduledStop& s : r.stops) stops.push_back({s.job, s.kind});
  }
  return out;
}

}  // namespace autonomy::courier::scheduling
