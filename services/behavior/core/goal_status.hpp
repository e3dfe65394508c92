#pragma once
// The life of one navigation goal as other services see it (autonomy::GoalStatus in
// idl/navigation.idl). Legal transitions:
//   set_goal: Rejected (terminal)  |  Accepted
//   Accepted -> Active -> Reached | Failed | Preempted
//   Accepted -> Failed (no route) | Preempted
#include <string>

namespace autonomy::behavior {

enum class GoalState { Accepted, Active, Reached, Failed, Preempted, Rejected };

// Lower-case name ("accepted", ...), for logs and reasons.
const char* to_string(GoalState state);

// Reached, Failed, Preempted and Rejected end a goal; nothing follows them for that goal id.
inline bool is_terminal(GoalState s) { return s != GoalState::Accepted && s != GoalState::Active; }

struct GoalStatus {
  std::string goal_id;
  GoalState state = GoalState::Accepted;
  std::string reason;             // why it failed, was rejected or preempted; empty otherwise
  double distance_to_goal = 0.0;  // m, straight line from the last known pose; 0 when unknown

  bool operator==(const GoalStatus& o) const {
    return goal_id == o.goal_id && state == o.state && reason == o.reason &&
           distance_to_goal == o.distance_to_goal;
  }
};

}  // namespace autonomy::behavior
