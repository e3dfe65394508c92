#pragma once
// C++ value types of idl/navigation.idl.
#include <cstdint>
#include <string>
#include <vector>

namespace autonomy::msg {

struct NavGoal {
  std::string robot_id;
  std::string goal_id;
  double x = 0.0, y = 0.0;
  double tolerance = 0.0;
  std::string constraint_set;  // "" = obstacles only
};

struct NavCancel {
  std::string robot_id;
  std::string goal_id;  // "" = whatever is pursued
  std::string reason;
};

// Blocked was called Failed before (same wire value).
enum class GoalState { Accepted, Active, Reached, Blocked, Preempted, Rejected, Cancelled };

struct GoalStatus {
  std::string robot_id;
  std::string goal_id;
  GoalState state = GoalState::Accepted;
  std::string reason;
  int64_t tick = 0;
  double distance_to_goal = 0.0;
};

struct MissionStatus {
  std::string robot_id;
  std::string mission;
  std::string state;
  std::string event;
  std::string reason;
  bool finished = false;
  int64_t tick = 0;
};

struct ItineraryPoint {
  double x = 0.0, y = 0.0;
  int64_t t_ns = 0;
};

// A robot's itinerary (docs/traffic.md); claim is "", "waiting" or "holding".
struct Itinerary {
  std::string robot_id;
  int64_t tick = 0;
  int64_t sim_time_ns = 0;
  double radius = 0.0;
  double x = 0.0, y = 0.0;
  std::vector<ItineraryPoint> path;
  std::string passage;
  std::string claim;
  int64_t request_time_ns = 0;
  std::string waiting_for;
};

const char* to_string(GoalState s);

}  // namespace autonomy::msg
