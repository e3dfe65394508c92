#pragma once
// Where a robot waits for a passage it may not enter yet (docs/traffic.md): a free cell it can
// reach, outside every passage box, as far from the passage as `prefer_gap_m` asks and clear of
// the path of the robot it waits for, so that the robot coming out does not find it in its way.
// Among the cells that qualify, the one nearest by path wins (a waiting robot does not wander).
#include "common/geometry/geometry.hpp"
#include "services/behavior/core/occupancy_grid.hpp"
#include "services/behavior/core/traffic/passage.hpp"

#include <optional>
#include <vector>

namespace autonomy::behavior::traffic {

struct HoldingSettings {
  double search_m = 4.0;       // > 0: candidates within this path distance of the robot
  double prefer_gap_m = 1.5;   // > 0: distance from the passage worth walking for (capped there)
  double keep_clear_m = 0.9;   // >= 0: centre distance to keep from the other robot's path
                               // (two 0.3 m discs and more than the brake's 0.2 m gap)
};

// nullopt when the robot's own cell has no route (it sits in an obstacle's margin) or no cell
// qualifies; `keep_clear` are the points of the path to stay off (relaxed when nothing else fits).
std::optional<geometry::Vec2> holding_point(const OccupancyGrid& grid, const geometry::Vec2& me,
                                            const Passage& passage, const std::vector<Passage>& all,
                                            const std::vector<geometry::Vec2>& keep_clear,
                                            const HoldingSettings& settings = {});

}  // namespace autonomy::behavior::traffic
