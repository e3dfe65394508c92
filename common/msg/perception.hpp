#pragma once
// C++ value types of idl/perception.idl: what a robot senses.
#include <cstdint>
#include <string>
#include <vector>

namespace autonomy::msg {

struct RangeScan {
  std::string robot_id;
  int64_t tick = 0;
  double angle_min = 0.0;
  double angle_increment = 0.0;
  double max_range = 0.0;
  std::vector<float> ranges;
};

struct PoseEstimate {
  std::string robot_id;
  int64_t tick = 0;
  double x = 0.0, y = 0.0, theta = 0.0;
};

struct DoorSighting {
  std::string door_id;
  double angle_estimate = 0.0;
  double distance = 0.0;
  double bearing = 0.0;
};

struct DoorObservation {
  std::string robot_id;
  int64_t tick = 0;
  std::vector<DoorSighting> doors;
};

}  // namespace autonomy::msg
