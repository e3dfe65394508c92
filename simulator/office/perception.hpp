#pragma once
// What one robot perceives of the office, as opposed to the ground truth in OfficeState: the
// objects lying at places it can see, the people it can see at their desks, and what it carries
// itself. A place is seen when its position is within range_m of the robot and line_of_sight
// (the world's visibility, through doors and around walls) says so. The percept is a copy taken
// at one time; nothing in it changes when the office does.
#include "common/geometry/geometry.hpp"
#include "simulator/office/office_state.hpp"

#include <functional>
#include <string>
#include <vector>

namespace autonomy::sim::office {

using LineOfSight = std::function<bool(const geometry::Vec2& from, const geometry::Vec2& to)>;

struct PerceivedObject {
  std::string id;
  std::string kind;
  std::string colour;
  std::string place;  // where it was seen lying
};

struct PerceivedPerson {
  std::string name;
  std::string place;
};

struct OfficePercept {
  double time_s = 0.0;
  std::vector<std::string> seen_places;   // in declaration order
  std::vector<PerceivedObject> objects;   // by place order, then object order
  std::vector<PerceivedPerson> people;    // by place order, then person order
  std::vector<std::string> carried;       // object ids the robot carries, sorted
};

// An empty line_of_sight means nothing blocks sight.
OfficePercept perceive(const OfficeState& office, const std::string& robot_id,
                       const geometry::Vec2& robot_position, double range_m, double now_s,
                       const LineOfSight& line_of_sight);

}  // namespace autonomy::sim::office
