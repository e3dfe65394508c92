#include "common/grid/occupancy_raster.hpp"

#include <bitset>
#include <cmath>

namespace autonomy::grid {

OccupancyRaster::OccupancyRaster(int width, int height, double resolution_m, RasterOrigin origin)
    : width_(width), height_(height), resolution_m_(resolution_m), origin_(origin) {
  assert(width >= 0 && height >= 0 && std::isfinite(resolution_m) && resolution_m > 0.0);
  words_per_row_ = (static_cast<std::size_t>(width) + 63) / 64;
  bits_.assign(words_per_row_ * static_cast<std::size_t>(height), 0);
}

void OccupancyRaster::set_blocked(Cell c, bool blocked) {
  assert(contains(c));
  auto& word = bits_[static_cast<std::size_t>(c.row) * words_per_row_ +
                     (static_cast<std::size_t>(c.col) >> 6)];
  const std::uint64_t bit = std::uint64_t{1} << (c.col & 63);
  word = blocked ? (word | bit) : (word & ~bit);
}

OccupancyRaster OccupancyRaster::with_resolution(double resolution_m) const {
  assert(std::isfinite(resolution_m) && resolution_m > 0.0);
  OccupancyRaster r = *this;
  r.resolution_m_ = resolution_m;
  return r;
}

std::size_t OccupancyRaster::blocked_count() const {
  std::size_t n = 0;
  for (auto w : bits_) n += std::bitset<64>(w).count();
  return n;
}

}  // namespace autonomy::grid
