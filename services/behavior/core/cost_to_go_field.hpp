#pragma once
// The "internalized plan" of the robot-teams paper: for every free cell, the cost of the cheapest
// 8-connected path to the goal cell. A robot anywhere on the map reads which way is downhill
// instead of carrying a path, so it can be pushed off course (by other schemas, by people) and
// still know where to go.
//
// Moves: orthogonal steps cost one resolution, diagonal steps sqrt(2) resolutions. A diagonal step
// is allowed only when both orthogonal cells beside it are free, so that paths never clip the
// corner of an inflated obstacle. Unreachable and blocked cells hold +infinity.
//
// The search is common/grid's exact bucket-queue field (cost_to_go.hpp): bit-for-bit the costs of
// a textbook float Dijkstra over this graph, several times faster, 5 bytes per cell while it runs.
// This class adapts it to the behavior grid (world coordinates, GridCell).
#include "common/geometry/geometry.hpp"
#include "common/grid/cost_to_go.hpp"
#include "services/behavior/core/grid_geometry.hpp"
#include "services/behavior/core/occupancy_grid.hpp"

#include <optional>
#include <vector>

namespace autonomy::behavior {

class CostToGoField {
 public:
  // Computes the field towards `goal` (world coordinates). A goal outside the grid or in a blocked
  // cell yields a field that is +infinity everywhere (has_route_anywhere() == false).
  CostToGoField(const OccupancyGrid& grid, const geometry::Vec2& goal);
  // A field computed before (a plan resource file): `costs` row-major over `geometry`, +inf where
  // unreachable. Throws std::invalid_argument when the sizes differ.
  CostToGoField(const GridGeometry& geometry, const geometry::Vec2& goal, std::vector<float> costs);

  const GridGeometry& geometry() const { return geometry_; }
  const geometry::Vec2& goal() const { return goal_; }
  // The cell the search started from; nullopt when the goal lies outside the grid.
  const std::optional<GridCell>& goal_cell() const { return goal_cell_; }
  // False when the goal cell is blocked or outside: no start anywhere can reach it.
  bool has_route_anywhere() const { return has_route_anywhere_; }

  // Metres along the cheapest grid path to the goal cell; +inf outside the grid or unreachable.
  float cost(GridCell c) const;
  bool reachable(GridCell c) const;
  // Cost of the cell holding p (+inf outside the grid).
  float cost_at(const geometry::Vec2& p) const;

  // Unit vector from c towards its cheapest reachable neighbour (moves as in the search); zero at
  // the goal cell and where c is unreachable. Ties go to the first neighbour in the fixed order
  // E, N, W, S, NE, NW, SW, SE, so advice is deterministic.
  geometry::Vec2 advice(GridCell c) const;

  // The reachable cell whose centre is closest to p, within `within_m`; nullopt if none. Used to
  // find a way back when the robot's centre has drifted into the inflation margin.
  [[nodiscard]] std::optional<GridCell> nearest_reachable(const geometry::Vec2& p,
                                                          double within_m) const;

  // Row-major costs, index = row * cols + col; for tests, benchmarks and plots.
  const std::vector<float>& costs() const { return field_.costs(); }

 private:
  GridGeometry geometry_;
  geometry::Vec2 goal_;
  std::optional<GridCell> goal_cell_;
  bool has_route_anywhere_ = false;
  grid::CostField field_;  // same cells, same row-major layout as geometry_
};

}  // namespace autonomy::behavior
