#include "services/behavior/core/schemas/avoid_obstacles.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace autonomy::behavior {

namespace {
bool finite_positive(double v) { return std::isfinite(v) && v > 0.0; }
}  // namespace

AvoidObstacles::AvoidObstacles(AvoidObstaclesConfig config) : config_(config) {
  if (!finite_positive(config.sphere_of_influence_m) || !std::isfinite(config.safety_margin_m) ||
      config.safety_margin_m < 0.0 || config.safety_margin_m >= config.sphere_of_influence_m ||
      !finite_positive(config.inside_margin_gain) || !finite_positive(config.max_magnitude)) {
    throw std::invalid_argument(
        "avoid_obstacles: need 0 <= safety margin < sphere of influence and positive gains");
  }
}

double AvoidObstacles::magnitude(double d) const {
  const double s = config_.sphere_of_influence_m;
  const double r = config_.safety_margin_m;
  if (d > s) return 0.0;
  if (d <= r) return config_.inside_margin_gain;
  return (s - d) / (s - r);
}

geometry::Vec2 AvoidObstacles::vote(const Perception& p) const {
  geometry::Vec2 sum = geometry::Vec2::Zero();
  for (const RangeRay& ray : p.rays) {
    if (!ray.hit() || !std::isfinite(ray.range_m) || !std::isfinite(ray.angle_rad)) continue;
    const double m = magnitude(std::max(ray.range_m, 0.0));
    if (m == 0.0) continue;
    // The obstacle lies along the ray; the repulsion points the opposite way.
    const double world_angle = p.pose.theta + ray.angle_rad;
    sum -= m * geometry::Vec2(std::cos(world_angle), std::sin(world_angle));
  }
  const double n = sum.norm();
  if (n > config_.max_magnitude) sum *= config_.max_magnitude / n;
  return sum;
}

}  // namespace autonomy::behavior
