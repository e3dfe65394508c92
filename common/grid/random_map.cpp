#include "common/grid/random_map.hpp"

#include <algorithm>
#include <cstdlib>
#include <random>

namespace autonomy::grid {

OccupancyRaster random_rectangles(int width, int height, double blocked_fraction,
                                  std::uint64_t seed, double resolution_m) {
  OccupancyRaster r(width, height, resolution_m);
  if (width <= 0 || height <= 0) return r;
  std::mt19937_64 rng(seed);
  const auto uniform = [&rng](std::uint64_t n) {
    return static_cast<int>(rng() % n);
  };  // tiny bias is fine
  const int max_side = std::max(2, std::min(width, height) / 25);
  const auto target =
      static_cast<std::size_t>(blocked_fraction * static_cast<double>(r.cell_count()));
  const Cell goal = random_map_goal(r);
  std::size_t blocked = 0;
  // Count as we go; 100 tries per cell bound the loop if the target is unreachable.
  for (std::size_t tries = 0; blocked < target && tries < 100 * r.cell_count(); ++tries) {
    const int w = 1 + uniform(static_cast<std::uint64_t>(max_side));
    const int h = 1 + uniform(static_cast<std::uint64_t>(max_side));
    const int c0 = uniform(static_cast<std::uint64_t>(width));
    const int r0 = uniform(static_cast<std::uint64_t>(height));
    for (int row = r0; row < std::min(height, r0 + h) && blocked < target; ++row) {
      for (int col = c0; col < std::min(width, c0 + w) && blocked < target; ++col) {
        if (std::abs(col - goal.col) <= 1 && std::abs(row - goal.row) <= 1) continue;
        if (!r.blocked({col, row})) {
          r.set_blocked({col, row}, true);
          ++blocked;
        }
      }
    }
  }
  return r;
}

Cell random_map_goal(const OccupancyRaster& raster) {
  return {raster.width() / 2, raster.height() / 2};
}

}  // namespace autonomy::grid
