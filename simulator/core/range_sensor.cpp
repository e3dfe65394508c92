#include "simulator/core/range_sensor.hpp"

#include "simulator/core/shapes.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace autonomy::sim {

RangeSensor::RangeSensor(const RangeSensorSpec& spec) : spec_(spec) {
  assert(spec.rays >= 1 && spec.max_range_m > 0.0);
  const int n = std::max(1, spec.rays);
  constexpr double kFullCircle = 2.0 * M_PI - 1e-9;
  if (spec.fov_rad >= kFullCircle) {
    angle_min_ = -M_PI;
    angle_increment_ = 2.0 * M_PI / n;
  } else {
    angle_min_ = n == 1 ? 0.0 : -0.5 * spec.fov_rad;
    angle_increment_ = n == 1 ? 0.0 : spec.fov_rad / (n - 1);
  }
  directions_.reserve(n);
  for (int i = 0; i < n; ++i) {
    const double a = angle_min_ + i * angle_increment_;
    directions_.emplace_back(std::cos(a), std::sin(a));
  }
}

RangeScan RangeSensor::scan(const geometry::Pose2& pose, const ObstacleMap& map,
                            const DynamicObstacles& dynamic, Rng* noise) const {
  const double max_range = spec_.max_range_m;
  const geometry::Vec2 origin = pose.position();

  // Only what can be within range matters for this scan.
  std::vector<Disc> robots;
  for (const Disc& d : dynamic.robots) {
    if ((d.center - origin).norm() < max_range + d.radius) robots.push_back(d);
  }
  std::vector<DoorLeaf> leaves;
  for (const DoorLeaf& l : dynamic.leaves) {
    if (segment_distance(origin, l.hinge, l.tip) < max_range) leaves.push_back(l);
  }

  RangeScan scan;
  scan.angle_min = angle_min_;
  scan.angle_increment = angle_increment_;
  scan.max_range_m = max_range;
  scan.ranges.resize(directions_.size());
  const double c = std::cos(pose.theta);
  const double s = std::sin(pose.theta);
  for (std::size_t i = 0; i < directions_.size(); ++i) {
    const geometry::Vec2& local = directions_[i];
    const geometry::Vec2 dir{c * local.x() - s * local.y(), s * local.x() + c * local.y()};
    double range = map.cast(origin, dir, max_range);
    for (const DoorLeaf& l : leaves) range = std::min(range, ray_segment(origin, dir, l.hinge, l.tip));
    for (const Disc& d : robots) range = std::min(range, ray_circle(origin, dir, d.center, d.radius));
    if (range < max_range && noise != nullptr && spec_.noise_stddev_m > 0.0) {
      range = std::clamp(noise->normal(range, spec_.noise_stddev_m), 0.0, std::nextafter(max_range, 0.0));
    }
    scan.ranges[i] = static_cast<float>(std::min(range, max_range));
  }
  return scan;
}

}  // namespace autonomy::sim
