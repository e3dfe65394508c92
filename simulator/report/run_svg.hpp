#pragma once
// An SVG picture of a run: the world, its obstacles, and every robot's path with its start
// (circle) and final pose (disc of the robot's radius). Pure: returns the document as a string.
#include "common/geometry/geometry.hpp"
#include "simulator/core/robot_status.hpp"
#include "simulator/core/world_spec.hpp"

#include <map>
#include <string>
#include <vector>

namespace autonomy::sim {

struct RunPicture {
  const WorldSpec* world = nullptr;
  std::map<std::string, std::vector<geometry::Vec2>> paths;  // by robot id
  std::vector<RobotStatus> final_robots;
  std::string caption;  // e.g. "demo, tick 612 (30.6 s)"
};

std::string render_run_svg(const RunPicture& picture);

}  // namespace autonomy::sim
