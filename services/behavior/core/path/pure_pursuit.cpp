#include "services/behavior/core/path/pure_pursuit.hpp"

#include <algorithm>
#include <cmath>

namespace autonomy::behavior {

PursuitStep pure_pursuit(const std::vector<geometry::Pose2>& path, std::size_t progress,
                         const geometry::Pose2& robot, Kinematics kinematics,
                         const MotionLimits& limits, const PursuitSettings& settings) {
  PursuitStep step;
  if (path.empty()) {
    step.arrived = true;
    return step;
  }
  const geometry::Vec2 here = robot.position();
  // Closest pose from the previous progress on, within the window: never jumps back along a path
  // that passes near itself.
  std::size_t closest = std::min(progress, path.size() - 1);
  const std::size_t last_searched = std::min(path.size() - 1, closest + settings.search_window);
  for (std::size_t i = closest; i <= last_searched; ++i) {
    if ((path[i].position() - here).norm() < (path[closest].position() - here).norm()) closest = i;
  }
  step.progress = closest;

  const geometry::Vec2 end = path.back().position();
  const double to_goal = (end - here).norm();
  if (to_goal <= settings.goal_tolerance_m && closest + settings.search_window >= path.size() - 1) {
    step.arrived = true;
    return step;
  }
  std::size_t target = closest;
  while (target + 1 < path.size() && (path[target].position() - here).norm() < settings.lookahead_m)
    ++target;
  const geometry::Vec2 aim = path[target].position();
  const double speed = limits.max_speed_mps * std::clamp(to_goal / settings.slow_down_m, 0.1, 1.0);

  if (kinematics == Kinematics::Holonomic) {
    const geometry::Vec2 d = aim - here;
    const double n = d.norm();
    const geometry::Vec2 v =
        n > 1e-9 ? geometry::Vec2(d * (std::min(speed, n / 0.5) / n)) : geometry::Vec2(0, 0);
    step.command.vx = v.x();
    step.command.vy = v.y();
    const double err = geometry::wrap_angle(path[target].theta - robot.theta);
    step.command.omega =
        std::clamp(settings.heading_gain * err, -limits.max_omega_rps, limits.max_omega_rps);
    return step;
  }

  // Unicycle: the aim point in the body frame.
  const double c = std::cos(robot.theta);
  const double s = std::sin(robot.theta);
  const geometry::Vec2 d = aim - here;
  const double lx = c * d.x() + s * d.y();
  const double ly = -s * d.x() + c * d.y();
  const double l2 = lx * lx + ly * ly;
  if (l2 < 1e-12) {
    step.arrived = to_goal <= settings.goal_tolerance_m;
    return step;
  }
  if (lx <= 0.0) {  // behind: turn towards it in place
    step.command.omega = ly >= 0.0 ? limits.max_omega_rps : -limits.max_omega_rps;
    return step;
  }
  const double curvature = 2.0 * ly / l2;
  double v = speed;
  if (std::abs(curvature) * v > limits.max_omega_rps)
    v = limits.max_omega_rps / std::abs(curvature);
  step.command.vx = v;
  step.command.omega = std::clamp(v * curvature, -limits.max_omega_rps, limits.max_omega_rps);
  return step;
}

}  // namespace autonomy::behavior
