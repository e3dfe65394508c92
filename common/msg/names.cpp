// Human-readable names of the message enums, as logs and JSON show them.
#include "common/msg/clock.hpp"
#include "common/msg/courier.hpp"
#include "common/msg/navigation.hpp"
#include "common/msg/office.hpp"
#include "common/msg/planner.hpp"
#include "common/msg/robot.hpp"
#include "common/msg/simulation.hpp"
#include "common/msg/system.hpp"

namespace autonomy::msg {

const char* to_string(ServiceState s) {
  switch (s) {
    case ServiceState::Starting: return "starting";
    case ServiceState::Ready: return "ready";
    case ServiceState::Stopping: return "stopping";
  }
  return "?";
}

const char* to_string(ClockMode m) { return m == ClockMode::Lockstep ? "lockstep" : "paced"; }

const char* to_string(Kinematics k) { return k == Kinematics::Holonomic ? "holonomic" : "unicycle"; }

const char* to_string(RequestStatus s) { return s == RequestStatus::Accepted ? "accepted" : "rejected"; }

const char* to_string(GoalState s) {
  switch (s) {
    case GoalState::Accepted: return "accepted";
    case GoalState::Active: return "active";
    case GoalState::Reached: return "reached";
    case GoalState::Blocked: return "blocked";
    case GoalState::Preempted: return "preempted";
    case GoalState::Rejected: return "rejected";
    case GoalState::Cancelled: return "cancelled";
  }
  return "?";
}

const char* to_string(HandoverKind k) { return k == HandoverKind::Load ? "load" : "unload"; }

const char* to_string(HandoverState s) {
  switch (s) {
    case HandoverState::Accepted: return "accepted";
    case HandoverState::Rejected: return "rejected";
    case HandoverState::Completed: return "completed";
    case HandoverState::Failed: return "failed";
  }
  return "?";
}

const char* to_string(CourierCommandKind k) {
  switch (k) {
    case CourierCommandKind::Text: return "text";
    case CourierCommandKind::Deliver: return "deliver";
    case CourierCommandKind::Cancel: return "cancel";
    case CourierCommandKind::Revise: return "revise";
  }
  return "?";
}

const char* to_string(JobState s) {
  switch (s) {
    case JobState::Queued: return "queued";
    case JobState::Underway: return "underway";
    case JobState::Opportunistic: return "opportunistic";
    case JobState::Completed: return "completed";
    case JobState::Failed: return "failed";
    case JobState::Cancelled: return "cancelled";
    case JobState::Stranded: return "stranded";
  }
  return "?";
}

const char* to_string(PlanningStatus s) {
  switch (s) {
    case PlanningStatus::Optimal: return "optimal";
    case PlanningStatus::PlanFound: return "plan_found";
    case PlanningStatus::Infeasible: return "infeasible";
    case PlanningStatus::OutOfTime: return "out_of_time";
    case PlanningStatus::Cancelled: return "cancelled";
    case PlanningStatus::Rejected: return "rejected";
  }
  return "?";
}

}  // namespace autonomy::msg
