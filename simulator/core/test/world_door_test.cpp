// The World with walls, doors and sensing: a robot stops at a closed door and passes an open
// one, a door never swings through a robot, line of sight, range scans and door observations.
#include "simulator/core/world.hpp"

#include "simulator/core/test/world_fixtures.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace autonomy::sim {
namespace {

using test::command;
using test::robot_spec;
using test::run;

constexpr double kOpen = M_PI / 2;

// A 20 x 10 m floor: a wall along y = 5 (0.2 m thick) with a 1 m doorway at x in [9.5, 10.5];
// the door is hinged at x = 9.5 and opens clockwise, into the south room. Robot r1 stands in
// the north half facing the doorway.
WorldSpec floor_with_door(double angle) {
  WorldSpec spec;
  spec.name = "floor";
  spec.width = 20.0;
  spec.height = 10.0;
  spec.obstacles = {{0.0, 4.9, 9.5, 5.1}, {10.5, 4.9, 20.0, 5.1}};
  DoorSpec d;
  d.id = "A-120";
  d.position = {10.0, 5.0};
  d.width = 1.0;
  d.heading = 0.0;
  d.swing = DoorSwing::Clockwise;
  d.angle = angle;
  d.rooms = {"hallway", "A-120"};
  spec.doors = {d};
  RobotSpec r = robot_spec("r1", Kinematics::Holonomic, 10.0, 8.0, -M_PI / 2);
  r.radius = 0.3;
  r.sensors.range = {8, 2 * M_PI, 10.0, 0.0};
  r.sensors.doors = {5.0, 0.0};
  spec.robots_at_start = {r};
  spec.command_timeout_s = 100.0;
  spec.seed = 5;
  return spec;
}

TEST(WorldDoors, RobotStopsAtAClosedDoorAndNeverPassesThrough) {
  World world(floor_with_door(0.0));
  ASSERT_TRUE(world.submit(command("r1", 0.0, -1.0, 0.0)).accepted);
  run(world, 100, 0.1);
  const RobotStatus r = *world.robot("r1");
  EXPECT_TRUE(r.in_collision);
  // Stopped at contact with the leaf (y = 5, half-thickness 0.025), within the contact precision.
  EXPECT_GE(r.pose.y, 5.0 + 0.025 + 0.3);
  EXPECT_NEAR(r.pose.y, 5.0 + 0.025 + 0.3, 1e-3);
}

TEST(WorldDoors, RobotPassesAnOpenDoor) {
  World world(floor_with_door(kOpen));
  ASSERT_TRUE(world.submit(command("r1", 0.0, -1.0, 0.0)).accepted);
  run(world, 60, 0.1);
  const RobotStatus r = *world.robot("r1");
  EXPECT_FALSE(r.in_collision);
  EXPECT_NEAR(r.pose.y, 2.0, 1e-9);
}

TEST(WorldDoors, ScriptedDoorClosesOnTimeUnlessARobotIsInTheWay) {
  WorldSpec spec = floor_with_door(kOpen);
  spec.doors[0].schedule.kind = DoorScheduleSpec::Kind::Script;
  spec.doors[0].schedule.script = {{1.0, 0.0}, {5.0, kOpen}, {6.0, 0.0}};
  spec.robots_at_start[0].start = {10.1, 4.4, 0.0};  // just inside the room, under the doorway
  World world(spec);
  run(world, 10, 0.1);  // t = 1.0: the door wants to close but r1 is in the sweep
  DoorStatus d = *world.door("A-120");
  EXPECT_DOUBLE_EQ(d.angle, kOpen);
  EXPECT_DOUBLE_EQ(d.target_angle, 0.0);
  EXPECT_TRUE(d.blocked);
  ASSERT_TRUE(world.submit(command("r1", 0.0, -1.0, 0.0)).accepted);
  run(world, 20, 0.1);  // r1 leaves the sweep (y < 5 - 1 - 0.325)
  ASSERT_TRUE(world.submit(command("r1", 0.0, 0.0, 0.0)).accepted);
  run(world, 1, 0.1);
  d = *world.door("A-120");
  EXPECT_TRUE(d.closed());
  EXPECT_FALSE(d.blocked);
  run(world, 19, 0.1);  // t = 5.0: open again
  EXPECT_DOUBLE_EQ(world.door("A-120")->angle, kOpen);
  run(world, 10, 0.1);  // t = 6.0: closed
  EXPECT_TRUE(world.door("A-120")->closed());
}

TEST(WorldDoors, SetDoorChecksIdAndAngle) {
  World world(floor_with_door(kOpen));
  EXPECT_EQ(world.set_door("A-999", 0.0).reason, "door A-999 unknown");
  EXPECT_EQ(world.set_door("A-120", 2.0).reason, "door A-120: angle 2.0 is outside [0, 1.5708]");
  EXPECT_TRUE(world.set_door("A-120", 0.0).accepted);
  EXPECT_TRUE(world.door("A-120")->closed());
}

TEST(WorldSensing, LineOfSightIsBlockedByWallsAndClosedDoors) {
  World world(floor_with_door(kOpen));
  EXPECT_TRUE(world.line_of_sight({10.0, 8.0}, {10.2, 2.0}));   // through the open doorway
  EXPECT_FALSE(world.line_of_sight({5.0, 8.0}, {5.0, 2.0}));    // through the wall
  EXPECT_FALSE(world.line_of_sight({10.4, 5.5}, {9.0, 4.5}));   // the open leaf stands at x = 9.5
  ASSERT_TRUE(world.set_door("A-120", 0.0).accepted);
  EXPECT_FALSE(world.line_of_sight({10.0, 8.0}, {10.2, 2.0}));  // the closed leaf
}

TEST(WorldSensing, RangeScanSeesWallsDoorsAndRobots) {
  WorldSpec spec = floor_with_door(0.0);
  RobotSpec other = robot_spec("r2", Kinematics::Holonomic, 14.0, 8.0);
  other.radius = 0.5;
  spec.robots_at_start.push_back(other);
  World world(spec);
  const auto scan = world.sense("r1");
  ASSERT_TRUE(scan.has_value());
  ASSERT_EQ(scan->ranges.size(), 8u);
  EXPECT_DOUBLE_EQ(scan->angle_min, -M_PI);
  EXPECT_DOUBLE_EQ(scan->angle_increment, M_PI / 4);
  // r1 faces -y (south). Ray 4 (angle 0) points south: the closed leaf at y = 5, 3 m away.
  EXPECT_NEAR(scan->ranges[4], 3.0, 1e-6);
  // Ray 0 (angle -pi) points north: the world boundary at y = 10, 2 m away.
  EXPECT_NEAR(scan->ranges[0], 2.0, 1e-6);
  // Ray 6 (angle +pi/2, counter-clockwise from south) points east: r2's disc at x = 13.5.
  EXPECT_NEAR(scan->ranges[6], 3.5, 1e-6);
  // Ray 2 points west: the boundary at x = 0 is 10 m away = max range: nothing within range.
  EXPECT_FLOAT_EQ(scan->ranges[2], 10.0f);
  ASSERT_TRUE(world.set_door("A-120", kOpen).accepted);
  EXPECT_NEAR(world.sense("r1")->ranges[4], 8.0, 1e-6);  // through the doorway to y = 0
}

TEST(WorldSensing, NoisyScansAreReproducibleFromTheSeed) {
  WorldSpec spec = floor_with_door(0.0);
  spec.robots_at_start[0].sensors.range.noise_stddev_m = 0.05;
  World a(spec), b(spec);
  const auto sa = a.sense("r1"), sb = b.sense("r1");
  EXPECT_EQ(sa->ranges, sb->ranges);
  EXPECT_NE(sa->ranges[4], 3.0f);
  EXPECT_NEAR(sa->ranges[4], 3.0, 0.3);
  spec.seed = 6;
  EXPECT_NE(World(spec).sense("r1")->ranges, sa->ranges);
}

TEST(WorldSensing, DoorIsObservedWithinRangeAndInSightOnly) {
  World world(floor_with_door(0.0));
  // r1 is 3 m from the doorway, sensor range 5 m: observed closed.
  auto seen = world.observe_doors("r1");
  ASSERT_EQ(seen.size(), 1u);
  EXPECT_EQ(seen[0].door_id, "A-120");
  EXPECT_DOUBLE_EQ(seen[0].angle_estimate, 0.0);
  EXPECT_DOUBLE_EQ(seen[0].distance_m, 3.0);
  EXPECT_NEAR(seen[0].bearing_rad, 0.0, 1e-12);  // straight ahead
  // Out of range.
  EXPECT_TRUE(world.observe_doors("r1", DoorSensorSpec{2.0, 0.0}).empty());
  // Behind the wall: from the south room far to the side, the wall hides the doorway.
  ASSERT_TRUE(world.spawn("r3", geometry::Pose2{2.0, 4.5, 0.0}).accepted);
  EXPECT_TRUE(world.observe_doors("r3", DoorSensorSpec{10.0, 0.0}).empty());
}

TEST(WorldSensing, DoorAngleEstimatesCarryGaussianNoise) {
  WorldSpec spec = floor_with_door(1.0);
  spec.robots_at_start[0].sensors.doors = {5.0, 0.1};
  World world(spec);
  double sum = 0.0, sum2 = 0.0;
  constexpr int kN = 4000;
  for (int i = 0; i < kN; ++i) {
    const auto seen = world.observe_doors("r1");
    ASSERT_EQ(seen.size(), 1u);
    sum += seen[0].angle_estimate;
    sum2 += seen[0].angle_estimate * seen[0].angle_estimate;
  }
  const double mean = sum / kN;
  EXPECT_NEAR(mean, 1.0, 0.01);
  EXPECT_NEAR(std::sqrt(sum2 / kN - mean * mean), 0.1, 0.01);
}

TEST(WorldSensing, PoseObservationIsExactWithoutNoise) {
  World world(floor_with_door(0.0));
  EXPECT_EQ(*world.observe_pose("r1"), world.robot("r1")->pose);
  EXPECT_FALSE(world.observe_pose("nobody").has_value());
}

TEST(WorldObstacles, RobotsCannotBePlacedOnPolygonsOrDoorLeaves) {
  WorldSpec spec = floor_with_door(0.0);
  spec.polygons = {{"pillar", {{2, 7}, {3, 7}, {2.5, 8}}}};
  World world(spec);
  EXPECT_EQ(world.spawn("x", geometry::Pose2{2.5, 7.3, 0}).reason, "robot x at (2.5, 7.3) overlaps polygon 0 'pillar'");
  EXPECT_EQ(world.spawn("y", geometry::Pose2{10.0, 5.2, 0}).reason, "robot y at (10.0, 5.2) overlaps door A-120");
}

}  // namespace
}  // namespace autonomy::sim
