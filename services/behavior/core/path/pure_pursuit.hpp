#pragma once
// Following a planned path: pure pursuit. The robot steers on the circle through its position and
// the path point one look-ahead distance ahead, which turns a polyline into a smooth drive and
// pulls a robot pushed off the path back onto it. A pure function of the path, the robot's pose
// and its limits: the go-to logic keeps the progress index between ticks.
//
// Commands always respect the limits: a unicycle slows down rather than exceed max_omega (so it
// keeps the curvature it needs), turns in place when the target is behind it, and slows down near
// the goal. Reverse segments (Reeds-Shepp) are driven forward by turning first: the tracker is
// forward-only.
#include "common/geometry/geometry.hpp"
#include "services/behavior/core/velocity_command.hpp"

#include <cstddef>
#include <vector>

namespace autonomy::behavior {

struct PursuitSettings {
  double lookahead_m = 0.6;        // > 0
  double goal_tolerance_m = 0.1;   // arrived within this of the last pose
  double slow_down_m = 0.8;        // full speed until this close to the goal, then proportional
  double heading_gain = 2.0;       // holonomic robots: omega per rad of heading error
  std::size_t search_window = 40;  // poses ahead of `progress` searched for the closest one
};

struct PursuitStep {
  VelocityCommand command;
  std::size_t progress = 0;  // index of the path pose closest to the robot (never decreases)
  bool arrived = false;      // the command is zero
};

// `progress` is the previous step's (0 at the start). An empty path gives a zero command, arrived.
PursuitStep pure_pursuit(const std::vector<geometry::Pose2>& path, std::size_t progress,
                         const geometry::Pose2& robot, Kinematics kinematics,
                         const MotionLimits& limits, const PursuitSettings& settings = {});

}  // namespace autonomy::behavior
