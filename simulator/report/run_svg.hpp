#pragma once
// An SVG picture of a run: the world, its obstacles (rectangles and polygons), doors (open or
// closed), attenuating areas (translucent), named places, and every robot's path with its start
// (circle) and final pose (disc of the robot's radius), with a legend. Paths can be coloured by
// connectivity: solid in the robot's colour where it was connected to at least one teammate,
// dashed and faded where it was not. Pure: returns the document as a string.
//
// Everything beyond world, paths and final_robots is optional and plain data, so the picture does
// not depend on how the world or the radio model store doors and areas.
#include "common/geometry/geometry.hpp"
#include "simulator/core/robot_status.hpp"
#include "simulator/core/world_spec.hpp"

#include <map>
#include <string>
#include <vector>

namespace autonomy::sim {

struct PictureDoor {
  geometry::Vec2 a{0.0, 0.0};
  geometry::Vec2 b{0.0, 0.0};
  bool open = true;  // at the end of the run
  std::string name;  // drawn beside the door when not empty
};

struct PictureArea {
  std::vector<geometry::Vec2> polygon;  // closed implicitly
  std::string name;
};

struct PicturePlace {
  std::string name;
  geometry::Vec2 position{0.0, 0.0};
  double radius = 0.0;  // drawn as a dotted circle when > 0
};

// A numbered marker drawn above the paths (a step of a story told beside the picture).
struct PictureMarker {
  geometry::Vec2 position{0.0, 0.0};
  std::string label;  // short: drawn inside the marker's circle
};

struct RunPicture {
  const WorldSpec* world = nullptr;
  std::map<std::string, std::vector<geometry::Vec2>> paths;  // by robot id
  std::vector<RobotStatus> final_robots;
  std::string caption;  // e.g. "demo, tick 612 (30.6 s)"

  std::vector<std::vector<geometry::Vec2>> polygon_obstacles;  // besides world->obstacles
  std::vector<PictureDoor> doors;
  std::vector<PictureArea> attenuating_areas;
  std::vector<PicturePlace> places;
  // By robot id, one flag per point of paths[id]: connected to at least one teammate there. The
  // segment ending at point k is drawn as flag k says. A robot without flags, or whose flag count
  // differs from its point count, is drawn solid as before.
  std::map<std::string, std::vector<bool>> path_connected;
  std::vector<PictureMarker> markers;
};

std::string render_run_svg(const RunPicture& picture);

}  // namespace autonomy::sim
