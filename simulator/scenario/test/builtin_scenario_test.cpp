#include "simulator/core/world.hpp"
#include "simulator/scenario/builtin_scenario.hpp"
#include "simulator/scenario/scenario_loader.hpp"

#include <gtest/gtest.h>

namespace autonomy::sim {
namespace {

TEST(BuiltinScenario, LoadsAndBuildsTheDemoWorld) {
  const ScenarioLoadResult result =
      load_scenario_text(std::string(builtin_default_scenario()), std::string(kBuiltinScenarioSource));
  ASSERT_TRUE(result.ok()) << result.error_text();
  const Scenario& s = *result.scenario;
  EXPECT_EQ(s.world.name, "demo");
  EXPECT_DOUBLE_EQ(s.world.width, 20.0);
  EXPECT_DOUBLE_EQ(s.world.height, 12.0);
  EXPECT_EQ(s.world.obstacles.size(), 4u);
  ASSERT_EQ(s.world.robots_at_start.size(), 1u);
  EXPECT_EQ(s.world.robots_at_start[0].id, "r1");
  EXPECT_EQ(s.world.robots_at_start[0].kinematics, Kinematics::Unicycle);
  EXPECT_EQ(s.world.robots_at_start[0].start, (geometry::Pose2{2.0, 2.0, 0.0}));
  ASSERT_EQ(s.world.known_robots.size(), 2u);
  EXPECT_EQ(s.world.known_robots[0].id, "r2");
  EXPECT_EQ(s.world.known_robots[0].kinematics, Kinematics::Holonomic);
  EXPECT_EQ(s.world.known_robots[1].id, "r3");
  EXPECT_EQ(s.simulation.mode, ClockMode::Lockstep);
  EXPECT_DOUBLE_EQ(s.simulation.step_s, 0.05);
  EXPECT_EQ(s.simulation.seed, 1u);

  World world(s.world);
  EXPECT_EQ(world.robots().size(), 1u);
  EXPECT_TRUE(world.spawn("r2").accepted);
  EXPECT_TRUE(world.spawn("r3").accepted);
}

TEST(BuiltinScenario, WallBlocksTheStraightLineFromStartToGoal) {
  const ScenarioLoadResult result =
      load_scenario_text(std::string(builtin_default_scenario()), std::string(kBuiltinScenarioSource));
  ASSERT_TRUE(result.ok()) << result.error_text();
  World world(result.scenario->world);
  for (int i = 0; i < 300; ++i) {  // drive straight east from (2, 2) for 15 s
    (void)world.submit({"r1", "test", 0, 1.0, 0.0, 0.0});
    world.step(0.05);
  }
  EXPECT_NEAR(world.robot("r1")->pose.x, 9.8 - 0.3, 0.002);
  EXPECT_TRUE(world.robot("r1")->in_collision);
}

}  // namespace
}  // namespace autonomy::sim
