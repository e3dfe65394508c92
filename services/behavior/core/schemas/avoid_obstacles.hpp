#pragma once
// avoid-obstacles, in the classic formulation of Arkin, "Motor Schema-Based Mobile Robot
// Navigation", International Journal of Robotics Research 8(4):92-112, 1989 (also Behavior-Based
// Robotics, 1998, section 4.4). For an obstacle at distance d, with sphere of influence S and
// safety margin R (R < S), the repulsion points from the obstacle to the robot with magnitude
//   0                   for d > S
//   (S - d) / (S - R)   for R < d <= S     (0 at the edge of the sphere, 1 at the margin)
//   inside_margin_gain  for d <= R         (Arkin's "infinity", kept finite so sums stay usable)
//
// Obstacles are the hits of the range rays: each ray that hit something (range < max_range) is
// one obstacle point at that range along the ray. The vote is the sum over rays, then clipped to
// max_magnitude. A wall seen by k rays therefore pushes up to k times as hard as a post seen by
// one; pick S, the gains and max_magnitude for the sensor's ray count (the clip bounds the worst
// case). Rays that saw nothing contribute nothing.
#include "services/behavior/core/schemas/motor_schema.hpp"

namespace autonomy::behavior {

struct AvoidObstaclesConfig {
  double sphere_of_influence_m = 3.0;  // S, > safety_margin_m
  double safety_margin_m = 0.5;        // R, >= 0
  double inside_margin_gain = 10.0;    // magnitude per ray at d <= R, > 0
  double max_magnitude = 10.0;         // clip on the summed vote, > 0
};

class AvoidObstacles final : public MotorSchema {
 public:
  // Throws std::invalid_argument on inconsistent or non-finite parameters.
  explicit AvoidObstacles(AvoidObstaclesConfig config = {});

  [[nodiscard]] geometry::Vec2 vote(const Perception& p) const override;
  std::string_view name() const override { return "avoid_obstacles"; }

  // The magnitude profile above for one obstacle at distance d (exposed for tests and plots).
  double magnitude(double d) const;

 private:
  AvoidObstaclesConfig config_;
};

}  // namespace autonomy::behavior
