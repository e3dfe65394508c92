#include "services/behavior/core/traffic/holding_point.hpp"

#include "services/behavior/core/cost_to_go_field.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace autonomy::behavior::traffic {

std::optional<geometry::Vec2> holding_point(const OccupancyGrid& grid, const geometry::Vec2& me,
                                            const Passage& passage, const std::vector<Passage>& all,
                                            const std::vector<geometry::Vec2>& keep_clear,
                                            const HoldingSettings& settings) {
  const CostToGoField from_me(grid, me);  // path distance from the robot to each cell
  if (!from_me.has_route_anywhere()) return std::nullopt;
  const auto& g = from_me.geometry();
  const double res = g.resolution_m();
  const double r = settings.search_m;
  const int c0 = std::max(0, static_cast<int>(std::floor((me.x() - r) / res)));
  const int r0 = std::max(0, static_cast<int>(std::floor((me.y() - r) / res)));
  const int c1 = std::min(g.cols() - 1, static_cast<int>(std::floor((me.x() + r) / res)));
  const int r1 = std::min(g.rows() - 1, static_cast<int>(std::floor((me.y() + r) / res)));
  std::optional<geometry::Vec2> best[2];  // [0]: clear of the path; [1]: any
  double best_score[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  for (int row = r0; row <= r1; ++row) {
    for (int col = c0; col <= c1; ++col) {
      const GridCell cell{col, row};
      const float cost = from_me.cost(cell);
      if (!std::isfinite(cost) || cost > r) continue;
      const geometry::Vec2 p = g.centre(cell);
      if (std::any_of(all.begin(), all.end(), [&](const Passage& q) { return q.distance(p) <= res; })) continue;
      const double gap = std::min(passage.distance(p), settings.prefer_gap_m);
      // Each metre nearer the preferred gap is worth two metres of walking.
      const double score = static_cast<double>(cost) - 2.0 * gap;
      const bool clear = std::none_of(keep_clear.begin(), keep_clear.end(), [&](const geometry::Vec2& k) {
        return (k - p).norm() < settings.keep_clear_m;
      });
      for (int k = clear ? 0 : 1; k < 2; ++k) {
        if (score < best_score[k]) {
          best_score[k] = score;
          best[k] = p;
        }
      }
    }
  }
  return best[0] ? best[0] : best[1];
}

}  // namespace autonomy::behavior::traffic
