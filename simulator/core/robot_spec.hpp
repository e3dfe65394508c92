#pragma once
// A robot as configured: its body, its limits and where it starts.
#include "common/geometry/geometry.hpp"
#include "simulator/core/kinematics.hpp"
#include "simulator/core/sensor_spec.hpp"

#include <cstdint>

#include <string>

namespace autonomy::sim {

struct RobotSpec {
  std::string id;
  Kinematics kinematics = Kinematics::Holonomic;
  double radius = 0.3;     // m, the robot is a disc
  double max_speed = 1.0;  // m/s, commands above it are rejected, never clipped
  double max_omega = 2.0;  // rad/s
  geometry::Pose2 start;   // where spawn() puts the robot when no pose is given
  std::string kind;        // what sort of robot ("courier", "scout"); informative for the core
  std::uint32_t capacity = 1;  // how many items it can carry at once (0: carries nothing)
  SensorSpec sensors;      // all absent unless configured
};

}  // namespace autonomy::sim
