#pragma once
// The last guard of fleet traffic (docs/traffic.md): a command that would drive this robot
// towards another robot closer than `gap_m` between their discs loses its translation (a
// unicycle may still turn in place). The passage rule and the holding points keep robots apart
// where it matters; this keeps a robot from running into one it follows, or one standing where it
// waits, whatever the planner chose. Two robots braking for each other head-on stand still: the
// goal's stall rule then ends it with a reason (docs/traffic.md, "What is not solved").
#include "common/geometry/geometry.hpp"
#include "services/behavior/core/velocity_command.hpp"

#include <vector>

namespace autonomy::behavior::traffic {

struct Disc {
  geometry::Vec2 centre = geometry::Vec2::Zero();
  double radius = 0.0;
};

VelocityCommand brake_for_robots(const geometry::Pose2& pose, Kinematics kinematics, double radius_m,
                                 const VelocityCommand& command, const std::vector<Disc>& others, double gap_m = 0.2);

}  // namespace autonomy::behavior::traffic
