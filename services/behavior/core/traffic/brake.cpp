#include "services/behavior/core/traffic/brake.hpp"

#include <cmath>

namespace autonomy::behavior::traffic {

VelocityCommand brake_for_robots(const geometry::Pose2& pose, Kinematics kinematics, double radius_m,
                                 const VelocityCommand& command, const std::vector<Disc>& others, double gap_m,
                                 double pass_m) {
  // The command's velocity in the world frame.
  const geometry::Vec2 v = kinematics == Kinematics::Holonomic
                               ? geometry::Vec2(command.vx, command.vy)
                               : geometry::Vec2(command.vx * std::cos(pose.theta), command.vx * std::sin(pose.theta));
  if (v.norm() < 1e-9) return command;
  for (const Disc& o : others) {
    const geometry::Vec2 d = o.centre - pose.position();
    const double gap = d.norm() - radius_m - o.radius;
    // How close the straight line along the velocity comes to the other centre.
    const double miss = std::abs(v.x() * d.y() - v.y() * d.x()) / v.norm();
    if (gap < gap_m && v.dot(d) > 0.0 && miss < radius_m + o.radius + pass_m) {
      VelocityCommand braked;
      braked.omega = command.omega;
      return braked;
    }
  }
  return command;
}

}  // namespace autonomy::behavior::traffic
