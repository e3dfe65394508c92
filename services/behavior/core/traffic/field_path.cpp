#include "services/behavior/core/traffic/field_path.hpp"

#include <cmath>

namespace autonomy::behavior::traffic {

std::vector<geometry::Vec2> field_path(const CostToGoField& field, const geometry::Vec2& from, double length_m,
                                       double spacing_m) {
  std::vector<geometry::Vec2> out;
  const auto& g = field.geometry();
  auto cell = g.cell_at(from);
  if (!cell || !field.reachable(*cell)) return out;
  double walked = 0.0, since_point = 0.0;
  geometry::Vec2 prev = from;
  // Each step lowers the cost, so the walk ends; the bound guards a malformed stored field.
  const std::size_t max_steps = static_cast<std::size_t>(g.cols()) * static_cast<std::size_t>(g.rows());
  for (std::size_t step = 0; step < max_steps && walked < length_m; ++step) {
    if (field.goal_cell() && *cell == *field.goal_cell()) {
      out.push_back(field.goal());
      return out;
    }
    const geometry::Vec2 a = field.advice(*cell);
    if (a.norm() < 0.5) break;
    const GridCell next{cell->col + static_cast<int>(std::lround(a.x())), cell->row + static_cast<int>(std::lround(a.y()))};
    if (!field.reachable(next) || !(field.cost(next) < field.cost(*cell))) break;
    cell = next;
    const geometry::Vec2 p = g.centre(*cell);
    walked += (p - prev).norm();
    since_point += (p - prev).norm();
    prev = p;
    if (since_point >= spacing_m) {
      out.push_back(p);
      since_point = 0.0;
    }
  }
  if (out.empty() || (out.back() - prev).norm() > 1e-9) out.push_back(prev);
  return out;
}

}  // namespace autonomy::behavior::traffic
