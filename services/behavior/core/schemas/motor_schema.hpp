#pragma once
// A motor schema (Arkin, "Motor Schema-Based Mobile Robot Navigation", IJRR 8(4), 1989; and
// Behavior-Based Robotics, MIT Press 1998, ch. 4): one primitive behaviour that turns a perception
// into a vote, a vector saying which way and how strongly it wants the robot to move. A
// SchemaBlend multiplies each vote by its gain, sums them and scales the sum to a velocity.
//
// Contract for implementations:
//  - vote() is const, deterministic and has no side effects: the same perception gives the same
//    vote (Noise derives its randomness from the perception's time and a seed, not from a hidden
//    generator), so a run can be replayed and a test can assert exact numbers.
//  - Votes are dimensionless, world frame, and finite. Magnitude 1 means "full strength"; only
//    AvoidObstacles inside its safety margin votes more than 1.
#include "common/geometry/geometry.hpp"
#include "services/behavior/core/schemas/perception.hpp"

#include <string_view>

namespace autonomy::behavior {

class MotorSchema {
 public:
  virtual ~MotorSchema() = default;

  [[nodiscard]] virtual geometry::Vec2 vote(const Perception& p) const = 0;
  // A short fixed name for logs and blend reports ("move_to_goal", "avoid_obstacles", ...).
  virtual std::string_view name() const = 0;
};

}  // namespace autonomy::behavior
