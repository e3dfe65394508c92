#pragma once
// Meeting another robot outside the narrow passages (docs/traffic.md, "Meeting in the hallway"):
// where two robots fit beside each other (the office's 1.8 m hallway) but their cost-to-go
// fields send both down the middle, the one later in a total order steps aside and stands until
// the other has passed; the other plans around it (a waiting robot is a soft obstacle).
//
// Order: a robot inside a passage box or holding a passage's reservation comes first (it cannot
// step aside in a doorway and must not be held there), then the robot id. A robot gives way only
// to a robot that is moving (a fresh itinerary with a path, not standing at a holding or side
// point), so a robot it gives way to never waits for it or for anybody else: no wait-for chains.
//
// Pure logic: positions, paths and the grid arrive as arguments.
#include "common/geometry/geometry.hpp"
#include "services/behavior/core/occupancy_grid.hpp"
#include "services/behavior/core/traffic/passage.hpp"
#include "services/behavior/core/traffic/traffic_rule.hpp"

#include <optional>
#include <string>
#include <vector>

namespace autonomy::behavior::traffic {

struct GiveWaySettings {
  double look_m = 3.0;        // > 0: the stretch of both paths compared (from where each robot is)
  double clearance_m = 0.8;   // > 0: paths closer than this meet (two 0.3 m discs and the brake's gap)
  double same_way_cos = 0.5;  // headings closer than acos(this) (60 degrees) follow, not meet
  double side_search_m = 2.0; // > 0: a side point is at most this far to walk (outside passages)
  double side_clear_m = 0.9;  // > 0: distance from the other's path worth walking for (capped there)
  double side_apart_m = 1.4;  // >= 0: a side point keeps this far from every other robot (when it
                              // can), so that two robots standing aside never close the hallway
};

// Whether a robot comes first in the meeting order by where it is: inside a passage box or
// holding a passage.
bool meets_first(const geometry::Vec2& position, const Claim& claim, const std::vector<Passage>& passages);

// Whether `o`, as its itinerary says, stands rather than moves: no path, or waiting with at most
// its holding (or side) point.
bool standing(const OtherRobot& o);

// The robot this one must give way to now, if any: among the others that are fresh (itinerary no
// older than `expiry_s`), moving, earlier in the order than this robot and whose path ahead meets
// this robot's path ahead (not the same way), the nearest. `me_first`: meets_first() for this
// robot. Throws std::invalid_argument on bad settings.
std::optional<std::string> give_way_to(const std::string& my_id, const geometry::Vec2& me, bool me_first,
                                       const std::vector<geometry::Vec2>& path_ahead,
                                       const std::vector<OtherRobot>& others, const std::vector<Passage>& passages,
                                       double expiry_s, const GiveWaySettings& settings = {});

// Where to stand aside: a free cell reachable within side_search_m without crossing a passage
// box, outside every box, as far from `their_path` as side_clear_m asks; among those, the nearest
// by path; one at least side_apart_m from every robot in `robots` when there is one. nullopt when
// the robot's own cell is outside the grid or nothing qualifies.
std::optional<geometry::Vec2> side_point(const OccupancyGrid& grid, const geometry::Vec2& me,
                                         const std::vector<geometry::Vec2>& their_path,
                                         const std::vector<Passage>& passages,
                                         const std::vector<geometry::Vec2>& robots = {},
                                         const GiveWaySettings& settings = {});

}  // namespace autonomy::behavior::traffic
