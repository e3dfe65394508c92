#pragma once
// The static world as autonomy/map carries it to every controller: rectangles, polygons and
// occupancy rasters exactly as the scenario declared them, so a planner rebuilds the same
// obstacles at whatever resolution it likes. Doors are left out: they move, and robots learn
// them by observation.
#include "common/msg/simulation.hpp"
#include "simulator/core/world_spec.hpp"

namespace autonomy::sim {

msg::WorldMap map_message(const WorldSpec& spec);

}  // namespace autonomy::sim
