#pragma once
// Deterministic obstacle maps for tests and benchmarks: axis-aligned rectangles dropped at random
// until a target fraction of the cells is blocked. The same (size, fraction, seed) gives the same
// map on every platform: only std::mt19937_64's output (fixed by the standard) and integer
// arithmetic are used, no std::*_distribution.
#include "common/grid/occupancy_raster.hpp"

#include <cstdint>

namespace autonomy::grid {

// Rectangles have sides of 1 .. max(2, min(width, height) / 25) cells. The cell returned by
// random_map_goal is kept free (a 3 x 3 patch around the centre is cleared).
OccupancyRaster random_rectangles(int width, int height, double blocked_fraction,
                                  std::uint64_t seed, double resolution_m = 1.0);

// The centre cell, which random_rectangles keeps free.
Cell random_map_goal(const OccupancyRaster& raster);

}  // namespace autonomy::grid
