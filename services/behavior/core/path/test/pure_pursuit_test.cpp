#include "services/behavior/core/path/pure_pursuit.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace autonomy::behavior {
namespace {

// A polyline sampled every 5 cm, headings along it.
std::vector<geometry::Pose2> densify(const std::vector<geometry::Vec2>& corners) {
  std::vector<geometry::Pose2> out;
  for (std::size_t i = 1; i < corners.size(); ++i) {
    const geometry::Vec2 d = corners[i] - corners[i - 1];
    const int n = static_cast<int>(std::ceil(d.norm() / 0.05));
    const double th = std::atan2(d.y(), d.x());
    for (int k = (i == 1 ? 0 : 1); k <= n; ++k) {
      const geometry::Vec2 p = corners[i - 1] + d * (static_cast<double>(k) / n);
      out.push_back({p.x(), p.y(), th});
    }
  }
  return out;
}

// Integrates the commands at 10 Hz; checks every command against the limits; returns the final
// pose and the largest distance from the path's corners polyline seen (cross-track error).
struct Drive {
  geometry::Pose2 end;
  bool arrived = false;
  double worst_offset = 0.0;
};

Drive drive(const std::vector<geometry::Pose2>& path, geometry::Pose2 pose, Kinematics k,
            const MotionLimits& lim) {
  Drive d;
  std::size_t progress = 0;
  for (int tick = 0; tick < 2000 && !d.arrived; ++tick) {
    const auto step = pure_pursuit(path, progress, pose, k, lim);
    EXPECT_GE(step.progress, progress);
    progress = step.progress;
    d.arrived = step.arrived;
    const auto& c = step.command;
    if (k == Kinematics::Unicycle) {
      EXPECT_EQ(c.vy, 0.0);
      EXPECT_GE(c.vx, 0.0);
      EXPECT_LE(c.vx, lim.max_speed_mps + 1e-12);
      pose.x += c.vx * std::cos(pose.theta) * 0.1;
      pose.y += c.vx * std::sin(pose.theta) * 0.1;
    } else {
      EXPECT_LE(std::hypot(c.vx, c.vy), lim.max_speed_mps + 1e-12);
      pose.x += c.vx * 0.1;
      pose.y += c.vy * 0.1;
    }
    EXPECT_LE(std::abs(c.omega), lim.max_omega_rps + 1e-12);
    pose.theta = geometry::wrap_angle(pose.theta + c.omega * 0.1);
    double nearest = 1e9;
    for (const auto& p : path) nearest = std::min(nearest, (p.position() - pose.position()).norm());
    d.worst_offset = std::max(d.worst_offset, nearest);
  }
  d.end = pose;
  return d;
}

const MotionLimits kPursuitLimits{0.8, 1.5};

TEST(PurePursuit, ConvergesOnAStraightLineFromAnOffset) {
  const auto path = densify({{0, 0}, {6, 0}});
  const auto d = drive(path, {0.0, 0.5, 0.0}, Kinematics::Unicycle, kPursuitLimits);
  EXPECT_TRUE(d.arrived);
  EXPECT_NEAR(d.end.x, 6.0, 0.1);
  EXPECT_NEAR(d.end.y, 0.0, 0.1);
  EXPECT_LE(d.worst_offset, 0.51);  // never (by more than 1 cm) further off than it started
}

TEST(PurePursuit, FollowsAnLPathWithBothKinematics) {
  const auto path = densify({{0, 0}, {4, 0}, {4, 4}});
  for (Kinematics k : {Kinematics::Unicycle, Kinematics::Holonomic}) {
    const auto d = drive(path, {0.0, 0.0, 0.0}, k, kPursuitLimits);
    EXPECT_TRUE(d.arrived);
    EXPECT_NEAR(d.end.x, 4.0, 0.1);
    EXPECT_NEAR(d.end.y, 4.0, 0.1);
    EXPECT_LE(d.worst_offset, 0.35);  // corner cut by at most about half the look-ahead
  }
}

TEST(PurePursuit, TurnsInPlaceWhenThePathIsBehind) {
  const auto path = densify({{0, 0}, {-3, 0}});
  const auto step = pure_pursuit(path, 0, {0.0, 0.0, 0.0}, Kinematics::Unicycle, kPursuitLimits);
  EXPECT_EQ(step.command.vx, 0.0);
  EXPECT_DOUBLE_EQ(std::abs(step.command.omega), kPursuitLimits.max_omega_rps);
  EXPECT_FALSE(step.arrived);
}

TEST(PurePursuit, EmptyPathAndArrivalGiveZeroCommands) {
  EXPECT_TRUE(pure_pursuit({}, 0, {}, Kinematics::Unicycle, kPursuitLimits).arrived);
  const auto path = densify({{0, 0}, {1, 0}});
  const auto step = pure_pursuit(path, 0, {1.0, 0.05, 0.0}, Kinematics::Unicycle, kPursuitLimits);
  EXPECT_TRUE(step.arrived);
  EXPECT_TRUE(step.command.is_zero());
}

}  // namespace
}  // namespace autonomy::behavior
