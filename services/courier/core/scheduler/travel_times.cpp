#include "services/courier/core/scheduler/travel_times.hpp"

#include "common/grid/cost_to_go.hpp"

#include <cmath>

namespace autonomy::courier::scheduling {

std::optional<grid::Cell> cell_at(const grid::OccupancyRaster& raster, const MapPosition& p) {
  if (!std::isfinite(p.x_m) || !std::isfinite(p.y_m)) return std::nullopt;
  const auto& o = raster.origin();
  const double dx = p.x_m - o.x;
  const double dy = p.y_m - o.y;
  const double u = std::cos(o.yaw) * dx + std::sin(o.yaw) * dy;
  const double v = -std::sin(o.yaw) * dx + std::cos(o.yaw) * dy;
  const double col = std::floor(u / raster.resolution_m());
  const double row = std::floor(v / raster.resolution_m());
  if (col < 0 || row < 0 || col >= raster.width() || row >= raster.height()) return std::nullopt;
  return grid::Cell{static_cast<int>(col), static_cast<int>(row)};
}

TravelTimesResult travel_times_from_map(const grid::OccupancyRaster& raster,
                                        const std::vector<MapPosition>& places, double speed_mps,
                                        const std::vector<grid::Cell>& blocked) {
  TravelTimesResult out;
  if (!(speed_mps > 0.0) || !std::isfinite(speed_mps)) {
    out.error = "speed must be finite and > 0 m/s";
    return out;
  }
  for (std::size_t i = 0; i < places.size(); ++i) {
    const auto cell = cell_at(raster, places[i]);
    const std::string where = "place " + std::to_string(i) + " (" + std::to_string(places[i].x_m) +
                              ", " + std::to_string(places[i].y_m) + ")";
    if (!cell) {
      out.error = where + " is outside the map";
      return out;
    }
    if (raster.blocked(*cell)) {
      out.error = where + " is on an occupied or unknown cell";
      return out;
    }
    out.cells.push_back(*cell);
  }
  grid::OccupancyRaster closed = raster;
  for (const grid::Cell& c : blocked)
    if (closed.contains(c)) closed.set_blocked(c, true);
  out.matrix = TravelMatrix(places.size());
  for (std::size_t b = 0; b < places.size(); ++b) {
    if (closed.blocked(out.cells[b])) continue;  // inside a closed door: row and column stay +inf
    const grid::FieldResult field = grid::compute_cost_to_go(closed, out.cells[b]);
    if (!field.ok()) {
      out.error = "place " + std::to_string(b) + ": " + field.reason;
      return out;
    }
    for (std::size_t a = 0; a < places.size(); ++a) {
      if (a == b) continue;
      const float metres = field.field.cost(out.cells[a]);
      out.matrix.set(
          a, b, metres < grid::kUnreachable ? static_cast<double>(metres) / speed_mps : kNoRoute);
    }
  }
  return out;
}

}  // namespace autonomy::courier::scheduling
