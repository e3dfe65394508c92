#pragma once
// The life of one navigation goal as other services see it (autonomy::GoalStatus in
// idl/navigation.idl). Legal transitions:
//   set_goal: Rejected (terminal)  |  Accepted
//   Accepted -> Active -> Reached | Blocked | Preempted | Cancelled
//   Accepted -> Blocked (no route) | Preempted | Cancelled
// Blocked was called Failed before (same place in the enum, same wire value): the goal cannot be
// reached from where the robot is: no route on the plan, in collision or no progress for a while.
#include <string>

namespace autonomy::behavior {

enum class GoalState { Accepted, Active, Reached, Blocked, Preempted, Rejected, Cancelled };

// Lower-case name ("accepted", ...), for logs and reasons.
const char* to_string(GoalState state);

// Reached, Blocked, Preempted, Rejected and Cancelled end a goal; nothing follows them for that goal id.
inline bool is_terminal(GoalState s) { return s != GoalState::Accepted && s != GoalState::Active; }

struct GoalStatus {
  std::string goal_id;
  GoalState state = GoalState::Accepted;
  std::string reason;             // why it was blocked, rejected, preempted or cancelled, or resumed (active
                                  // again after a restart, behavior --journal); else empty
  double distance_to_goal = 0.0;  // m, straight line from the last known pose; 0 when unknown

  bool operator==(const GoalStatus& o) const {
    return goal_id == o.goal_id && state == o.state && reason == o.reason &&
           distance_to_goal == o.distance_to_goal;
  }
};

}  // namespace autonomy::behavior
