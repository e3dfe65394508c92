#pragma once
// move-to-goal (Arkin 1989): a unit vector from the robot towards the goal. Arkin's schema has a
// constant magnitude; here it ramps down linearly inside slowdown_radius_m so that a robot
// driven by this schema alone settles on the goal instead of oscillating across it:
//   |vote| = min(1, d / slowdown_radius_m),   d = distance to the goal.
// No goal in the perception, or d == 0: zero vote.
#include "services/behavior/core/schemas/motor_schema.hpp"

namespace autonomy::behavior {

struct MoveToGoalConfig {
  double slowdown_radius_m = 1.0;  // > 0
};

class MoveToGoal final : public MotorSchema {
 public:
  // Throws std::invalid_argument on a non-positive or non-finite radius.
  explicit MoveToGoal(MoveToGoalConfig config = {});

  [[nodiscard]] geometry::Vec2 vote(const Perception& p) const override;
  std::string_view name() const override { return "move_to_goal"; }

 private:
  MoveToGoalConfig config_;
};

}  // namespace autonomy::behavior
