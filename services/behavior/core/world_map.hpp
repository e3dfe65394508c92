#pragma once
// The static world as the behavior controller receives it (autonomy/map): a rectangle
// [0, width] x [0, height] with axis-aligned obstacles. A plain value; the DDS node converts the
// IDL sample into it at the edge.
#include "common/geometry/geometry.hpp"

#include <vector>

namespace autonomy::behavior {

struct WorldMap {
  double width_m = 0.0;
  double height_m = 0.0;
  std::vector<geometry::Rect> obstacles;
};

}  // namespace autonomy::behavior
