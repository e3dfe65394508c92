#pragma once
// The autonomy/map sample as the behavior's planning world (WorldMap): obstacles, polygons,
// rasters and doorways (doors open; DoorKnowledge closes the ones the robot saw closed).
#include "common/msg/simulation.hpp"
#include "services/behavior/core/world_map.hpp"

namespace autonomy::behavior {

// Shapes another process got wrong (a crossing polygon, a raster whose cells do not add up) are
// left out with a warning rather than stopping the robot.
WorldMap world_of(const msg::WorldMap& m);

}  // namespace autonomy::behavior
