#include "services/behavior/core/cost_to_go_field.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <utility>

namespace autonomy::behavior {

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

struct Move {
  int dc;
  int dr;
  bool diagonal;
};

// Orthogonal moves first: advice breaks ties towards them, and the order is part of the contract.
constexpr Move kMoves[8] = {{1, 0, false},  {0, 1, false},  {-1, 0, false}, {0, -1, false},
                            {1, 1, true},   {-1, 1, true},  {-1, -1, true}, {1, -1, true}};

// A diagonal move needs both orthogonal cells beside it free; `free` answers for a cell.
template <typename FreeFn>
bool move_allowed(GridCell from, const Move& m, const FreeFn& free) {
  const GridCell to{from.col + m.dc, from.row + m.dr};
  if (!free(to)) return false;
  if (!m.diagonal) return true;
  return free(GridCell{from.col + m.dc, from.row}) && free(GridCell{from.col, from.row + m.dr});
}

}  // namespace

CostToGoField::CostToGoField(const OccupancyGrid& grid, const geometry::Vec2& goal)
    : geometry_(grid.geometry()), goal_(goal), goal_cell_(geometry_.cell_at(goal)) {
  costs_.assign(geometry_.cell_count(), kInf);
  if (!goal_cell_ || grid.blocked(*goal_cell_)) return;
  has_route_anywhere_ = true;

  const float orthogonal = static_cast<float>(geometry_.resolution_m());
  const float diagonal = static_cast<float>(geometry_.resolution_m() * std::sqrt(2.0));
  const auto free = [&grid](GridCell c) { return !grid.blocked(c); };

  // The graph is undirected (moves and their costs are symmetric), so searching outwards from the
  // goal gives every cell its cost *to* the goal.
  using Entry = std::pair<float, std::size_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
  const auto start = geometry_.index(*goal_cell_);
  costs_[start] = 0.0f;
  open.push({0.0f, start});
  while (!open.empty()) {
    const auto [cost, index] = open.top();
    open.pop();
    if (cost > costs_[index]) continue;  // stale entry: the cell was settled cheaper already
    const GridCell from = geometry_.cell(index);
    for (const auto& m : kMoves) {
      if (!move_allowed(from, m, free)) continue;
      const auto to = geometry_.index({from.col + m.dc, from.row + m.dr});
      const float candidate = cost + (m.diagonal ? diagonal : orthogonal);
      if (candidate < costs_[to]) {
        costs_[to] = candidate;
        open.push({candidate, to});
      }
    }
  }
}

float CostToGoField::cost(GridCell c) const {
  return geometry_.contains(c) ? costs_[geometry_.index(c)] : kInf;
}

bool CostToGoField::reachable(GridCell c) const { return std::isfinite(cost(c)); }

float CostToGoField::cost_at(const geometry::Vec2& p) const {
  const auto c = geometry_.cell_at(p);
  return c ? cost(*c) : kInf;
}

geometry::Vec2 CostToGoField::advice(GridCell c) const {
  const float here = cost(c);
  if (!std::isfinite(here) || here == 0.0f) return geometry::Vec2::Zero();
  // A reachable cell's free neighbours are reachable too, so "finite" doubles as "free" here.
  const auto free = [this](GridCell n) { return reachable(n); };
  const Move* best = nullptr;
  float best_cost = here;
  for (const auto& m : kMoves) {
    if (!move_allowed(c, m, free)) continue;
    const float v = cost({c.col + m.dc, c.row + m.dr});
    if (v < best_cost) {
      best_cost = v;
      best = &m;
    }
  }
  if (best == nullptr) return geometry::Vec2::Zero();  // cannot happen in a settled field
  return geometry::Vec2(best->dc, best->dr).normalized();
}

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
