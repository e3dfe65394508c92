// The tracking schema: an OMPL path followed through a doorway within the limits, stray
// detection, and the obstacle-avoidance schema beside it.
#include "services/behavior/core/path/path_follower.hpp"
#include "services/behavior/core/path/ompl_path_planner.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace autonomy::behavior {
namespace {

const MotionLimits kLimits{0.8, 1.5};

std::vector<geometry::Pose2> straight_path(double length) {
  std::vector<geometry::Pose2> out;
  for (int k = 0; k * 0.05 <= length + 1e-9; ++k) out.push_back({1.0 + k * 0.05, 1.0, 0.0});
  return out;
}

// A 10 x 6 m room split by a 0.2 m wall at x = 5 with a 1 m doorway at y in [2.5, 3.5].
WorldMap walled_room_map() {
  WorldMap w;
  w.width_m = 10.0;
  w.height_m = 6.0;
  w.obstacles = {{4.9, 0.0, 5.1, 2.5}, {4.9, 3.5, 5.1, 6.0}};
  return w;
}

TEST(PathFollower, DrivesAReedsSheppPathThroughTheDoorwayWithinTheLimits) {
  seed_ompl(11);
  const WorldMap w = walled_room_map();
  const auto grid = std::make_shared<const OccupancyGrid>(w, 0.05, 0.35);
  OmplPlannerSettings s;
  s.turning_radius_m = 0.4;
  OmplPathPlanner planner(grid, s);
  PathRequest q;
  q.start = {2.0, 1.0, M_PI};  // facing away from the doorway
  q.goal = {8.0, 5.0};
  q.budget_s = 1.0;
  const PathResult r = planner.plan(q);
  ASSERT_TRUE(r.found()) << r.reason;

  PathFollower follower(Kinematics::Unicycle, kLimits);
  follower.follow(r.poses);
  geometry::Pose2 pose = q.start;
  FollowStep step;
  bool passed_doorway = false;
  for (int tick = 0; tick < 3000; ++tick) {
    step = follower.step(pose, {});
    if (step.outcome == FollowOutcome::Arrived) break;
    EXPECT_NE(step.outcome, FollowOutcome::Strayed)
        << "tick " << tick << " off " << step.off_path_m;
    const auto& c = step.command;
    EXPECT_EQ(c.vy, 0.0);
    EXPECT_GE(c.vx, 0.0);
    EXPECT_LE(c.vx, kLimits.max_speed_mps + 1e-12);
    EXPECT_LE(std::abs(c.omega), kLimits.max_omega_rps + 1e-12);
    pose.x += c.vx * std::cos(pose.theta) * 0.05;
    pose.y += c.vx * std::sin(pose.theta) * 0.05;
    pose.theta = geometry::wrap_angle(pose.theta + c.omega * 0.05);
    // The robot's 0.3 m disc never touches a wall (the path keeps 0.35 m; tracking error < 5 cm).
    for (const auto& o : w.obstacles)
      ASSERT_GE(geometry::distance(o, pose.position()), 0.3) << "tick " << tick;
    if (std::abs(pose.x - 5.0) < 0.1) passed_doorway = true;
  }
  EXPECT_EQ(step.outcome, FollowOutcome::Arrived);
  EXPECT_TRUE(passed_doorway);
  EXPECT_NEAR(pose.x, 8.0, 0.15);
  EXPECT_NEAR(pose.y, 5.0, 0.15);
}

TEST(PathFollower, PushedOffThePathItReportsStrayed) {
  PathFollower follower(Kinematics::Unicycle, kLimits);
  follower.follow(straight_path(4.0));
  EXPECT_EQ(follower.step({1.0, 1.1, 0.0}, {}).outcome, FollowOutcome::Following);
  const FollowStep far = follower.step({2.0, 1.8, 0.0}, {});
  EXPECT_EQ(far.outcome, FollowOutcome::Strayed);
  EXPECT_NEAR(far.off_path_m, 0.8, 1e-9);
  EXPECT_FALSE(far.command.is_zero());  // it keeps steering back until the caller replans
}

TEST(PathFollower, NoPathAndArrivalGiveZeroCommands) {
  PathFollower follower(Kinematics::Unicycle, kLimits);
  EXPECT_EQ(follower.step({1.0, 1.0, 0.0}, {}).outcome, FollowOutcome::NoPath);
  follower.follow(straight_path(2.0));
  follower.set_goal_tolerance(0.05);
  const FollowStep end = follower.step({3.0, 1.02, 0.0}, {});
  EXPECT_EQ(end.outcome, FollowOutcome::Arrived);
  EXPECT_TRUE(end.command.is_zero());
  follower.clear();
  EXPECT_FALSE(follower.has_path());
}

TEST(PathFollower, AvoidSchemaSlowsAndTurnsAwayFromWhatTheRaysSee) {
  PathFollower follower(Kinematics::Unicycle, kLimits);
  follower.follow(straight_path(6.0));
  const geometry::Pose2 pose{1.0, 1.0, 0.0};
  const FollowStep free = follower.step(pose, {{0.0, 5.0, 5.0}});  // the ray saw nothing
  ASSERT_GT(free.command.vx, 0.5);
  EXPECT_NEAR(free.command.omega, 0.0, 1e-9);

  // Something 0.5 m ahead, a little to the left: slower, turning right, never backwards.
  const FollowStep ahead = follower.step(pose, {{0.2, 0.5, 5.0}});
  EXPECT_LT(ahead.command.vx, free.command.vx);
  EXPECT_GE(ahead.command.vx, 0.0);
  EXPECT_LT(ahead.command.omega, 0.0);
  // Many rays inside the margin: the command stays within the limits.
  std::vector<RangeRay> wall;
  for (int k = -10; k <= 10; ++k) wall.push_back({k * 0.05, 0.2, 5.0});
  const FollowStep blocked = follower.step(pose, wall);
  EXPECT_GE(blocked.command.vx, 0.0);
  EXPECT_LE(std::abs(blocked.command.omega), kLimits.max_omega_rps);

  PathFollower holonomic(Kinematics::Holonomic, kLimits);
  holonomic.follow(straight_path(6.0));
  const FollowStep side = holonomic.step(pose, {{M_PI / 2, 0.4, 5.0}});  // on the left
  EXPECT_LT(side.command.vy, 0.0);
  EXPECT_LE(std::hypot(side.command.vx, side.command.vy), kLimits.max_speed_mps + 1e-12);
}

// A path that drives east to (3, 1), then backs up north-west to (2, 2): two legs. The robot
// reaches the cusp before it takes the second leg, and arrives at the end.
TEST(PathFollower, ReachesEachCuspBeforeTheLegThatDoublesBack) {
  std::vector<geometry::Pose2> path = straight_path(2.0);  // (1, 1) to (3, 1), heading east
  for (int k = 1; k <= 28; ++k) {
    const double t = k / 28.0;
    path.push_back({3.0 - t, 1.0 + t, 0.0});  // reversing: heading stays east, motion goes back
  }
  const auto legs = split_at_cusps(path);
  ASSERT_EQ(legs.size(), 2u);
  EXPECT_NEAR(legs[0].back().x, 3.0, 1e-9);
  EXPECT_NEAR(legs[1].front().x, 3.0, 1e-9);
  EXPECT_EQ(legs[0].size() + legs[1].size(), path.size() + 1);
  EXPECT_EQ(split_at_cusps(straight_path(2.0)).size(), 1u);

  PathFollower follower(Kinematics::Unicycle, kLimits);
  follower.follow(path);
  EXPECT_EQ(follower.leg_count(), 2u);
  geometry::Pose2 pose{1.0, 1.0, 0.0};
  double closest_to_cusp = 1e9;
  FollowStep step;
  for (int tick = 0; tick < 2000; ++tick) {
    step = follower.step(pose, {});
    if (step.outcome == FollowOutcome::Arrived) break;
    if (follower.leg() == 0) closest_to_cusp = std::min(closest_to_cusp, std::hypot(pose.x - 3.0, pose.y - 1.0));
    const auto& c = step.command;
    EXPECT_GE(c.vx, 0.0);
    EXPECT_LE(std::abs(c.omega), kLimits.max_omega_rps + 1e-12);
    pose.x += c.vx * std::cos(pose.theta) * 0.05;
    pose.y += c.vx * std::sin(pose.theta) * 0.05;
    pose.theta = geometry::wrap_angle(pose.theta + c.omega * 0.05);
  }
  EXPECT_EQ(step.outcome, FollowOutcome::Arrived);
  EXPECT_EQ(follower.leg(), 1u);
  EXPECT_LE(closest_to_cusp, 0.15);
  EXPECT_NEAR(pose.x, 2.0, 0.15);
  EXPECT_NEAR(pose.y, 2.0, 0.15);
}

TEST(PathFollower, RejectsBadLimitsAndSettings) {
  EXPECT_THROW(PathFollower(Kinematics::Unicycle, {0.0, 1.0}), std::invalid_argument);
  PathFollowerConfig c;
  c.stray_distance_m = -1.0;
  EXPECT_THROW(PathFollower(Kinematics::Unicycle, kLimits, c), std::invalid_argument);
}

}  // namespace
}  // namespace autonomy::behavior
