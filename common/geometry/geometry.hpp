#pragma once
// Plane geometry shared by the simulator and the robot controllers: poses, axis-aligned
// rectangles (the first simulator's obstacles) and the circle tests robots need.
#include "common/geometry/vec2.hpp"

#include <algorithm>
#include <cmath>

namespace autonomy::geometry {

struct Pose2 {
  double x = 0.0;
  double y = 0.0;
  double theta = 0.0;  // rad, counter-clockwise from +x

  Vec2 position() const { return {x, y}; }
  bool operator==(const Pose2& o) const { return x == o.x && y == o.y && theta == o.theta; }
};

// Axis-aligned rectangle, min corner inclusive. An empty or inverted rectangle is invalid input
// and must be rejected where it enters (scenario files, map samples).
struct Rect {
  double min_x = 0.0;
  double min_y = 0.0;
  double max_x = 0.0;
  double max_y = 0.0;

  bool valid() const { return min_x < max_x && min_y < max_y; }
  bool contains(const Vec2& p) const {
    return p.x() >= min_x && p.x() <= max_x && p.y() >= min_y && p.y() <= max_y;
  }
  Rect inflated(double margin) const {
    return {min_x - margin, min_y - margin, max_x + margin, max_y + margin};
  }
  bool operator==(const Rect& o) const {
    return min_x == o.min_x && min_y == o.min_y && max_x == o.max_x && max_y == o.max_y;
  }
};

// Distance from p to the closest point of r; 0 inside.
inline double distance(const Rect& r, const Vec2& p) {
  const double cx = std::clamp(p.x(), r.min_x, r.max_x);
  const double cy = std::clamp(p.y(), r.min_y, r.max_y);
  return std::hypot(p.x() - cx, p.y() - cy);
}

inline bool circle_overlaps(const Rect& r, const Vec2& center, double radius) {
  return distance(r, center) < radius;
}

// Angle wrapped to (-pi, pi].
inline double wrap_angle(double a) {
  a = std::remainder(a, 2.0 * M_PI);
  return a <= -M_PI ? a + 2.0 * M_PI : a;
}

}  // namespace autonomy::geometry
