#pragma once
// Generated occupancy maps that look like the maps robots really get, for tests and benchmarks of
// the cost-to-goal field: building floors (rooms, 1-3 cell walls with doors, long corridors),
// SLAM-like scans of such floors (rotated so walls are staircases, ragged wall edges, speckle,
// unknown space outside and in unscanned patches), mazes, small random clutter, large blocks, and
// a small mapped arena in a large unknown grid (where only a few percent of the cells are free).
// Deterministic: the same (class, size, seed) gives the same map on every platform
// (std::mt19937_64 output and integer arithmetic only, plus one rotation evaluated in double).
//
// Goal placements pick a free cell of the largest connected region, so that a field from it
// covers most of the map: the centre, near a corner, or in a narrow passage (a door, a gap
// between obstacles, a maze corridor) near the centre.
#include "common/grid/occupancy_raster.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace autonomy::grid {

enum class MapClass {
  kClutter,   // 15 % of the cells under random rectangles with sides 2..10 cells
  kBlocks,    // 15 % under rectangles up to min(w, h) / 25 a side (random_rectangles)
  kBuilding,  // rooms, thin walls with doors, corridors, some furniture
  kSlam,      // a building floor as a SLAM map shows it
  kMaze,      // a maze with 6-cell corridors and 2-cell walls, a few loops
  kArena,     // a small mapped arena (4-5 % of the cells) inside a large unknown grid
};

inline constexpr MapClass kAllMapClasses[] = {MapClass::kClutter,  MapClass::kBlocks,
                                              MapClass::kBuilding, MapClass::kSlam,
                                              MapClass::kMaze,     MapClass::kArena};

const char* to_string(MapClass c);
std::optional<MapClass> map_class_from_string(const std::string& name);

// Resolution only scales the step costs; the geometry is in cells.
OccupancyRaster make_map(MapClass c, int width, int height, std::uint64_t seed,
                         double resolution_m = 0.05);

enum class GoalPlacement { kCentre, kCorner, kNarrow };

inline constexpr GoalPlacement kAllGoalPlacements[] = {
    GoalPlacement::kCentre, GoalPlacement::kCorner, GoalPlacement::kNarrow};

const char* to_string(GoalPlacement g);
std::optional<GoalPlacement> goal_placement_from_string(const std::string& name);

// A free cell of the largest 4-connected free region (8-connected moves without corner cutting
// connect exactly the same cells) placed as asked; nullopt when the map has no free cell. kNarrow
// falls back to the centre placement when no cell qualifies.
std::optional<Cell> place_goal(const OccupancyRaster& raster, GoalPlacement g);

}  // namespace autonomy::grid
