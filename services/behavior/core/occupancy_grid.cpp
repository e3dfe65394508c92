#include "services/behavior/core/occupancy_grid.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace autonomy::behavior {

namespace {

bool positive_finite_size(double v) { return std::isfinite(v) && v > 0.0; }

// Number of cells covering `length`; the tolerance keeps 10 / 0.1 from becoming 101 cells.
int cells_covering(double length_m, double resolution_m) {
  return static_cast<int>(std::ceil(length_m / resolution_m - 1e-9));
}

}  // namespace

OccupancyGrid::OccupancyGrid(const WorldMap& world, double resolution_m, double inflation_radius_m) {
  if (!positive_finite_size(world.width_m) || !positive_finite_size(world.height_m)) {
    throw std::invalid_argument("world width and height must be positive and finite");
  }
  if (!positive_finite_size(resolution_m)) {
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
  for (const auto& p : world.polygons) {
    if (const auto problem = geometry::polygon_problem(p.vertices)) {
      throw std::invalid_argument("polygon '" + p.name + "': " + *problem);
    }
  }
  for (const auto& r : world.rasters) {
    if (!r || !positive_finite_size(r->resolution_m()) || r->origin().yaw != 0.0 || !std::isfinite(r->origin().x) ||
        !std::isfinite(r->origin().y)) {
      throw std::invalid_argument("occupancy rasters must exist, have a positive resolution and no rotation");
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
    block_cells_near(o.inflated(r), [&](const geometry::Vec2& c) { return geometry::distance(o, c) <= r; });
  }
  // A polygon blocks the cells whose centre is inside it or within r of one of its edges.
  for (const auto& p : world.polygons) {
    const auto& v = p.vertices;
    block_cells_near(p.bounds().inflated(r), [&](const geometry::Vec2& c) {
      if (geometry::polygon_contains(v, c)) return true;
      for (std::size_t i = 0; i < v.size(); ++i) {
        if (geometry::segment_distance(c, v[i], v[(i + 1) % v.size()]) <= r) return true;
      }
      return false;
    });
  }
  // A raster's blocked cells are squares. Inside a block of them only the cells under each square
  // need marking; only squares on the block's border (a free or outside 4-neighbour) can be the
  // nearest obstacle of a cell outside, so only they are grown by r.
  for (const auto& raster : world.rasters) {
    const grid::OccupancyRaster& m = *raster;
    const double res = m.resolution_m();
    const auto free_at = [&](int col, int row) { return !m.contains({col, row}) || !m.blocked({col, row}); };
    for (int row = 0; row < m.height(); ++row) {
      for (int col = 0; col < m.width(); ++col) {
        if (!m.blocked({col, row})) continue;
        const geometry::Rect square{m.origin().x + col * res, m.origin().y + row * res,
                                    m.origin().x + (col + 1) * res, m.origin().y + (row + 1) * res};
        const bool border = free_at(col - 1, row) || free_at(col + 1, row) || free_at(col, row - 1) ||
                            free_at(col, row + 1);
        const double grow = border ? r : 0.0;
        block_cells_near(square.inflated(grow),
                         [&](const geometry::Vec2& c) { return geometry::distance(square, c) <= grow; });
      }
    }
  }
  make_raster();
}

void OccupancyGrid::make_raster() {
  auto raster = std::make_shared<grid::OccupancyRaster>(geometry_.cols(), geometry_.rows(), geometry_.resolution_m());
  for (int row = 0; row < geometry_.rows(); ++row) {
    const std::uint8_t* cells = blocked_.data() + geometry_.index({0, row});
    for (int col = 0; col < geometry_.cols(); ++col)
      if (cells[col] != 0) raster->set_blocked({col, row}, true);
  }
  raster_ = std::move(raster);
}

OccupancyGrid OccupancyGrid::with_areas(const std::vector<geometry::Rect>& areas) const {
  OccupancyGrid out = *this;
  const double r = inflation_radius_m_;
  for (const auto& o : areas) {
    if (!o.valid() || !std::isfinite(o.min_x) || !std::isfinite(o.min_y) || !std::isfinite(o.max_x) ||
        !std::isfinite(o.max_y)) {
      throw std::invalid_argument("obstacle rectangles must be finite with min < max");
    }
    out.block_cells_near(o.inflated(r), [&](const geometry::Vec2& c) { return geometry::distance(o, c) <= r; });
  }
  out.make_raster();
  return out;
}

template <typename Blocks>
void OccupancyGrid::block_cells_near(const geometry::Rect& box, Blocks&& blocks) {
  const double res = geometry_.resolution_m();
  const int c0 = std::max(0, static_cast<int>(std::floor(box.min_x / res)));
  const int r0 = std::max(0, static_cast<int>(std::floor(box.min_y / res)));
  const int c1 = std::min(geometry_.cols() - 1, static_cast<int>(std::floor(box.max_x / res)));
  const int r1 = std::min(geometry_.rows() - 1, static_cast<int>(std::floor(box.max_y / res)));
  for (int row = r0; row <= r1; ++row) {
    for (int col = c0; col <= c1; ++col) {
      auto& cell = blocked_[geometry_.index({col, row})];
      if (cell == 0 && blocks(geometry_.centre({col, row}))) cell = 1;
    }
  }
}

OccupancyGrid OccupancyGrid::from_picture(const std::vector<std::string>& rows_top_first,
                                          double resolution_m) {
  if (rows_top_first.empty() || rows_top_first.front().empty()) {
    throw std::invalid_argument("a grid picture needs at least one cell");
  }
  if (!positive_finite_size(resolution_m)) {
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
  grid.make_raster();
  return grid;
}

}  // namespace autonomy::behavior
