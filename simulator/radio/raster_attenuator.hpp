#pragma once
// An occupancy raster (a ROS map_server map loaded into the world, common/grid) as an obstacle to
// radio: the blocked cells are walls. A signal path pays
//   loss = walls * loss_per_wall_db + inside_m * loss_per_metre_db
// where, along the straight segment a-b,
//   inside_m  is the length of the segment inside blocked cells;
//   walls     is the number of separate runs of blocked cells the segment passes through, each
//             counted once (one free -> blocked transition per wall crossed). A map draws a wall
//             as a band of blocked cells, so a band is one wall, whatever its thickness (a vector
//             building, by contrast, is two walls: its boundary is crossed going in and out).
//
// Conventions, the same as attenuator.hpp's for shapes:
// - The obstacle is the interior of the union of the blocked cells (closed squares). The boundary
//   is outside: a path that only touches a blocked cell at a corner, or runs along the outer edge
//   of a band, is not inside it. A path through the corner where two blocked cells meet
//   diagonally leaves one wall and enters another (two walls) unless the two other cells at that
//   corner are blocked too. Points within kBoundaryToleranceM of a grid line count as on it.
// - A radio standing in a blocked cell pays for the run it stands in when the path leaves it (as a
//   radio inside a building pays for the wall it passes on the way out); a path that stays inside
//   one run from end to end crosses no wall, it only pays its length.
// - Cells outside the raster are free (a map covers part of the world).
// - Rasters must be axis-aligned (origin yaw 0), as in ObstacleMap.
//
// Cost: an exact grid walk (Amanatides & Woo 1987) over the cells the segment passes, one bit
// read per cell, that jumps across 16 x 16-cell blocks with no blocked cell in one step (a summary
// built once), so a path across open ground costs about length / (16 cells) steps. Const and
// thread safe.
#include "common/geometry/geometry.hpp"
#include "common/grid/occupancy_raster.hpp"
#include "simulator/radio/attenuator.hpp"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace autonomy::sim::radio {

class RasterAttenuator {
 public:
  // Throws std::invalid_argument when raster_attenuator_problem finds something.
  RasterAttenuator(std::shared_ptr<const grid::OccupancyRaster> raster, double loss_per_wall_db,
                   double loss_per_metre_db, std::string name = {});
  // A map of walls with the parameters' wall losses (wall_loss_db, inside_loss_db_per_m).
  static RasterAttenuator obstacle(std::shared_ptr<const grid::OccupancyRaster> raster,
                                   const RadioParameters& params, std::string name = {});

  // crossings = walls crossed, stretches = runs of blocked cells met (crossings + 1 only when the
  // whole segment lies in one run), inside_m as above.
  Traversal traverse(const geometry::Vec2& a, const geometry::Vec2& b) const;

  double loss_db(const Traversal& t) const {
    return t.crossings * loss_per_wall_db_ + t.inside_m * loss_per_metre_db_;
  }

  const grid::OccupancyRaster& raster() const { return *raster_; }
  double loss_per_wall_db() const { return loss_per_wall_db_; }
  double loss_per_metre_db() const { return loss_per_metre_db_; }
  const std::string& name() const { return name_; }
  // The world-frame box the raster covers.
  geometry::Rect bounds() const;

 private:
  bool block_free(int bx, int by) const {
    return free_blocks_[static_cast<size_t>(by) * static_cast<size_t>(block_cols_) +
                        static_cast<size_t>(bx)] != 0;
  }

  std::shared_ptr<const grid::OccupancyRaster> raster_;
  double loss_per_wall_db_ = 0.0;
  double loss_per_metre_db_ = 0.0;
  std::string name_;
  int block_cols_ = 0;
  std::vector<uint8_t> free_blocks_;  // 1: no blocked cell in the block (row-major, like cells)
};

// Why a raster cannot attenuate: no raster, rotated (yaw != 0), or losses negative / not finite.
std::optional<std::string> raster_attenuator_problem(
    const std::shared_ptr<const grid::OccupancyRaster>& raster, double loss_per_wall_db,
    double loss_per_metre_db, const std::string& name);

// The reference for tests: the same Traversal from the definition, slowly. Every parameter where
// the segment crosses a grid line splits it into pieces; a piece (by its midpoint) and a split
// point are inside when every cell whose closed square holds the point is blocked.
Traversal traverse_raster_reference(const grid::OccupancyRaster& raster, const geometry::Vec2& a,
                                    const geometry::Vec2& b);

}  // namespace autonomy::sim::radio
