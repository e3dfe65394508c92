#include "simulator/core/free_space.hpp"

namespace autonomy::sim {

bool fits_in_world(double width, double height, const geometry::Vec2& center, double radius) {
  return center.x() - radius >= 0.0 && center.x() + radius <= width &&
         center.y() - radius >= 0.0 && center.y() + radius <= height;
}

std::optional<std::size_t> overlapping_obstacle(const std::vector<geometry::Rect>& obstacles,
                                                const geometry::Vec2& center, double radius) {
  for (std::size_t i = 0; i < obstacles.size(); ++i) {
    if (geometry::circle_overlaps(obstacles[i], center, radius)) return i;
  }
  return std::nullopt;
}

bool discs_overlap(const geometry::Vec2& a, double radius_a, const geometry::Vec2& b,
                   double radius_b) {
  return (a - b).norm() < radius_a + radius_b;
}

}  // namespace autonomy::sim
