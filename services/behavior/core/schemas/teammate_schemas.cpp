#include "services/behavior/core/schemas/teammate_schemas.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace autonomy::behavior {

AvoidTeammates::AvoidTeammates(AvoidObstaclesConfig config)
    : profile_(config), max_magnitude_(config.max_magnitude) {}

geometry::Vec2 AvoidTeammates::vote(const Perception& p) const {
  const geometry::Vec2 me = p.pose.position();
  geometry::Vec2 sum = geometry::Vec2::Zero();
  for (const TeammateState& t : p.teammates) {
    if (!t.position) continue;
    const geometry::Vec2 away = me - *t.position;
    const double d = away.norm();
    if (!std::isfinite(d) || d == 0.0) continue;  // coincident: no direction to push in
    sum += away * (profile_.magnitude(d) / d);
  }
  const double n = sum.norm();
  if (n > max_magnitude_) sum *= max_magnitude_ / n;
  return sum;
}

StayNearTeammates::StayNearTeammates(StayNearConfig config) : config_(config) {
  if (!std::isfinite(config.comfort_radius_m) || config.comfort_radius_m < 0.0 ||
      !std::isfinite(config.max_radius_m) || config.max_radius_m <= config.comfort_radius_m) {
    throw std::invalid_argument("stay_near_teammates: need 0 <= comfort radius < max radius");
  }
}

geometry::Vec2 StayNearTeammates::vote(const Perception& p) const {
  geometry::Vec2 centroid = geometry::Vec2::Zero();
  int known = 0;
  for (const TeammateState& t : p.teammates) {
    if (!t.position) continue;
    centroid += *t.position;
    ++known;
  }
  if (known == 0) return geometry::Vec2::Zero();
  centroid /= known;
  const geometry::Vec2 towards = centroid - p.pose.position();
  const double d = towards.norm();
  if (!std::isfinite(d) || d <= config_.comfort_radius_m) return geometry::Vec2::Zero();
  const double m = std::min(1.0, (d - config_.comfort_radius_m) /
                                     (config_.max_radius_m - config_.comfort_radius_m));
  return towards * (m / d);
}

}  // namespace autonomy::behavior
