#pragma once
// The simulator's names for the shared polygon and ray tests (common/geometry/shapes.hpp): the
// world, its sensors and the radio model use them as sim::Polygon, sim::ray_segment, ...
// Conventions follow free_space.hpp: touching is not overlapping (distance == radius is free).
#include "common/geometry/shapes.hpp"

namespace autonomy::sim {

using geometry::cross;
using geometry::disc_overlaps_polygon;
using geometry::kNoHit;
using geometry::Polygon;
using geometry::polygon_contains;
using geometry::polygon_problem;
using geometry::ray_circle;
using geometry::ray_segment;
using geometry::segment_distance;
using geometry::segments_intersect;

}  // namespace autonomy::sim
