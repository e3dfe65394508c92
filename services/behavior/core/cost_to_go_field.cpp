#include "services/behavior/core/cost_to_go_field.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace autonomy::behavior {

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

grid::Cell to_grid(GridCell c) { return {c.col, c.row}; }

}  // namespace

CostToGoField::CostToGoField(const OccupancyGrid& grid, const geometry::Vec2& goal)
    : geometry_(grid.geometry()), goal_(goal), goal_cell_(geometry_.cell_at(goal)) {
  const grid::OccupancyRaster& raster = grid.raster();  // made once with the grid
  // Outside or blocked goals come back as a reasoned result with an all-+inf field, which is
  // exactly "no route anywhere" here.
  auto result =
      grid::compute_cost_to_go(raster, goal_cell_ ? to_grid(*goal_cell_) : grid::Cell{-1, -1});
  has_route_anywhere_ = result.ok();
  field_ = std::move(result.field);
}

CostToGoField::CostToGoField(const GridGeometry& geometry, const geometry::Vec2& goal, std::vector<float> costs)
    : geometry_(geometry), goal_(goal), goal_cell_(geometry_.cell_at(goal)) {
  if (costs.size() != geometry_.cell_count()) {
    throw std::invalid_argument("stored field has " + std::to_string(costs.size()) + " costs for " +
                                std::to_string(geometry_.cell_count()) + " cells");
  }
  const grid::Cell g = goal_cell_ ? to_grid(*goal_cell_) : grid::Cell{-1, -1};
  field_ = grid::CostField(geometry_.cols(), geometry_.rows(), geometry_.resolution_m(), g, std::move(costs));
  has_route_anywhere_ = goal_cell_ && std::isfinite(field_.cost(g));
}

float CostToGoField::cost(GridCell c) const { return field_.cost(to_grid(c)); }

bool CostToGoField::reachable(GridCell c) const { return std::isfinite(cost(c)); }

float CostToGoField::cost_at(const geometry::Vec2& p) const {
  const auto c = geometry_.cell_at(p);
  return c ? cost(*c) : kInf;
}

geometry::Vec2 CostToGoField::advice(GridCell c) const { return field_.advice(to_grid(c)); }

std::optional<GridCell> CostToGoField::nearest_reachable(const geometry::Vec2& p,
                                                         double within_m) const {
  if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !(within_m >= 0.0)) return std::nullopt;
  const double res = geometry_.resolution_m();
  // Clamp in floating point first: a far-away p must not overflow the int conversion.
  const auto clamp_index = [](double v, int last) {
    return static_cast<int>(std::clamp(std::floor(v), 0.0, static_cast<double>(last)));
  };
  if (p.x() + within_m < 0.0 || p.y() + within_m < 0.0 ||
      p.x() - within_m > geometry_.cols() * res || p.y() - within_m > geometry_.rows() * res) {
    return std::nullopt;
  }
  const int c0 = clamp_index((p.x() - within_m) / res, geometry_.cols() - 1);
  const int r0 = clamp_index((p.y() - within_m) / res, geometry_.rows() - 1);
  const int c1 = clamp_index((p.x() + within_m) / res, geometry_.cols() - 1);
  const int r1 = clamp_index((p.y() + within_m) / res, geometry_.rows() - 1);
  std::optional<GridCell> best;
  double best_d = within_m;
  for (int row = r0; row <= r1; ++row) {
    for (int col = c0; col <= c1; ++col) {
      const GridCell c{col, row};
      if (!reachable(c)) continue;
      const double d = (geometry_.centre(c) - p).norm();
      if (d <= best_d && (!best || d < best_d)) {
        best_d = d;
        best = c;
      }
    }
  }
  return best;
}

}  // namespace autonomy::behavior
