#include "services/behavior/core/goal_status.hpp"

namespace autonomy::behavior {

const char* to_string(GoalState state) {
  switch (state) {
    case GoalState::Accepted: return "accepted";
    case GoalState::Active: return "active";
    case GoalState::Reached: return "reached";
    case GoalState::Blocked: return "blocked";
    case GoalState::Preempted: return "preempted";
    case GoalState::Rejected: return "rejected";
    case GoalState::Cancelled: return "cancelled";
  }
  return "unknown";
}

}  // namespace autonomy::behavior
