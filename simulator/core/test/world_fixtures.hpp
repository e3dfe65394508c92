#pragma once
// Small worlds shared by the World tests.
#include "simulator/core/world.hpp"

namespace autonomy::sim::test {

inline RobotSpec robot_spec(std::string id, Kinematics k, double x, double y, double theta = 0.0) {
  RobotSpec r;
  r.id = std::move(id);
  r.kinematics = k;
  r.start = {x, y, theta};
  return r;
}

// A 20 x 12 m room with one obstacle, and a command timeout long enough that motion tests do
// not have to refresh their commands.
inline WorldSpec room() {
  WorldSpec spec;
  spec.name = "room";
  spec.width = 20.0;
  spec.height = 12.0;
  spec.obstacles = {{10.0, 4.0, 11.0, 8.0}};
  spec.command_timeout_s = 100.0;
  spec.attach_defaults.radius = 0.25;
  return spec;
}

inline VelocityCommand command(std::string robot, double vx, double vy, double omega) {
  VelocityCommand c;
  c.robot_id = std::move(robot);
  c.source = "test";
  c.vx = vx;
  c.vy = vy;
  c.omega = omega;
  return c;
}

inline void run(World& world, int steps, double dt = 0.05) {
  for (int i = 0; i < steps; ++i) world.step(dt);
}

}  // namespace autonomy::sim::test
