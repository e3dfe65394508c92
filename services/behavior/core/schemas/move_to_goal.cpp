#include "services/behavior/core/schemas/move_to_goal.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace autonomy::behavior {

MoveToGoal::MoveToGoal(MoveToGoalConfig config) : config_(config) {
  if (!(std::isfinite(config.slowdown_radius_m) && config.slowdown_radius_m > 0.0)) {
    throw std::invalid_argument("move_to_goal: slowdown radius must be positive and finite");
  }
}

geometry::Vec2 MoveToGoal::vote(const Perception& p) const {
  if (!p.goal) return geometry::Vec2::Zero();
  const geometry::Vec2 delta = *p.goal - p.pose.position();
  const double d = delta.norm();
  if (!(d > 0.0) || !std::isfinite(d)) return geometry::Vec2::Zero();
  return delta * (std::min(1.0, d / config_.slowdown_radius_m) / d);
}

}  // namespace autonomy::behavior
