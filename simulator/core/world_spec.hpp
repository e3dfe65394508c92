#pragma once
// Everything the World needs to start: the room, its obstacles, its doors and which robots may
// exist.
// Built at the edge (scenario files) and checked there; World trusts only what it re-checks itself.
#include "common/geometry/geometry.hpp"
#include "simulator/core/door.hpp"
#include "simulator/core/obstacle_map.hpp"
#include "simulator/core/robot_spec.hpp"
#include "simulator/core/shapes.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace autonomy::sim {

struct WorldSpec {
  std::string name;
  double width = 0.0;   // m, the world spans [0, width] x [0, height]
  double height = 0.0;
  std::vector<geometry::Rect> obstacles;
  std::vector<Polygon> polygons;     // walls, buildings: simple polygons
  std::vector<RasterLayer> rasters;  // occupancy maps (shared, read-only: copies are cheap)
  std::vector<DoorSpec> doors;       // ids unique
  std::vector<RobotSpec> robots_at_start;  // spawned when the World is built
  // Configured but absent until a controller attaches and asks to spawn them; their start pose
  // and limits are used then.
  std::vector<RobotSpec> known_robots;
  // Body and limits for a robot attached under an id that is not configured (id and start unused).
  RobotSpec attach_defaults;
  // A held command expires after this much simulated time, so a dead controller stops its robot.
  double command_timeout_s = 0.5;
  // Seeds every random process of the world (door schedules, sensor noise), each in its own
  // stream named after the door or robot (random.hpp).
  std::uint64_t seed = 0;
};

}  // namespace autonomy::sim
