#include "services/behavior/core/goal_status.hpp"

namespace autonomy::behavior {

const char* to_string(GoalState state) {
  switch (state) {
    case GoalState::Accepted: return "accepted";
    case GoalState::Active: return "active";
    case GoalState::Reached: return "reached";
    case GoalState::Failed: return "failed";
    case GoalState::Preempted: return "preempted";
    case GoalState::Rejected: return "rejected";
  }
  return "unknown";
}

}  // namespace autonomy::behavior
