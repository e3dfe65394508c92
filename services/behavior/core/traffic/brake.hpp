#pragma once
// The last guard of fleet traffic (docs/traffic.md): a command that would drive this robot
// towards another robot closer than `gap_m` between their discs loses its translation (a
// unicycle may still turn in place). The passage rule and the holding points keep robots apart
// where it matters; this keeps a robot from running into one it follows, or one standing where it
// waits, whatever the planner chose. Driving past a robot is not driving into it: the command
// keeps its translation when the straight line it drives passes the other disc with more than
// `pass_m` between them (a robot overtaking or meeting one that stands aside, docs/traffic.md).
#include "common/geometry/geometry.hpp"
#include "services/behavior/core/velocity_command.hpp"

#include <vector>

namespace autonomy::behavior::traffic {

struct Disc {
  geometry::Vec2 centre = geometry::Vec2::Zero();
  double radius = 0.0;
};

VelocityCommand brake_for_robots(const geometry::Pose2& pose, Kinematics kinematics, double radius_m,
                                 const VelocityCommand& command, const std::vector<Disc>& others, double gap_m = 0.2,
                                 double pass_m = 0.05);

}  // namespace autonomy::behavior::traffic
