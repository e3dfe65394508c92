#pragma once
// Where a disc-shaped robot may be: inside the world rectangle, clear of obstacles and of other
// robots. Touching is allowed (distance == radius), overlapping is not, so a robot stopped at
// contact can always move away again.
#include "common/geometry/geometry.hpp"

#include <cstddef>
#include <optional>
#include <vector>

namespace autonomy::sim {

// The disc lies entirely within [0, width] x [0, height].
bool fits_in_world(double width, double height, const geometry::Vec2& center, double radius);

// Index of the first obstacle the disc overlaps.
std::optional<std::size_t> overlapping_obstacle(const std::vector<geometry::Rect>& obstacles,
                                                const geometry::Vec2& center, double radius);

bool discs_overlap(const geometry::Vec2& a, double radius_a, const geometry::Vec2& b,
                   double radius_b);

}  // namespace autonomy::sim
