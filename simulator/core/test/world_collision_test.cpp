// Motion through the World: kinematics, contact with walls, obstacles and robots, determinism.
#include "simulator/core/world.hpp"
#include "world_fixtures.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace autonomy::sim {
namespace {

using test::command;
using test::robot_spec;
using test::room;
using test::run;

TEST(WorldMotion, HolonomicRobotMovesStraight) {
  WorldSpec spec = room();
  spec.robots_at_start = {robot_spec("r1", Kinematics::Holonomic, 2.0, 2.0)};
  World world(spec);
  ASSERT_TRUE(world.submit(command("r1", 0.6, 0.8, 0.0)).accepted);
  run(world, 40);  // 2 s at 1 m/s
  const RobotStatus r = *world.robot("r1");
  EXPECT_NEAR(r.pose.x, 3.2, 1e-9);
  EXPECT_NEAR(r.pose.y, 3.6, 1e-9);
  EXPECT_NEAR(r.distance_travelled, 2.0, 1e-9);
  EXPECT_DOUBLE_EQ(r.vx, 0.6);
  EXPECT_DOUBLE_EQ(r.vy, 0.8);
  EXPECT_FALSE(r.in_collision);
  EXPECT_NEAR(world.time_s(), 2.0, 1e-9);
}

TEST(WorldMotion, UnicycleRobotDrivesAHalfCircle) {
  WorldSpec spec = room();
  spec.robots_at_start = {robot_spec("r1", Kinematics::Unicycle, 5.0, 2.0)};
  World world(spec);
  // 0.5 m/s at 0.5 rad/s: radius 1 m; after 2 pi seconds it faces back, 2 m to the left.
  ASSERT_TRUE(world.submit(command("r1", 0.5, 0.0, 0.5)).accepted);
  run(world, 200, M_PI / 100);
  const RobotStatus r = *world.robot("r1");
  EXPECT_NEAR(r.pose.x, 5.0, 1e-9);
  EXPECT_NEAR(r.pose.y, 4.0, 1e-9);
  EXPECT_NEAR(std::abs(r.pose.theta), M_PI, 1e-9);
  EXPECT_NEAR(r.distance_travelled, M_PI, 1e-9);
}

TEST(WorldCollision, RobotStopsAtTheWorldBoundaryAtItsRadius) {
  WorldSpec spec = room();
  spec.robots_at_start = {robot_spec("r1", Kinematics::Unicycle, 18.0, 2.0)};
  World world(spec);
  ASSERT_TRUE(world.submit(command("r1", 1.0, 0.0, 0.0)).accepted);
  bool collided = false;
  for (int i = 0; i < 60; ++i) {
    world.step(0.05);
    const RobotStatus r = *world.robot("r1");
    EXPECT_LE(r.pose.x, 20.0 - 0.3) << "step " << i;  // never overlaps the boundary
    collided = collided || r.in_collision;
  }
  const RobotStatus r = *world.robot("r1");
  EXPECT_TRUE(collided);
  EXPECT_TRUE(r.in_collision);  // still pushing against the wall
  EXPECT_NEAR(20.0 - r.pose.x, 0.3, 0.002);
  EXPECT_DOUBLE_EQ(r.vx, 0.0);
}

TEST(WorldCollision, RobotStopsAtAnObstacleAtItsRadiusAndNeverCloser) {
  WorldSpec spec = room();  // obstacle [10, 11] x [4, 8]
  spec.robots_at_start = {robot_spec("r1", Kinematics::Holonomic, 7.0, 6.0)};
  World world(spec);
  ASSERT_TRUE(world.submit(command("r1", 0.9, 0.1, 0.0)).accepted);
  for (int i = 0; i < 100; ++i) {
    world.step(0.05);
    const double d = geometry::distance(spec.obstacles[0], world.robot("r1")->pose.position());
    ASSERT_GE(d, 0.3) << "step " << i;
  }
  const RobotStatus r = *world.robot("r1");
  EXPECT_TRUE(r.in_collision);
  EXPECT_NEAR(geometry::distance(spec.obstacles[0], r.pose.position()), 0.3, 0.002);
  EXPECT_NEAR(r.pose.x, 9.7, 0.002);
}

TEST(WorldCollision, BlockedUnicycleStillTurnsAndCanLeave) {
  WorldSpec spec = room();
  spec.robots_at_start = {robot_spec("r1", Kinematics::Unicycle, 19.0, 2.0)};
  World world(spec);
  ASSERT_TRUE(world.submit(command("r1", 1.0, 0.0, 0.0)).accepted);
  run(world, 20);
  ASSERT_TRUE(world.robot("r1")->in_collision);
  // Pushing into the wall while turning: no translation, full rotation.
  ASSERT_TRUE(world.submit(command("r1", 1.0, 0.0, 2.0)).accepted);
  const double x_at_wall = world.robot("r1")->pose.x;
  world.step(0.05);
  EXPECT_NEAR(world.robot("r1")->pose.theta, 0.1, 1e-12);
  EXPECT_LE(world.robot("r1")->pose.x, 19.7);
  EXPECT_NEAR(world.robot("r1")->pose.x, x_at_wall, 0.002);  // may creep closer, never past
  const double x_after_turn = world.robot("r1")->pose.x;
  // Turn in place (no contact, no translation) to theta 1.6, then drive off along the wall.
  ASSERT_TRUE(world.submit(command("r1", 0.0, 0.0, 2.0)).accepted);
  run(world, 15);
  EXPECT_FALSE(world.robot("r1")->in_collision);
  EXPECT_DOUBLE_EQ(world.robot("r1")->pose.x, x_after_turn);
  EXPECT_NEAR(world.robot("r1")->pose.theta, 1.6, 1e-9);
  ASSERT_TRUE(world.submit(command("r1", 0.5, 0.0, 0.0)).accepted);
  world.step(0.05);
  EXPECT_FALSE(world.robot("r1")->in_collision);
  EXPECT_LT(world.robot("r1")->pose.x, x_after_turn);
}

TEST(WorldCollision, RobotStopsAtAnotherRobot) {
  WorldSpec spec = room();
  spec.robots_at_start = {robot_spec("r1", Kinematics::Holonomic, 2.0, 10.0),
                          robot_spec("r2", Kinematics::Holonomic, 4.0, 10.0)};
  World world(spec);
  ASSERT_TRUE(world.submit(command("r1", 1.0, 0.0, 0.0)).accepted);
  run(world, 40);
  const RobotStatus r1 = *world.robot("r1");
  const RobotStatus r2 = *world.robot("r2");
  const double gap = (r1.pose.position() - r2.pose.position()).norm();
  EXPECT_GE(gap, 0.6);
  EXPECT_NEAR(gap, 0.6, 0.002);
  EXPECT_TRUE(r1.in_collision);
  EXPECT_FALSE(r2.in_collision);
  EXPECT_DOUBLE_EQ(r2.pose.x, 4.0);
}

TEST(WorldCollision, RobotsDrivingHeadOnStopApartInIdOrder) {
  WorldSpec spec = room();
  spec.robots_at_start = {robot_spec("a", Kinematics::Holonomic, 2.0, 10.0),
                          robot_spec("b", Kinematics::Holonomic, 3.0, 10.0)};
  World world(spec);
  ASSERT_TRUE(world.submit(command("a", 1.0, 0.0, 0.0)).accepted);
  ASSERT_TRUE(world.submit(command("b", -1.0, 0.0, 0.0)).accepted);
  world.step(0.05);  // both free: gap 1.0 -> 0.9
  world.step(0.2);   // a moves first (gap 0.9 -> 0.7), so b has room for 0.1 m of its 0.2 m
  const RobotStatus a = *world.robot("a");
  const RobotStatus b = *world.robot("b");
  EXPECT_NEAR(a.pose.x, 2.25, 1e-9);
  EXPECT_FALSE(a.in_collision);
  EXPECT_NEAR(b.pose.x, 2.85, 0.002);
  EXPECT_GE(b.pose.x - a.pose.x, 0.6);
  EXPECT_TRUE(b.in_collision);
}

TEST(WorldDeterminism, SameCommandsGiveIdenticalPoses) {
  const auto simulate = [] {
    WorldSpec spec = room();
    spec.command_timeout_s = 0.5;
    spec.robots_at_start = {robot_spec("r1", Kinematics::Unicycle, 8.0, 6.0),
                            robot_spec("r2", Kinematics::Holonomic, 13.0, 6.0),
                            robot_spec("r3", Kinematics::Holonomic, 12.0, 2.0, 1.0)};
    World world(spec);
    for (int i = 0; i < 400; ++i) {
      const double phase = 0.05 * i;
      (void)world.submit(command("r1", 1.0, 0.0, std::sin(phase)));
      if (i % 7 == 0) (void)world.submit(command("r2", -0.7, 0.3 * std::cos(phase), 0.5));
      if (i % 11 == 0) (void)world.submit(command("r3", 0.1 * (i % 5), 0.6, -1.0));
      world.step(0.05);
    }
    return world.robots();
  };
  const std::vector<RobotStatus> first = simulate();
  const std::vector<RobotStatus> second = simulate();
  ASSERT_EQ(first.size(), 3u);
  ASSERT_EQ(second.size(), 3u);
  for (std::size_t i = 0; i < first.size(); ++i) {
    EXPECT_EQ(first[i].id, second[i].id);
    EXPECT_EQ(first[i].pose, second[i].pose) << first[i].id;
    EXPECT_EQ(first[i].distance_travelled, second[i].distance_travelled) << first[i].id;
  }
}

}  // namespace
}  // namespace autonomy::sim
