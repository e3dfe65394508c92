#include "services/behavior/core/path/path_follower.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

namespace autonomy::behavior {

namespace {

bool positive_finite(double v) {
  return std::isfinite(v) && v > 0.0;
}

}  // namespace

std::vector<std::vector<geometry::Pose2>> split_at_cusps(const std::vector<geometry::Pose2>& path) {
  std::vector<std::vector<geometry::Pose2>> legs;
  if (path.empty()) return legs;
  legs.push_back({path.front()});
  std::optional<geometry::Vec2> last_step;  // the last motion longer than a millimetre
  for (std::size_t i = 1; i < path.size(); ++i) {
    const geometry::Vec2 step = path[i].position() - path[i - 1].position();
    if (step.norm() > 1e-3) {
      if (last_step && last_step->dot(step) < 0.0) legs.push_back({path[i - 1]});
      last_step = step;
    }
    legs.back().push_back(path[i]);
  }
  return legs;
}

const char* to_string(FollowOutcome o) {
  switch (o) {
    case FollowOutcome::Following:
      return "following";
    case FollowOutcome::Arrived:
      return "arrived";
    case FollowOutcome::Strayed:
      return "strayed";
    case FollowOutcome::NoPath:
      return "no path";
  }
  return "?";
}

PathFollower::PathFollower(Kinematics kinematics, MotionLimits limits, PathFollowerConfig config)
    : kinematics_(kinematics), limits_(limits), config_(config), avoid_(config.avoid) {
  if (!positive_finite(limits.max_speed_mps) || !positive_finite(limits.max_omega_rps))
    throw std::invalid_argument("path follower: limits must be positive and finite");
  const PursuitSettings& p = config.pursuit;
  if (!positive_finite(p.lookahead_m) || !positive_finite(p.goal_tolerance_m) ||
      !positive_finite(p.slow_down_m) || !positive_finite(p.heading_gain) ||
      !positive_finite(config.stray_distance_m) || !std::isfinite(config.avoid_gain) ||
      config.avoid_gain < 0.0) {
    throw std::invalid_argument("path follower: settings must be positive and finite");
  }
}

void PathFollower::follow(std::vector<geometry::Pose2> path) {
  path_ = std::move(path);
  legs_ = split_at_cusps(path_);
  leg_ = 0;
  progress_ = 0;
}

void PathFollower::set_goal_tolerance(double metres) {
  if (positive_finite(metres)) config_.pursuit.goal_tolerance_m = metres;
}

FollowStep PathFollower::step(const geometry::Pose2& pose, const std::vector<RangeRay>& rays) {
  FollowStep out;
  if (path_.empty() || !std::isfinite(pose.x) || !std::isfinite(pose.y) ||
      !std::isfinite(pose.theta)) {
    return out;
  }
  PursuitStep p = pure_pursuit(legs_[leg_], progress_, pose, kinematics_, limits_, config_.pursuit);
  // At a cusp: on to the next leg (a leg's end is the next one's start).
  while (p.arrived && leg_ + 1 < legs_.size()) {
    ++leg_;
    p = pure_pursuit(legs_[leg_], 0, pose, kinematics_, limits_, config_.pursuit);
  }
  progress_ = p.progress;
  out.progress = p.progress;
  out.off_path_m = (legs_[leg_][p.progress].position() - pose.position()).norm();
  if (p.arrived) {
    out.outcome = FollowOutcome::Arrived;
    return out;
  }
  out.command = with_avoidance(p.command, pose, rays);
  out.outcome =
      out.off_path_m > config_.stray_distance_m ? FollowOutcome::Strayed : FollowOutcome::Following;
  return out;
}

VelocityCommand PathFollower::with_avoidance(const VelocityCommand& pursuit,
                                             const geometry::Pose2& pose,
                                             const std::vector<RangeRay>& rays) const {
  if (config_.avoid_gain == 0.0 || rays.empty()) return pursuit;
  Perception perception;
  perception.pose = pose;
  perception.rays = rays;
  const geometry::Vec2 vote = avoid_.vote(perception);
  if (vote.squaredNorm() == 0.0) return pursuit;
  const geometry::Vec2 push = vote * (config_.avoid_gain * limits_.max_speed_mps);
  const geometry::Vec2 heading(std::cos(pose.theta), std::sin(pose.theta));
  VelocityCommand c = pursuit;
  if (kinematics_ == Kinematics::Holonomic) {
    geometry::Vec2 v = geometry::Vec2(pursuit.vx, pursuit.vy) + push;
    const double n = v.norm();
    if (n > limits_.max_speed_mps) v *= limits_.max_speed_mps / n;
    c.vx = v.x();
    c.vy = v.y();
    return c;
  }
  // Unicycle: the blended world velocity projected on the heading (never backwards, never faster
  // than pursuit asked), and a turn towards the blend's direction on top of pursuit's turn.
  const geometry::Vec2 want = heading * pursuit.vx + push;
  c.vx = std::clamp(want.dot(heading), 0.0, pursuit.vx);
  const double side = heading.x() * want.y() - heading.y() * want.x();  // cross(heading, want)
  const double turn = side / limits_.max_speed_mps * config_.pursuit.heading_gain;
  c.omega = std::clamp(pursuit.omega + turn, -limits_.max_omega_rps, limits_.max_omega_rps);
  return c;
}

}  // namespace autonomy::behavior
