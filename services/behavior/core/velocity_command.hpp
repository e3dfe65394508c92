#pragma once
// What the behavior controller sends to a robot, with the robot's kinematic model and limits.
// Frames follow autonomy::RobotState / VelocityCommand in idl/robot.idl.
namespace autonomy::behavior {

enum class Kinematics {
  Holonomic,  // vx, vy in the world frame, omega
  Unicycle,   // vx = forward speed in the body frame, omega; vy is always 0
};

struct MotionLimits {
  double max_speed_mps = 0.0;  // holonomic: norm of (vx, vy); unicycle: vx
  double max_omega_rps = 0.0;
};

struct VelocityCommand {
  double vx = 0.0;
  double vy = 0.0;
  double omega = 0.0;

  bool is_zero() const { return vx == 0.0 && vy == 0.0 && omega == 0.0; }
};

}  // namespace autonomy::behavior
