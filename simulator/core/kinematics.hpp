#pragma once
// How a robot's velocity command maps to motion. Mirrors the Kinematics enum of idl/robot.idl.
#include <string_view>

namespace autonomy::sim {

enum class Kinematics {
  Holonomic,  // vx, vy in the world frame, omega: the robot can move in any direction
  Unicycle,   // vx is forward speed in the body frame, vy must be 0, omega turns the heading
};

constexpr std::string_view to_string(Kinematics k) {
  return k == Kinematics::Holonomic ? "holonomic" : "unicycle";
}

}  // namespace autonomy::sim
