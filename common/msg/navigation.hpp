#pragma once
// C++ value types of idl/navigation.idl.
#include <cstdint>
#include <string>

namespace autonomy::msg {

struct NavGoal {
  std::string robot_id;
  std::string goal_id;
  double x = 0.0, y = 0.0;
  double tolerance = 0.0;
};

enum class GoalState { Accepted, Active, Reached, Failed, Preempted, Rejected };

struct GoalStatus {
  std::string robot_id;
  std::string goal_id;
  GoalState state = GoalState::Accepted;
  std::string reason;
  int64_t tick = 0;
  double distance_to_goal = 0.0;
};

const char* to_string(GoalState s);

}  // namespace autonomy::msg
