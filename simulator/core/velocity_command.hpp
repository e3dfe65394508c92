#pragma once
// A controller's request for motion, and the simulator's verdict on it.
#include <cstdint>
#include <string>

namespace autonomy::sim {

// Mirrors autonomy::VelocityCommand of idl/robot.idl.
struct VelocityCommand {
  std::string robot_id;
  std::string source;     // the sending participant (lockstep bookkeeping, rejection reports)
  std::int64_t tick = 0;  // the tick it was computed for; 0 outside lockstep
  double vx = 0.0;        // m/s: world frame (holonomic) or forward in the body frame (unicycle)
  double vy = 0.0;        // m/s, world frame; must be 0 for a unicycle
  double omega = 0.0;     // rad/s, counter-clockwise
};

// Rejected commands are never applied (and never clipped: a controller asking for more than
// the robot can do has a bug the reason should show).
struct [[nodiscard]] CommandResult {
  bool accepted = false;
  std::string reason;  // why it was rejected; empty when accepted

  static CommandResult accept() { return {true, {}}; }
  static CommandResult reject(std::string why) { return {false, std::move(why)}; }
};

}  // namespace autonomy::sim
