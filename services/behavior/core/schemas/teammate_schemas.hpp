#pragma once
// Team schemas over the teammates' last known positions (teammates never heard are ignored).
//
// AvoidTeammates: Arkin's avoid-obstacle profile applied to each teammate (linear from 0 at
// sphere_of_influence_m to 1 at safety_margin_m, inside_margin_gain closer), summed and clipped
// to max_magnitude, so robots do not bunch up at a shared waypoint.
//
// StayNearTeammates: attraction towards the centroid of the teammates' positions, 0 within
// comfort_radius_m, growing linearly to 1 at max_radius_m and 1 beyond: a soft pull that keeps the
// team within radio range without dictating the route.
#include "services/behavior/core/schemas/avoid_obstacles.hpp"
#include "services/behavior/core/schemas/motor_schema.hpp"

namespace autonomy::behavior {

class AvoidTeammates final : public MotorSchema {
 public:
  explicit AvoidTeammates(AvoidObstaclesConfig config = {});  // throws like AvoidObstacles

  [[nodiscard]] geometry::Vec2 vote(const Perception& p) const override;
  std::string_view name() const override { return "avoid_teammates"; }

 private:
  AvoidObstacles profile_;
  double max_magnitude_;
};

struct StayNearConfig {
  double comfort_radius_m = 10.0;  // >= 0
  double max_radius_m = 30.0;      // > comfort_radius_m
};

class StayNearTeammates final : public MotorSchema {
 public:
  explicit StayNearTeammates(StayNearConfig config = {});  // throws std::invalid_argument

  [[nodiscard]] geometry::Vec2 vote(const Perception& p) const override;
  std::string_view name() const override { return "stay_near_teammates"; }

 private:
  StayNearConfig config_;
};

}  // namespace autonomy::behavior
