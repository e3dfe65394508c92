// Door geometry and schedules.
#include "simulator/core/door.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace autonomy::sim {
namespace {

// A 1 m door in a wall along y = 5, doorway x in [4, 5], hinge at x = 4, opening clockwise (into
// the room below the wall).
DoorSpec door_in_wall() {
  DoorSpec d;
  d.id = "A-120";
  d.position = {4.5, 5.0};
  d.width = 1.0;
  d.heading = 0.0;
  d.swing = DoorSwing::Clockwise;
  return d;
}

TEST(Door, LeafLiesAcrossTheDoorwayWhenClosedAndAlongTheJambWhenOpen) {
  const DoorSpec d = door_in_wall();
  const DoorLeaf closed = d.leaf(0.0);
  EXPECT_NEAR(closed.hinge.x(), 4.0, 1e-12);
  EXPECT_NEAR(closed.tip.x(), 5.0, 1e-12);
  EXPECT_NEAR(closed.tip.y(), 5.0, 1e-12);
  const DoorLeaf open = d.leaf(M_PI / 2);
  EXPECT_NEAR(open.tip.x(), 4.0, 1e-12);
  EXPECT_NEAR(open.tip.y(), 4.0, 1e-12);  // clockwise: into the room below
}

TEST(Door, SweepCoversTheSectorBetweenTwoAngles) {
  const DoorSpec d = door_in_wall();
  // A robot just inside the room in front of the doorway is in the way of closing from open.
  EXPECT_TRUE(disc_in_sweep(d, M_PI / 2, 0.0, {4.6, 4.4}, 0.2));
  // Beyond the leaf's reach it is not.
  EXPECT_FALSE(disc_in_sweep(d, M_PI / 2, 0.0, {4.5, 3.2}, 0.2));
  // On the hallway side (above the wall) the leaf never goes.
  EXPECT_FALSE(disc_in_sweep(d, M_PI / 2, 0.0, {4.5, 5.6}, 0.3));
}

TEST(Door, ProblemsAreNamed) {
  DoorSpec d = door_in_wall();
  d.width = 0.0;
  EXPECT_EQ(door_problem(d), "width must be positive (got 0.0)");
  d = door_in_wall();
  d.angle = 2.0;
  EXPECT_EQ(door_problem(d), "angle 2.0 is outside [0, max_angle 1.5708]");
}

TEST(DoorSchedule, ScriptEventsApplyAtTheFirstStepEndingAtOrAfterTheirTime) {
  DoorScheduleSpec spec;
  spec.kind = DoorScheduleSpec::Kind::Script;
  spec.script = {{10.0, 0.0}, {30.0, 1.2}, {30.5, 1.5}};
  DoorSchedule s(spec, M_PI / 2, Rng(1));
  EXPECT_EQ(s.advance(9.9), std::nullopt);
  EXPECT_EQ(s.advance(10.0), 0.0);
  EXPECT_EQ(s.advance(20.0), std::nullopt);
  EXPECT_EQ(s.advance(31.0), 1.5);  // two events in one step: the last wins
  EXPECT_EQ(s.advance(100.0), std::nullopt);
}

TEST(DoorSchedule, RandomProcessIsSeededAndFollowsItsRates) {
  DoorScheduleSpec spec;
  spec.kind = DoorScheduleSpec::Kind::Random;
  spec.random = {1.0 / 60.0, 1.0 / 20.0, 1.4};  // open for 60 s, closed for 20 s on average
  DoorSchedule a(spec, 1.4, Rng::stream(9, "door/d"));
  DoorSchedule b(spec, 1.4, Rng::stream(9, "door/d"));
  double open_time = 0.0;
  bool open = true;
  constexpr double kDt = 0.5;
  constexpr int kSteps = 400000;  // 200000 s
  for (int i = 1; i <= kSteps; ++i) {
    const auto x = a.advance(i * kDt);
    ASSERT_EQ(x, b.advance(i * kDt));
    if (x) {
      EXPECT_TRUE(*x == 0.0 || *x == 1.4);
      open = *x > 0.0;
    }
    if (open) open_time += kDt;
  }
  EXPECT_NEAR(open_time / (kSteps * kDt), 60.0 / 80.0, 0.02);  // stationary share of "open"
}

}  // namespace
}  // namespace autonomy::sim
