#pragma once
// A planning raster: which cells of a regular grid a robot may occupy, one bit per cell.
//
// Orientation: row 0 is the bottom row (lowest world y), as in ROS's nav_msgs/OccupancyGrid and
// the behavior controller's grid. Cell (col, row) covers, in the map frame,
//   [origin.x + col * res, origin.x + (col + 1) * res) x [origin.y + row * res, origin.y + (row +
//   1) * res)
// rotated by origin.yaw about (origin.x, origin.y). An image loaded from a ROS map (whose first
// pixel row is the top) is therefore flipped on load; see map_loader.hpp.
//
// Storage is one bit per cell, rows padded to 64-bit words, so a 4000 x 4000 map costs 2 MB and
// whole words of a row can be read at once.
#include <cassert>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace autonomy::grid {

struct Cell {
  int col = 0;
  int row = 0;

  bool operator==(const Cell& o) const { return col == o.col && row == o.row; }
  bool operator!=(const Cell& o) const { return !(*this == o); }
};

// Pose of cell (0, 0)'s outer corner in the map frame, as in a ROS map YAML's `origin: [x, y,
// yaw]`.
struct RasterOrigin {
  double x = 0.0;
  double y = 0.0;
  double yaw = 0.0;
};

class OccupancyRaster {
 public:
  OccupancyRaster() = default;
  // All cells free. width, height >= 0; resolution > 0 (metres per cell side).
  OccupancyRaster(int width, int height, double resolution_m, RasterOrigin origin = {});

  int width() const { return width_; }
  int height() const { return height_; }
  double resolution_m() const { return resolution_m_; }
  const RasterOrigin& origin() const { return origin_; }
  std::size_t cell_count() const {
    return static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_);
  }
  bool contains(Cell c) const {
    return c.col >= 0 && c.row >= 0 && c.col < width_ && c.row < height_;
  }
  // Row-major, row 0 first: the layout of every per-cell array in this library.
  std::size_t index(Cell c) const {
    assert(contains(c));
    return static_cast<std::size_t>(c.row) * static_cast<std::size_t>(width_) +
           static_cast<std::size_t>(c.col);
  }

  // Cells outside the raster count as blocked.
  bool blocked(Cell c) const {
    if (!contains(c)) return true;
    return (row_words(c.row)[static_cast<std::size_t>(c.col) >> 6] >> (c.col & 63)) & 1u;
  }
  void set_blocked(Cell c, bool blocked);
  // The same cells with another cell size (e.g. 1.0 to measure costs in cells).
  OccupancyRaster with_resolution(double resolution_m) const;
  std::size_t blocked_count() const;

  // Bit i of word i / 64 is cell (i, row); bits past width() are zero. For whole-row algorithms.
  std::size_t words_per_row() const { return words_per_row_; }
  const std::uint64_t* row_words(int row) const {
    assert(row >= 0 && row < height_);
    return bits_.data() + static_cast<std::size_t>(row) * words_per_row_;
  }

  std::size_t storage_bytes() const { return bits_.size() * sizeof(std::uint64_t); }

 private:
  int width_ = 0;
  int height_ = 0;
  double resolution_m_ = 1.0;
  RasterOrigin origin_;
  std::size_t words_per_row_ = 0;
  std::vector<std::uint64_t> bits_;  // 1 = blocked
};

}  // namespace autonomy::grid
