#pragma once
// Which cells a robot's centre may occupy. The world's obstacles (rectangles, polygons, raster
// cells) are grown by the inflation radius
// (robot radius plus a safety margin), so that the robot can be planned as a point: a cell is
// blocked when its centre lies within that distance of an obstacle or of the world's border.
//
// Only cell centres are tested, so a point inside a free cell can be up to resolution * sqrt(2)/2
// closer to an obstacle than the inflation radius. Keep margin >= 0.71 * resolution to guarantee
// clearance for a robot that stays in free cells.
#include "common/geometry/geometry.hpp"
#include "common/grid/occupancy_raster.hpp"
#include "services/behavior/core/grid_geometry.hpp"
#include "services/behavior/core/world_map.hpp"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace autonomy::behavior {

class OccupancyGrid {
 public:
  // Throws std::invalid_argument on a malformed world or parameters (non-positive or non-finite
  // sizes, invalid rectangles, more than kMaxCells cells). The node validates configuration and maps
  // before they get here; the throw keeps a bad value from silently producing an empty grid.
  OccupancyGrid(const WorldMap& world, double resolution_m, double inflation_radius_m);

  // A grid drawn as text, first string = top row (highest y); '#' is blocked, anything else free.
  // No inflation: what is drawn is what is blocked. For tests and hand-made examples.
  static OccupancyGrid from_picture(const std::vector<std::string>& rows_top_first,
                                    double resolution_m);

  static constexpr std::size_t kMaxCells = 64u * 1024u * 1024u;

  // This grid with `areas` blocked as well, grown by the same inflation radius: cell for cell the
  // grid of the world with the areas added to its obstacles, without redoing the world's polygons
  // and rasters (a constraint layer on top of the obstacles plan). Throws std::invalid_argument on
  // an invalid rectangle.
  [[nodiscard]] OccupancyGrid with_areas(const std::vector<geometry::Rect>& areas) const;

  const GridGeometry& geometry() const { return geometry_; }
  double width_m() const { return width_m_; }
  double height_m() const { return height_m_; }
  double inflation_radius_m() const { return inflation_radius_m_; }

  // Cells outside the grid count as blocked.
  bool blocked(GridCell c) const { return !geometry_.contains(c) || blocked_[geometry_.index(c)] != 0; }

  // The same cells as a planning raster (one bit per cell), made once with the grid and shared by
  // its copies: every cost-to-go field on this grid searches it (converting the grid per field was
  // 12 of the 30 ms median field on the 6.25 M-cell recon grid: path_bench, docs/fields.md).
  const grid::OccupancyRaster& raster() const { return *raster_; }

  // Inside [0, width] x [0, height] (borders included).
  bool inside_world(const geometry::Vec2& p) const {
    return p.x() >= 0.0 && p.y() >= 0.0 && p.x() <= width_m_ && p.y() <= height_m_;
  }

 private:
  OccupancyGrid() = default;
  // Marks the cells under `box` whose centre `blocks(centre)` says is too close to an obstacle.
  template <typename Blocks>
  void block_cells_near(const geometry::Rect& box, Blocks&& blocks);

  GridGeometry geometry_;
  double width_m_ = 0.0;
  double height_m_ = 0.0;
  double inflation_radius_m_ = 0.0;
  // Makes raster_ from blocked_: the last step of every way a grid is made.
  void make_raster();

  std::vector<std::uint8_t> blocked_;  // one byte per cell: vector<bool> would cost a shift per test
  std::shared_ptr<const grid::OccupancyRaster> raster_;  // never null once made
};

}  // namespace autonomy::behavior
