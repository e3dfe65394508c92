#pragma once
// The JSON frames the viewer pushes to its pages (docs/viewer.md, "Frames"):
//   {"type":"map", ...}   the static world: size, obstacles, rooms (named polygons), occupancy
//                         rasters (run-length coded), doorways; sent when it changes and to
//                         every page that connects;
//   {"type":"state", ...} everything that moves: robots with their tails, goals and itineraries,
//                         doors (angle, closed, the leaf as a segment), radio links, courier jobs
//                         with their state history. Sent at most at the node's rate;
//   {"type":"execution", ...} each executive's plans against what it executed
//                         (execution_trace.hpp): the plans it ran most recently with their
//                         tokens' windows, the executed tokens of those plans, and marks
//                         (violations, faults, re-plans). Times in simulated seconds.
// Coordinates are metres in the world frame, rounded to millimetres to keep frames small.
#include "services/viewer/core/execution_trace.hpp"
#include "services/viewer/core/world_view.hpp"

#include <nlohmann/json.hpp>

namespace autonomy::viewer {

nlohmann::json map_frame(const WorldView& view);
nlohmann::json state_frame(const WorldView& view, uint64_t sequence);
// The last `plans` plans each executive ran (the re-plan before the current one shows with it).
nlohmann::json execution_frame(const ExecutionTraces& traces, std::size_t plans = 2);

// A door's leaf from its hinge to its free end: the map's doorway turned by `angle` (rad, >= 0)
// towards the side it opens to (the sign of open_angle; counter-clockwise when not said).
struct LeafSegment {
  double hinge_x = 0.0, hinge_y = 0.0, tip_x = 0.0, tip_y = 0.0;
};
LeafSegment door_leaf(const msg::MapDoor& door, double angle);

// Run lengths of a raster's cells in row-major order, alternating free and blocked, starting
// with free (so a first run may be 0).
std::vector<uint32_t> raster_runs(const msg::MapRaster& raster);

}  // namespace autonomy::viewer
