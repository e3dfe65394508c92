#pragma once
// Passages too narrow for two robots, derived from the map (docs/traffic.md): a doorway whose
// opening is narrower than two robot diameters plus a margin holds one robot at a time, so robots
// reserve it before they drive into it. A passage is a box around the opening: along the opening
// its half width plus one robot radius, across it the wall's half thickness plus one robot
// diameter on either side, so that a robot whose centre is outside the box does not stand in the
// way of one driving through.
#include "common/geometry/geometry.hpp"
#include "services/behavior/core/world_map.hpp"

#include <string>
#include <vector>

namespace autonomy::behavior::traffic {

struct Passage {
  std::string id;      // the doorway's id
  std::string name;    // for people: "doorway A-114"
  geometry::Vec2 centre = geometry::Vec2::Zero();
  double heading = 0.0;     // rad, direction along the opening
  double half_along = 0.0;  // m, half the box's extent along the opening
  double half_across = 0.0; // m, half its extent across the opening (the way robots drive through)

  // The point's distance from the box (0 inside it).
  double distance(const geometry::Vec2& p) const;
  bool contains(const geometry::Vec2& p) const { return distance(p) <= 0.0; }
};

struct PassageSettings {
  double robot_radius_m = 0.3;  // > 0: the fleet's largest footprint
  double margin_m = 0.4;        // >= 0: room two robots need beside each other beyond their discs
  double wall_half_thickness_m = 0.1;  // >= 0: how far a doorway reaches either side of its line
};

// The map's doorways narrower than 4 * robot_radius_m + margin_m, sorted by id. Throws
// std::invalid_argument on non-finite or out-of-range settings.
std::vector<Passage> narrow_passages(const WorldMap& map, const PassageSettings& settings);

}  // namespace autonomy::behavior::traffic
