#pragma once
// The static world as the behavior controller receives it (autonomy/map): a rectangle
// [0, width] x [0, height] with obstacles of three kinds, as the scenario declared them:
// axis-aligned rectangles, simple polygons (buildings, walls) and occupancy rasters (ROS maps;
// blocked cells are obstacles, cells outside a raster are free), and where the doors are. A plain value; the DDS node
// converts the IDL sample into it at the edge. Rasters are shared: copies are cheap.
#include "common/geometry/geometry.hpp"
#include "common/geometry/shapes.hpp"
#include "common/grid/occupancy_raster.hpp"

#include <memory>
#include <string>
#include <vector>

namespace autonomy::behavior {

// A doorway: `width` m centred at `centre` along `heading` (rad, hinge to latch); its leaf, when
// open, turned `open_angle` (rad, signed, + counter-clockwise; 0: the map does not say) about the
// hinge. Not an obstacle by itself: what blocks depends on what the robot knows of the door
// (door_knowledge.hpp: a closed door's doorway, an open door's leaf).
struct Doorway {
  std::string id;
  geometry::Vec2 centre;
  double width_m = 0.0;
  double heading = 0.0;
  double open_angle = 0.0;
};

struct WorldMap {
  double width_m = 0.0;
  double height_m = 0.0;
  std::vector<geometry::Rect> obstacles;
  std::vector<geometry::Polygon> polygons;
  std::vector<std::shared_ptr<const grid::OccupancyRaster>> rasters;  // origin yaw 0
  std::vector<Doorway> doors;
};

}  // namespace autonomy::behavior
