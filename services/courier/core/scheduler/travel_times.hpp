#pragma once
// Travel times between places from an occupancy map: one exact cost-to-go field per place
// (common/grid's compute_cost_to_go, 8-connected, no corner cutting), computed over the raster
// with the cells of doors believed closed blocked as well. travel(a, b) = field_b(cell of a) /
// speed: the shortest grid path from a to b at constant speed (no turning or door overhead).
#include "common/grid/occupancy_raster.hpp"
#include "services/courier/core/scheduler/scheduling_problem.hpp"

#include <optional>
#include <string>
#include <vector>

namespace autonomy::courier::scheduling {

struct MapPosition {
  double x_m = 0.0;  // map frame, as the raster's origin
  double y_m = 0.0;
};

// The raster cell holding a map position; nullopt outside the raster or for non-finite input.
std::optional<grid::Cell> cell_at(const grid::OccupancyRaster& raster, const MapPosition& p);

struct [[nodiscard]] TravelTimesResult {
  std::string error;  // empty when ok: "place 3 (12.5, 4.0) is on an occupied cell"
  TravelMatrix matrix;
  std::vector<grid::Cell> cells;  // the cell of each place

  bool ok() const { return error.empty(); }
};

// Places must lie on free cells of `raster`. A place whose own cell is in `blocked` (behind or in
// a closed door) is unreachable from everywhere and reaches nothing. speed_mps > 0.
TravelTimesResult travel_times_from_map(const grid::OccupancyRaster& raster,
                                        const std::vector<MapPosition>& places, double speed_mps,
                                        const std::vector<grid::Cell>& blocked = {});

}  // namespace autonomy::courier::scheduling
