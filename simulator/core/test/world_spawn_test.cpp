// Spawning and removing robots.
#include "simulator/core/world.hpp"
#include "world_fixtures.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace autonomy::sim {
namespace {

using test::robot_spec;
using test::room;

class WorldSpawn : public ::testing::Test {
 protected:
  static WorldSpec spec() {
    WorldSpec s = room();  // obstacle [10, 11] x [4, 8]
    s.robots_at_start = {robot_spec("r1", Kinematics::Unicycle, 2.0, 2.0)};
    RobotSpec r2 = robot_spec("r2", Kinematics::Holonomic, 4.0, 2.0, 1.0);
    r2.radius = 0.4;
    r2.max_speed = 0.5;
    s.known_robots = {r2};
    return s;
  }
  World world{spec()};

  std::string reject_reason(const std::string& id, std::optional<geometry::Pose2> pose) {
    const SpawnResult result = world.spawn(id, pose);
    EXPECT_FALSE(result.accepted);
    return result.reason;
  }
};

TEST_F(WorldSpawn, StartRobotsArePresentKnownRobotsAreNot) {
  const std::vector<RobotStatus> robots = world.robots();
  ASSERT_EQ(robots.size(), 1u);
  EXPECT_EQ(robots[0].id, "r1");
  EXPECT_EQ(robots[0].kinematics, Kinematics::Unicycle);
  EXPECT_EQ(robots[0].pose, (geometry::Pose2{2.0, 2.0, 0.0}));
  EXPECT_FALSE(world.robot("r2").has_value());
}

TEST_F(WorldSpawn, KnownRobotSpawnsAtItsStartWithItsLimits) {
  const SpawnResult result = world.spawn("r2");
  EXPECT_TRUE(result.accepted);
  EXPECT_FALSE(result.already_present);
  const RobotStatus r2 = *world.robot("r2");
  EXPECT_EQ(r2.pose, (geometry::Pose2{4.0, 2.0, 1.0}));
  EXPECT_EQ(r2.kinematics, Kinematics::Holonomic);
  EXPECT_DOUBLE_EQ(r2.radius, 0.4);
  EXPECT_DOUBLE_EQ(r2.max_speed, 0.5);
  ASSERT_EQ(world.robots().size(), 2u);
  EXPECT_EQ(world.robots()[1].id, "r2");  // sorted by id
}

TEST_F(WorldSpawn, GivenPoseOverridesTheConfiguredStart) {
  EXPECT_TRUE(world.spawn("r2", geometry::Pose2{6.0, 9.0, 4.0}).accepted);
  EXPECT_DOUBLE_EQ(world.robot("r2")->pose.x, 6.0);
  EXPECT_NEAR(world.robot("r2")->pose.theta, 4.0 - 2 * M_PI, 1e-12);  // wrapped
}

TEST_F(WorldSpawn, UnconfiguredRobotNeedsAPoseAndGetsTheAttachDefaults) {
  EXPECT_EQ(reject_reason("r7", std::nullopt), "no start pose configured for robot r7; pass one");
  EXPECT_TRUE(world.spawn("r7", geometry::Pose2{15.0, 6.0, 0.0}).accepted);
  EXPECT_DOUBLE_EQ(world.robot("r7")->radius, 0.25);
}

TEST_F(WorldSpawn, ReattachWithoutPoseIsIdempotent) {
  const SpawnResult result = world.spawn("r1");
  EXPECT_TRUE(result.accepted);
  EXPECT_TRUE(result.already_present);
  EXPECT_EQ(world.robots().size(), 1u);
  EXPECT_EQ(reject_reason("r1", geometry::Pose2{5.0, 5.0, 0.0}), "robot r1 is already present");
}

TEST_F(WorldSpawn, RejectsInvalidIds) {
  EXPECT_EQ(reject_reason("", geometry::Pose2{5.0, 5.0, 0.0}), "robot id is empty");
  EXPECT_EQ(reject_reason("r 1", geometry::Pose2{5.0, 5.0, 0.0}),
            "robot id 'r 1' has characters outside [A-Za-z0-9_.-]");
}

TEST_F(WorldSpawn, RejectsPosesOutsideTheWorld) {
  EXPECT_EQ(reject_reason("r7", geometry::Pose2{0.1, 5.0, 0.0}),
            "robot r7 at (0.1, 5.0) does not fit inside the world [0, 20.0] x [0, 12.0]");
  EXPECT_EQ(reject_reason("r7", geometry::Pose2{25.0, 5.0, 0.0}),
            "robot r7 at (25.0, 5.0) does not fit inside the world [0, 20.0] x [0, 12.0]");
  EXPECT_EQ(reject_reason("r7", geometry::Pose2{5.0, std::nan(""), 0.0}), "y is NaN");
}

TEST_F(WorldSpawn, RejectsPosesOverlappingObstaclesOrRobots) {
  EXPECT_EQ(reject_reason("r7", geometry::Pose2{10.5, 6.0, 0.0}), "robot r7 at (10.5, 6.0) overlaps obstacle 0");
  EXPECT_EQ(reject_reason("r7", geometry::Pose2{9.8, 6.0, 0.0}), "robot r7 at (9.8, 6.0) overlaps obstacle 0");
  EXPECT_EQ(reject_reason("r7", geometry::Pose2{2.5, 2.0, 0.0}), "robot r7 at (2.5, 2.0) overlaps robot r1");
  EXPECT_TRUE(world.spawn("r7", geometry::Pose2{2.6, 2.0, 0.0}).accepted);  // 5 cm clear
}

TEST_F(WorldSpawn, RemovedRobotCanSpawnAgain) {
  EXPECT_TRUE(world.remove("r1"));
  EXPECT_FALSE(world.remove("r1"));
  EXPECT_TRUE(world.robots().empty());
  EXPECT_TRUE(world.spawn("r1").accepted);  // back at its configured start
  EXPECT_EQ(world.robot("r1")->pose, (geometry::Pose2{2.0, 2.0, 0.0}));
}

TEST(WorldConstruction, RejectsAnUnusableSpec) {
  WorldSpec spec = room();
  spec.robots_at_start = {robot_spec("r1", Kinematics::Holonomic, 10.5, 6.0)};
  EXPECT_THROW(World{spec}, std::invalid_argument);
  spec = room();
  spec.width = 0.0;
  EXPECT_THROW(World{spec}, std::invalid_argument);
}

}  // namespace
}  // namespace autonomy::sim
