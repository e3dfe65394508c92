#include "services/behavior/core/go_to_controller.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

namespace autonomy::behavior {
namespace {

using geometry::Pose2;
using geometry::Rect;
using geometry::Vec2;

constexpr double kRobotRadius = 0.25;
constexpr double kResolution = 0.1;
constexpr double kInflation = kRobotRadius + 0.1;  // margin >= 0.71 * resolution

// 6 m x 5 m, a wall from the floor to y = 3.2 m between start (left) and goal (right); the only
// way round is the 1.8 m gap above it.
WorldMap wall_world() { return WorldMap{6.0, 5.0, {Rect{2.8, 0.0, 3.2, 3.2}}}; }

struct Run {
  bool arrived = false;
  double seconds = 0.0;
  double min_clearance_m = 1e9;  // least distance from the robot's centre to an obstacle or border
  double max_speed_seen = 0.0;
  double max_omega_seen = 0.0;
};

// Integrates the commands in 0.05 s steps as the simulator would (unicycle by Euler on the pose).
Run simulate(const GoToController& controller, const WorldMap& world, Pose2 pose, const Vec2& goal,
             double tolerance, double time_limit_s) {
  const OccupancyGrid grid(world, kResolution, kInflation);
  const CostToGoField field(grid, goal);
  constexpr double dt = 0.05;
  Run run;
  for (double t = 0.0; t < time_limit_s; t += dt) {
    const auto decision = controller.command(pose, field, tolerance);
    if (decision.outcome == GoToOutcome::Arrived) {
      run.arrived = true;
      run.seconds = t;
      EXPECT_TRUE(decision.command.is_zero());
      break;
    }
    const auto& c = decision.command;
    run.max_speed_seen = std::max(run.max_speed_seen, std::hypot(c.vx, c.vy));
    run.max_omega_seen = std::max(run.max_omega_seen, std::abs(c.omega));
    if (controller.kinematics() == Kinematics::Holonomic) {
      pose.x += c.vx * dt;
      pose.y += c.vy * dt;
    } else {
      EXPECT_EQ(c.vy, 0.0);
      pose.x += c.vx * std::cos(pose.theta) * dt;
      pose.y += c.vx * std::sin(pose.theta) * dt;
    }
    pose.theta = geometry::wrap_angle(pose.theta + c.omega * dt);
    const Vec2 p = pose.position();
    double clearance = std::min({p.x(), p.y(), world.width_m - p.x(), world.height_m - p.y()});
    for (const auto& o : world.obstacles) clearance = std::min(clearance, geometry::distance(o, p));
    run.min_clearance_m = std::min(run.min_clearance_m, clearance);
  }
  return run;
}

TEST(GoToController, HolonomicGoesAroundTheWall) {
  const GoToController controller(Kinematics::Holonomic, MotionLimits{1.0, 2.0});
  const auto run = simulate(controller, wall_world(), Pose2{1.0, 1.0, 0.0}, Vec2(5.0, 1.0), 0.1, 60.0);
  EXPECT_TRUE(run.arrived);
  EXPECT_GE(run.min_clearance_m, kRobotRadius);  // the robot's disc never touched the wall
  EXPECT_LE(run.max_speed_seen, 1.0 + 1e-12);
  // The shortest collision-free route is about 4.7 m (up 2.6 m, across, down); the field makes the
  // robot use it, not wander: allow slow-down and corner rounding, not a second lap.
  EXPECT_LT(run.seconds, 12.0);
}

TEST(GoToController, UnicycleGoesAroundTheWallStartingBackwards) {
  const GoToController controller(Kinematics::Unicycle, MotionLimits{0.8, 2.0});
  const auto run = simulate(controller, wall_world(), Pose2{1.0, 1.0, M_PI}, Vec2(5.0, 1.0), 0.1, 90.0);
  EXPECT_TRUE(run.arrived);
  EXPECT_GE(run.min_clearance_m, kRobotRadius);
  EXPECT_LE(run.max_speed_seen, 0.8 + 1e-12);
  EXPECT_LE(run.max_omega_seen, 2.0);
  EXPECT_LT(run.seconds, 20.0);
}

TEST(GoToController, BothKinematicsCrossAClutteredRoom) {
  const WorldMap room{8.0, 6.0,
                      {Rect{2.0, 0.0, 2.4, 4.0}, Rect{4.0, 2.0, 4.4, 6.0}, Rect{5.5, 1.0, 6.5, 2.0},
                       Rect{0.8, 4.6, 1.4, 5.2}}};
  for (const auto kinematics : {Kinematics::Holonomic, Kinematics::Unicycle}) {
    const GoToController controller(kinematics, MotionLimits{0.7, 1.5});
    const auto run = simulate(controller, room, Pose2{0.8, 0.8, M_PI / 2}, Vec2(7.2, 5.2), 0.15, 120.0);
    EXPECT_TRUE(run.arrived) << static_cast<int>(kinematics);
    EXPECT_GE(run.min_clearance_m, kRobotRadius) << static_cast<int>(kinematics);
  }
}

TEST(GoToController, ManyRandomStartsAndGoalsArriveWithoutContact) {
  const WorldMap room{8.0, 6.0,
                      {Rect{2.0, 0.0, 2.4, 4.0}, Rect{4.0, 2.0, 4.4, 6.0}, Rect{5.5, 1.0, 6.5, 2.0},
                       Rect{0.8, 4.6, 1.4, 5.2}}};
  const OccupancyGrid grid(room, kResolution, kInflation);
  std::mt19937 rng(7);  // integer outputs only: distributions differ between standard libraries
  const auto uniform = [&rng](double hi) { return static_cast<double>(rng() % 10000u) * hi / 10000.0; };
  int runs = 0;
  while (runs < 60) {
    const Vec2 start(uniform(8.0), uniform(6.0));
    const Vec2 goal(uniform(8.0), uniform(6.0));
    const double theta = uniform(6.2) - 3.1;
    const CostToGoField field(grid, goal);
    if (!field.has_route_anywhere() || !std::isfinite(field.cost_at(start))) continue;
    for (const auto kinematics : {Kinematics::Holonomic, Kinematics::Unicycle}) {
      ++runs;
      const GoToController controller(kinematics, MotionLimits{0.8, 1.5});
      const auto run = simulate(controller, room, Pose2{start.x(), start.y(), theta}, goal, 0.1, 200.0);
      EXPECT_TRUE(run.arrived) << "start " << start.transpose() << " goal " << goal.transpose();
      EXPECT_GE(run.min_clearance_m, kRobotRadius) << "start " << start.transpose();
    }
  }
}

TEST(GoToController, NeverExceedsLimitsAnywhereOnTheMap) {
  const OccupancyGrid grid(wall_world(), kResolution, kInflation);
  const CostToGoField field(grid, Vec2(5.0, 1.0));
  for (const auto kinematics : {Kinematics::Holonomic, Kinematics::Unicycle}) {
    const GoToController controller(kinematics, MotionLimits{0.6, 0.9});
    int moving = 0;
    for (double x = 0.05; x < 6.0; x += 0.23) {
      for (double y = 0.05; y < 5.0; y += 0.19) {
        for (double theta = -3.0; theta < 3.2; theta += 0.7) {
          const auto c = controller.command(Pose2{x, y, theta}, field, 0.1).command;
          ASSERT_LE(std::hypot(c.vx, c.vy), 0.6 + 1e-12);
          ASSERT_LE(std::abs(c.omega), 0.9);
          if (kinematics == Kinematics::Unicycle) {
            ASSERT_EQ(c.vy, 0.0);
            ASSERT_GE(c.vx, 0.0);  // no reversing: it turns in place instead
          }
          moving += c.is_zero() ? 0 : 1;
        }
      }
    }
    EXPECT_GT(moving, 1000);
  }
}

TEST(GoToController, ZeroCommandWithinTolerance) {
  const OccupancyGrid grid(wall_world(), kResolution, kInflation);
  const CostToGoField field(grid, Vec2(5.0, 1.0));
  const GoToController controller(Kinematics::Unicycle, MotionLimits{1.0, 1.0});
  const auto d = controller.command(Pose2{5.05, 1.05, 2.0}, field, 0.1);
  EXPECT_EQ(d.outcome, GoToOutcome::Arrived);
  EXPECT_TRUE(d.command.is_zero());
}

TEST(GoToController, StuckWithZeroCommandWhenTheGoalIsBlocked) {
  const OccupancyGrid grid(wall_world(), kResolution, kInflation);
  const CostToGoField field(grid, Vec2(3.0, 1.0));  // inside the wall
  const GoToController controller(Kinematics::Holonomic, MotionLimits{1.0, 1.0});
  const auto d = controller.command(Pose2{1.0, 1.0, 0.0}, field, 0.1);
  EXPECT_EQ(d.outcome, GoToOutcome::Stuck);
  EXPECT_TRUE(d.command.is_zero());
}

TEST(GoToController, EscapesFromTheInflationMarginAwayFromTheWall) {
  const OccupancyGrid grid(wall_world(), kResolution, kInflation);
  const CostToGoField field(grid, Vec2(1.0, 1.0));
  const GoToController controller(Kinematics::Holonomic, MotionLimits{1.0, 1.0});
  const auto d = controller.command(Pose2{2.5, 1.0, 0.0}, field, 0.1);  // 0.3 m from the wall
  EXPECT_EQ(d.outcome, GoToOutcome::Escaping);
  EXPECT_LT(d.command.vx, 0.0);
}

TEST(GoToController, HeadsStraightForAVisibleGoalAndSlowsNearIt) {
  const OccupancyGrid grid(wall_world(), kResolution, kInflation);
  const CostToGoField field(grid, Vec2(1.6, 1.3));
  const GoToController controller(Kinematics::Holonomic, MotionLimits{1.0, 1.0});
  const auto d = controller.command(Pose2{1.0, 1.0, 0.0}, field, 0.05);
  EXPECT_EQ(d.target, Vec2(1.6, 1.3));
  const Vec2 v(d.command.vx, d.command.vy);
  EXPECT_TRUE(v.normalized().isApprox(Vec2(0.6, 0.3).normalized()));
  const auto near = controller.command(Pose2{1.4, 1.3, 0.0}, field, 0.05);
  EXPECT_NEAR(near.command.vx, 0.2 / 0.5, 1e-9);  // linear slow-down within 0.5 m
}

TEST(GoToController, UnicycleTurnsInPlaceWhenFacingAway) {
  const OccupancyGrid grid(wall_world(), kResolution, kInflation);
  const CostToGoField field(grid, Vec2(2.0, 1.0));
  const GoToController controller(Kinematics::Unicycle, MotionLimits{1.0, 1.0});
  const auto d = controller.command(Pose2{1.0, 1.0, M_PI}, field, 0.1);
  EXPECT_EQ(d.command.vx, 0.0);
  EXPECT_EQ(std::abs(d.command.omega), 1.0);
}

TEST(GoToController, RejectsNonPositiveLimits) {
  EXPECT_THROW(GoToController(Kinematics::Unicycle, MotionLimits{0.0, 1.0}), std::invalid_argument);
  EXPECT_THROW(GoToController(Kinematics::Unicycle, MotionLimits{1.0, NAN}), std::invalid_argument);
}

}  // namespace
}  // namespace autonomy::behavior
