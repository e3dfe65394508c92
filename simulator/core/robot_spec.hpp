#pragma once
// A robot as configured: its body, its limits and where it starts.
#include "common/geometry/geometry.hpp"
#include "simulator/core/kinematics.hpp"

#include <string>

namespace autonomy::sim {

struct RobotSpec {
  std::string id;
  Kinematics kinematics = Kinematics::Holonomic;
  double radius = 0.3;     // m, the robot is a disc
  double max_speed = 1.0;  // m/s, commands above it are rejected, never clipped
  double max_omega = 2.0;  // rad/s
  geometry::Pose2 start;   // where spawn() puts the robot when no pose is given
};

}  // namespace autonomy::sim
