#pragma once
// What the World reports about one robot after a step; mirrors autonomy::RobotState.
#include "common/geometry/geometry.hpp"
#include "simulator/core/kinematics.hpp"

#include <string>

namespace autonomy::sim {

struct RobotStatus {
  std::string id;
  Kinematics kinematics = Kinematics::Holonomic;
  geometry::Pose2 pose;
  // Velocity achieved over the last step, in the command's frames: the held command scaled by
  // the fraction of the motion that was free (omega is never scaled: turning is always allowed).
  double vx = 0.0;
  double vy = 0.0;
  double omega = 0.0;
  double radius = 0.0;
  double max_speed = 0.0;
  double max_omega = 0.0;
  bool in_collision = false;        // the last step's motion was cut short by a contact
  double distance_travelled = 0.0;  // m, path length since spawn
};

}  // namespace autonomy::sim
