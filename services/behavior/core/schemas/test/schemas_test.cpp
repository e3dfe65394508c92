// Each motor schema's vote, asserted numerically against hand-computed values.
#include "services/behavior/core/schemas/avoid_obstacles.hpp"
#include "services/behavior/core/schemas/move_to_goal.hpp"
#include "services/behavior/core/schemas/noise.hpp"
#include "services/behavior/core/schemas/teammate_schemas.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace autonomy::behavior {
namespace {

using geometry::Vec2;

Perception at(double x, double y, double theta = 0.0) {
  Perception p;
  p.pose = {x, y, theta};
  p.limits = {1.0, 2.0};
  return p;
}

void expect_vec(const Vec2& v, double x, double y) {
  EXPECT_NEAR(v.x(), x, 1e-12);
  EXPECT_NEAR(v.y(), y, 1e-12);
}

TEST(MoveToGoal, UnitVectorTowardsTheGoalFarAway) {
  const MoveToGoal schema({2.0});
  Perception p = at(0.0, 0.0);
  p.goal = Vec2(4.0, 3.0);  // d = 5
  expect_vec(schema.vote(p), 0.8, 0.6);
}

TEST(MoveToGoal, MagnitudeRampsDownInsideTheSlowdownRadius) {
  const MoveToGoal schema({2.0});
  Perception p = at(1.0, 1.0);
  p.goal = Vec2(1.0, 2.0);  // d = 1 of 2
  expect_vec(schema.vote(p), 0.0, 0.5);
  p.goal = Vec2(1.0, 1.0);
  expect_vec(schema.vote(p), 0.0, 0.0);
}

TEST(MoveToGoal, NoGoalNoVote) {
  expect_vec(MoveToGoal().vote(at(3.0, 4.0)), 0.0, 0.0);
  EXPECT_THROW(MoveToGoal({0.0}), std::invalid_argument);
}

TEST(AvoidObstacles, ArkinProfile) {
  const AvoidObstacles schema({3.0, 0.5, 10.0, 10.0});
  EXPECT_DOUBLE_EQ(schema.magnitude(3.5), 0.0);
  EXPECT_DOUBLE_EQ(schema.magnitude(3.0), 0.0);
  EXPECT_DOUBLE_EQ(schema.magnitude(2.0), 0.4);   // (3 - 2) / (3 - 0.5)
  EXPECT_DOUBLE_EQ(schema.magnitude(0.75), 0.9);  // (3 - 0.75) / 2.5
  EXPECT_DOUBLE_EQ(schema.magnitude(0.5), 10.0);  // at the margin: "infinite"
  EXPECT_DOUBLE_EQ(schema.magnitude(0.1), 10.0);
}

TEST(AvoidObstacles, RepulsionFromEachHitInTheBodyFrame) {
  const AvoidObstacles schema({3.0, 0.5, 10.0, 10.0});
  Perception p = at(5.0, 5.0, M_PI / 2);  // facing +y
  p.rays = {
      {0.0, 2.0, 10.0},         // ahead (+y), 0.4 -> pushes towards -y
      {M_PI / 2, 1.75, 10.0},   // left (-x), 0.5 -> pushes towards +x
      {M_PI, 10.0, 10.0},       // behind: saw nothing
      {-M_PI / 2, 5.0, 10.0},   // right, beyond the sphere of influence
  };
  expect_vec(schema.vote(p), 0.5, -0.4);
}

TEST(AvoidObstacles, SumIsClippedToMaxMagnitude) {
  const AvoidObstacles schema({3.0, 0.5, 10.0, 12.0});
  Perception p = at(0.0, 0.0);
  p.rays = {{0.0, 0.2, 5.0}, {0.0, 0.3, 5.0}};  // both inside the margin: 20 towards -x
  expect_vec(schema.vote(p), -12.0, 0.0);
  EXPECT_THROW(AvoidObstacles({1.0, 1.0, 1.0, 1.0}), std::invalid_argument);  // R must be < S
}

TEST(Noise, DirectionHeldForThePersistenceTime) {
  const Noise noise({2.0, 7});
  Perception p = at(0.0, 0.0);
  p.time_s = 0.1;
  const Vec2 first = noise.vote(p);
  EXPECT_NEAR(first.norm(), 1.0, 1e-12);
  p.time_s = 1.99;
  EXPECT_EQ(noise.vote(p), first);
  p.time_s = 2.0;  // next epoch
  const Vec2 second = noise.vote(p);
  EXPECT_NE(second, first);
  EXPECT_NEAR(second.norm(), 1.0, 1e-12);
  const double a = noise.direction(1);
  expect_vec(second, std::cos(a), std::sin(a));
}

TEST(Noise, DeterministicPerSeedAndIndependentOfCallHistory) {
  const Noise a({1.0, 42});
  const Noise b({1.0, 42});
  const Noise c({1.0, 43});
  Perception p = at(0.0, 0.0);
  p.time_s = 5.5;
  const Vec2 va = a.vote(p);
  for (double t : {0.0, 1.0, 9.0}) {
    Perception q = p;
    q.time_s = t;
    (void)b.vote(q);
  }
  EXPECT_EQ(b.vote(p), va);
  EXPECT_NE(c.vote(p), va);
  EXPECT_THROW(Noise({0.0, 1}), std::invalid_argument);
}

TEST(AvoidTeammates, PushesAwayFromNearTeammatesOnly) {
  const AvoidTeammates schema({3.0, 0.5, 10.0, 10.0});
  Perception p = at(0.0, 0.0);
  p.teammates = {{"r2", Vec2(1.0, 0.0), true},      // 0.8 away
                 {"r3", Vec2(0.0, 10.0), true},     // out of range
                 {"r4", std::nullopt, false}};      // never heard
  expect_vec(schema.vote(p), -0.8, 0.0);
}

TEST(StayNearTeammates, PullsTowardsTheCentroidBeyondTheComfortRadius) {
  const StayNearTeammates schema({10.0, 30.0});
  Perception p = at(0.0, 0.0);
  p.teammates = {{"r2", Vec2(20.0, 0.0), true}};
  expect_vec(schema.vote(p), 0.5, 0.0);  // (20 - 10) / (30 - 10)
  p.teammates.push_back({"r3", Vec2(40.0, 0.0), false});  // centroid (30, 0)
  expect_vec(schema.vote(p), 1.0, 0.0);
  p.teammates = {{"r2", Vec2(0.0, 6.0), true}};
  expect_vec(schema.vote(p), 0.0, 0.0);
  EXPECT_THROW(StayNearTeammates({5.0, 5.0}), std::invalid_argument);
}

}  // namespace
}  // namespace autonomy::behavior
