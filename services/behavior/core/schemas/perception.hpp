#pragma once
// What a motor schema may look at during one control step: a plain value the behavior node fills
// from its DDS samples (robot state, simulated range readings, radio links) and hands inward.
// Nothing here is read from a clock or a socket; the node decides what "now" is.
//
// Frames: positions, the goal and velocity are in the world frame (metres, x right, y up).
// Range rays are in the robot's body frame: angle_rad is measured counter-clockwise from the
// robot's heading (pose.theta), so a holonomic robot still needs a meaningful theta.
#include "common/geometry/geometry.hpp"
#include "services/behavior/core/velocity_command.hpp"

#include <optional>
#include <string>
#include <vector>

namespace autonomy::behavior {

// One beam of a range sensor. A beam that saw nothing reports range_m >= max_range_m.
struct RangeRay {
  double angle_rad = 0.0;  // body frame, counter-clockwise from the heading
  double range_m = 0.0;
  double max_range_m = 0.0;

  bool hit() const { return range_m < max_range_m; }
};

// A teammate as this robot knows it. in_contact is the node's judgement of the radio link
// (for instance: a message from that teammate arrived within the link's freshness window);
// position is the last one heard, absent when never heard.
struct TeammateState {
  std::string id;
  std::optional<geometry::Vec2> position;
  bool in_contact = false;
};

struct Perception {
  double time_s = 0.0;  // the caller's clock (simulated or wall); only differences matter
  geometry::Pose2 pose;
  geometry::Vec2 velocity = geometry::Vec2::Zero();  // world frame, m/s
  Kinematics kinematics = Kinematics::Holonomic;
  MotionLimits limits;
  std::vector<RangeRay> rays;
  std::optional<geometry::Vec2> goal;  // what move-to-goal attracts to; the mission sets it per state
  std::vector<TeammateState> teammates;

  // The teammate with this id, or nullptr.
  const TeammateState* teammate(const std::string& id) const {
    for (const TeammateState& t : teammates) {
      if (t.id == id) return &t;
    }
    return nullptr;
  }
};

}  // namespace autonomy::behavior
