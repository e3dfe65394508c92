// Velocity commands: validation against the robot's limits and expiry of held commands.
#include "simulator/core/world.hpp"
#include "world_fixtures.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace autonomy::sim {
namespace {

using test::command;
using test::robot_spec;
using test::room;
using test::run;

class WorldCommand : public ::testing::Test {
 protected:
  static WorldSpec spec() {
    WorldSpec s = room();
    s.command_timeout_s = 0.5;
    s.robots_at_start = {robot_spec("h1", Kinematics::Holonomic, 2.0, 2.0),
                         robot_spec("u1", Kinematics::Unicycle, 2.0, 10.0)};
    return s;
  }
  World world{spec()};

  std::string reject_reason(const VelocityCommand& c) {
    const CommandResult result = world.submit(c);
    EXPECT_FALSE(result.accepted);
    return result.reason;
  }
};

TEST_F(WorldCommand, RejectsUnknownRobot) {
  EXPECT_EQ(reject_reason(command("r9", 0.1, 0.0, 0.0)), "robot r9 unknown");
}

TEST_F(WorldCommand, RejectsNonFiniteValues) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(reject_reason(command("h1", nan, 0.0, 0.0)), "vx is NaN");
  EXPECT_EQ(reject_reason(command("h1", 0.0, -inf, 0.0)), "vy is infinite");
  EXPECT_EQ(reject_reason(command("u1", 0.0, 0.0, nan)), "omega is NaN");
}

TEST_F(WorldCommand, RejectsSpeedAboveTheLimit) {
  EXPECT_EQ(reject_reason(command("h1", 3.2, 0.0, 0.0)), "speed 3.2 m/s exceeds limit 1.0 m/s");
  EXPECT_EQ(reject_reason(command("h1", 0.8, 0.8, 0.0)),
            "speed 1.13137 m/s exceeds limit 1.0 m/s");  // holonomic: the norm counts
  EXPECT_EQ(reject_reason(command("u1", -1.5, 0.0, 0.0)), "speed 1.5 m/s exceeds limit 1.0 m/s");
}

TEST_F(WorldCommand, AcceptsExactlyTheLimitDespiteRounding) {
  EXPECT_TRUE(world.submit(command("h1", 0.6, 0.8, 2.0)).accepted);
  EXPECT_TRUE(world.submit(command("h1", std::sqrt(0.5), std::sqrt(0.5), -2.0)).accepted);
  EXPECT_TRUE(world.submit(command("u1", -1.0, 0.0, 2.0 + 1e-12)).accepted);
}

TEST_F(WorldCommand, RejectsSidewaysSpeedForAUnicycle) {
  EXPECT_EQ(reject_reason(command("u1", 0.5, 0.1, 0.0)), "vy must be 0 for unicycle robot u1 (got 0.1)");
}

TEST_F(WorldCommand, RejectsTurnRateAboveTheLimit) {
  EXPECT_EQ(reject_reason(command("u1", 0.5, 0.0, -2.5)), "|omega| 2.5 rad/s exceeds limit 2.0 rad/s");
}

TEST_F(WorldCommand, RejectedCommandIsNeverAppliedAndKeepsTheHeldOne) {
  ASSERT_TRUE(world.submit(command("h1", 0.5, 0.0, 0.0)).accepted);
  EXPECT_FALSE(world.submit(command("h1", 5.0, 0.0, 0.0)).accepted);
  run(world, 4);  // 0.2 s
  EXPECT_NEAR(world.robot("h1")->pose.x, 2.1, 1e-9);
  EXPECT_FALSE(world.submit(command("u1", 0.5, 0.5, 0.0)).accepted);
  EXPECT_DOUBLE_EQ(world.robot("u1")->pose.x, 2.0);
}

TEST_F(WorldCommand, HeldCommandExpiresAfterTheTimeout) {
  ASSERT_TRUE(world.submit(command("h1", 1.0, 0.0, 0.0)).accepted);
  run(world, 20);  // 1 s, but the command holds for 0.5 s only
  const RobotStatus r = *world.robot("h1");
  EXPECT_NEAR(r.pose.x, 2.5, 1e-9);
  EXPECT_DOUBLE_EQ(r.vx, 0.0);
  EXPECT_FALSE(r.in_collision);
}

TEST_F(WorldCommand, RefreshedCommandKeepsTheRobotMoving) {
  for (int i = 0; i < 20; ++i) {
    ASSERT_TRUE(world.submit(command("h1", 1.0, 0.0, 0.0)).accepted);
    world.step(0.05);
  }
  EXPECT_NEAR(world.robot("h1")->pose.x, 3.0, 1e-9);
}

}  // namespace
}  // namespace autonomy::sim
