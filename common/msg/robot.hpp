#pragma once
// C++ value types of idl/robot.idl.
#include <cstdint>
#include <string>

namespace autonomy::msg {

enum class Kinematics { Holonomic, Unicycle };

struct RobotState {
  std::string robot_id;
  int64_t tick = 0;
  int64_t sim_time_ns = 0;
  double x = 0.0, y = 0.0, theta = 0.0;
  double vx = 0.0, vy = 0.0, omega = 0.0;
  Kinematics kinematics = Kinematics::Holonomic;
  double radius = 0.0;
  double max_speed = 0.0;
  double max_omega = 0.0;
  bool in_collision = false;
};

struct VelocityCommand {
  std::string robot_id;
  std::string source;
  int64_t tick = 0;
  double vx = 0.0, vy = 0.0, omega = 0.0;
};

struct CommandRejection {
  std::string robot_id;
  std::string source;
  int64_t tick = 0;
  std::string reason;
};

const char* to_string(Kinematics k);

}  // namespace autonomy::msg
