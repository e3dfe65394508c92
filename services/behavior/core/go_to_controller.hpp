#pragma once
// The motion side of a navigation goal: turns a cost-to-go field into a velocity command.
//
// Each call picks a target point and drives towards it:
//  - the goal itself when it is within the lookahead distance and in line of sight;
//  - otherwise the visible cell c within the lookahead that minimises cost(c) + |c - robot|, an
//    any-angle estimate of the remaining path through c. Because grid costs overestimate straight
//    distances, this picks the farthest visible point down the field, so the robot cuts the
//    8-connected staircase into straight segments and rounds obstacles along their inflated edge.
// "Visible" means every cell the segment touches is reachable (exact grid traversal).
//
// When the robot's centre sits in a blocked or unreachable cell (pushed into the inflation margin,
// spawned there), it first heads for the nearest reachable cell ("escaping").
//
// Holonomic robots get a world-frame velocity and omega = 0 (heading is not controlled). Unicycles
// turn in place when the heading error exceeds turn_in_place_rad, otherwise move forward at a speed
// that falls linearly to zero at that error, so arcs stay tight near obstacles. Both slow down
// linearly within slowdown_radius_m of the goal. Commands never exceed the limits.
//
// Stateless and deterministic: the same pose and field always give the same command.
#include "common/geometry/geometry.hpp"
#include "services/behavior/core/cost_to_go_field.hpp"
#include "services/behavior/core/velocity_command.hpp"

#include <cstddef>
#include <tuple>
#include <vector>

namespace autonomy::behavior {

struct GoToConfig {
  double lookahead_m = 1.0;        // how far ahead the robot looks for a visible downhill point
  double slowdown_radius_m = 0.5;  // full speed beyond, proportional to distance within
  double heading_gain = 3.0;       // rad/s of turn rate per rad of heading error (unicycle)
  double turn_in_place_rad = 0.6;  // unicycle: above this heading error, stop and turn
};

enum class GoToOutcome {
  Following,  // moving along the field
  Escaping,   // moving back out of the inflation margin to the nearest reachable cell
  Arrived,    // within tolerance: zero command
  Stuck,      // no route (goal blocked, robot far inside an obstacle or off the map): zero command
};

struct GoToDecision {
  VelocityCommand command;
  GoToOutcome outcome = GoToOutcome::Stuck;
  geometry::Vec2 target = geometry::Vec2::Zero();  // the point steered to; for plots and debugging
};

class GoToController {
 public:
  // Throws std::invalid_argument on non-positive or non-finite limits or config values; the node
  // checks robot parameters before this, the throw keeps a zero limit from freezing a robot.
  GoToController(Kinematics kinematics, MotionLimits limits, GoToConfig config = {});

  [[nodiscard]] GoToDecision command(const geometry::Pose2& pose, const CostToGoField& field,
                                     double tolerance_m) const;

  Kinematics kinematics() const { return kinematics_; }
  const MotionLimits& limits() const { return limits_; }
  const GoToConfig& config() const { return config_; }

 private:
  geometry::Vec2 choose_target(const geometry::Vec2& p, const CostToGoField& field) const;
  VelocityCommand drive_towards(const geometry::Pose2& pose, const geometry::Vec2& target,
                                double speed_cap) const;

  Kinematics kinematics_;
  MotionLimits limits_;
  GoToConfig config_;
  // choose_target()'s candidates, kept so that a command per tick allocates nothing.
  mutable std::vector<std::tuple<double, std::size_t>> ranked_;
};

}  // namespace autonomy::behavior
