#include "services/behavior/core/occupancy_grid.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace autonomy::behavior {

namespace {

bool positive_finite(double v) { return std::isfinite(v) && v > 0.0; }

// Number of cells covering `length`; the tolerance keeps 10 / 0.1 from becoming 101 cells.
int cells_covering(double length_m, double resolution_m) {
  return static_cast<int>(std::ceil(length_m / resolution_m - 1e-9));
}

}  // namespace

OccupancyGrid::OccupancyGrid(const WorldMap& world, double resolution_m, double inflation_radius_m) {
  if (!positive_finite(world.width_m) || !positive_finite(world.height_m)) {
    throw std::invalid_argument("world width and height must be positive and finite");
  }
  if (!positive_finite(resolution_m)) {
    throw std::invalid_argument("grid resolution must be positive and finite");
  }
  if (!std::isfinite(inflation_radius_m) || inflation_radius_m < 0.0) {
    throw std::invalid_argument("inflation radius must be finite and not negative");
  }
  const double cols = std::ceil(world.width_m / resolution_m - 1e-9);
  const double rows = std::ceil(world.height_m / resolution_m - 1e-9);
  if (cols * rows > static_cast<double>(kMaxCells)) {
    throw std::invalid_argument("grid would exceed the cell limit; use a coarser resolution");
  }
  for (const auto& o : world.obstacles) {
    if (!o.valid() || !std::isfinite(o.min_x) || !std::isfinite(o.min_y) || !std::isfinite(o.max_x) ||
        !std::isfinite(o.max_y)) {
      throw std::invalid_argument("obstacle rectangles must be finite with min < max");
    }
  }

  geometry_ = GridGeometry(cells_covering(world.width_m, resolution_m),
                           cells_covering(world.height_m, resolution_m), resolution_m);
  width_m_ = world.width_m;
  height_m_ = world.height_m;
  inflation_radius_m_ = inflation_radius_m;
  blocked_.assign(geometry_.cell_count(), 0);

  const double r = inflation_radius_m;
  for (int row = 0; row < geometry_.rows(); ++row) {
    for (int col = 0; col < geometry_.cols(); ++col) {
      const auto c = geometry_.centre({col, row});
      if (c.x() < r || c.y() < r || c.x() > width_m_ - r || c.y() > height_m_ - r) {
        blocked_[geometry_.index({col, row})] = 1;
      }
    }
  }

  // Visit only the cells under each grown obstacle's bounding box; the exact test is the distance
  // to the rectangle, so corners are rounded as they are for a circular robot.
  for (const auto& o : world.obstacles) {
    const auto box = o.inflated(r);
    const int c0 = std::max(0, static_cast<int>(std::floor(box.min_x / resolution_m)));
    const int r0 = std::max(0, static_cast<int>(std::floor(box.min_y / resolution_m)));
    const int c1 = std::min(geometry_.cols() - 1, static_cast<int>(std::floor(box.max_x / resolution_m)));
    const int r1 = std::min(geometry_.rows() - 1, static_cast<int>(std::floor(box.max_y / resolution_m)));
    for (int row = r0; row <= r1; ++row) {
      for (int col = c0; col <= c1; ++col) {
        if (geometry::distance(o, geometry_.centre({col, row})) <= r) {
          blocked_[geometry_.index({col, row})] = 1;
        }
      }
    }
  }
}

OccupancyGrid OccupancyGrid::from_picture(const std::vector<std::string>& rows_top_first,
                                          double resolution_m) {
  if (rows_top_first.empty() || rows_top_first.front().empty()) {
    throw std::invalid_argument("a grid picture needs at least one cell");
  }
  if (!positive_finite(resolution_m)) {
    throw std::invalid_argument("grid resolution must be positive and finite");
  }
  const auto cols = rows_top_first.front().size();
  for (const auto& line : rows_top_first) {
    if (line.size() != cols) throw std::invalid_argument("grid picture rows differ in length");
  }
  OccupancyGrid grid;
  const int n_rows = static_cast<int>(rows_top_first.size());
  grid.geometry_ = GridGeometry(static_cast<int>(cols), n_rows, resolution_m);
  grid.width_m_ = static_cast<double>(cols) * resolution_m;
  grid.height_m_ = n_rows * resolution_m;
  grid.blocked_.assign(grid.geometry_.cell_count(), 0);
  for (int row = 0; row < n_rows; ++row) {
    const auto& line = rows_top_first[static_cast<std::size_t>(n_rows - 1 - row)];
    for (int col = 0; col < static_cast<int>(cols); ++col) {
      if (line[static_cast<std::size_t>(col)] == '#') grid.blocked_[grid.geometry_.index({col, row})] = 1;
    }
  }
  return grid;
}

}  // namespace autonomy::behavior
