#include "simulator/core/motion.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace autonomy::sim {
namespace {

TEST(Motion, HolonomicMovesInTheWorldFrameWhateverTheHeading) {
  const geometry::Pose2 end = advance({1.0, 1.0, 2.0}, Kinematics::Holonomic, {0.5, -0.25, 0.1}, 2.0);
  EXPECT_DOUBLE_EQ(end.x, 2.0);
  EXPECT_DOUBLE_EQ(end.y, 0.5);
  EXPECT_DOUBLE_EQ(end.theta, 2.2);
}

TEST(Motion, UnicycleDrivesAQuarterCircle) {
  // 1 m/s at pi/2 rad/s for 1 s: a quarter of a circle of radius 2/pi, turning left.
  const geometry::Pose2 end = advance({0.0, 0.0, 0.0}, Kinematics::Unicycle, {1.0, 0.0, M_PI / 2}, 1.0);
  EXPECT_NEAR(end.x, 2.0 / M_PI, 1e-12);
  EXPECT_NEAR(end.y, 2.0 / M_PI, 1e-12);
  EXPECT_NEAR(end.theta, M_PI / 2, 1e-12);
}

TEST(Motion, UnicycleWithoutTurnDrivesAlongItsHeading) {
  const geometry::Pose2 end = advance({1.0, 2.0, M_PI / 2}, Kinematics::Unicycle, {0.5, 0.0, 0.0}, 4.0);
  EXPECT_NEAR(end.x, 1.0, 1e-12);
  EXPECT_NEAR(end.y, 4.0, 1e-12);
}

TEST(Motion, ArcIsIndependentOfStepSize) {
  const Velocity v{0.8, 0.0, 1.3};
  geometry::Pose2 stepped{3.0, 4.0, 0.5};
  for (int i = 0; i < 100; ++i) stepped = advance(stepped, Kinematics::Unicycle, v, 0.01);
  const geometry::Pose2 once = advance({3.0, 4.0, 0.5}, Kinematics::Unicycle, v, 1.0);
  EXPECT_NEAR(stepped.x, once.x, 1e-12);
  EXPECT_NEAR(stepped.y, once.y, 1e-12);
  EXPECT_NEAR(stepped.theta, once.theta, 1e-12);
}

TEST(Motion, PathLengthIsSpeedTimesTime) {
  EXPECT_DOUBLE_EQ(path_length(Kinematics::Holonomic, {0.3, 0.4, 0.0}, 2.0), 1.0);
  EXPECT_DOUBLE_EQ(path_length(Kinematics::Unicycle, {-0.5, 0.0, 1.0}, 2.0), 1.0);
}

}  // namespace
}  // namespace autonomy::sim
