// The blend's weighted sum, its clip to max speed, and the conversion to a velocity command.
#include "services/behavior/core/schemas/schema_blend.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace autonomy::behavior {
namespace {

using geometry::Vec2;

class Constant final : public MotorSchema {
 public:
  explicit Constant(Vec2 v) : v_(std::move(v)) {}
  geometry::Vec2 vote(const Perception&) const override { return v_; }
  std::string_view name() const override { return "constant"; }

 private:
  Vec2 v_;
};

Perception robot(double max_speed) {
  Perception p;
  p.limits = {max_speed, 2.0};
  return p;
}

TEST(SchemaBlend, WeightedSumScaledByMaxSpeed) {
  SchemaBlend blend;
  blend.add(std::make_unique<Constant>(Vec2(1.0, 0.0)), 0.66);
  blend.add(std::make_unique<Constant>(Vec2(0.0, 1.0)), 0.34);
  const BlendResult r = blend.blend(robot(2.0));
  EXPECT_NEAR(r.weighted_sum.x(), 0.66, 1e-12);
  EXPECT_NEAR(r.weighted_sum.y(), 0.34, 1e-12);
  EXPECT_NEAR(r.velocity.x(), 1.32, 1e-12);
  EXPECT_NEAR(r.velocity.y(), 0.68, 1e-12);
  EXPECT_FALSE(r.clipped);
  ASSERT_EQ(r.terms.size(), 2u);
  EXPECT_EQ(r.terms[0].name, "constant");
  EXPECT_DOUBLE_EQ(r.terms[1].gain, 0.34);
}

TEST(SchemaBlend, ClippedToMaxSpeed) {
  SchemaBlend blend;
  blend.add(std::make_unique<Constant>(Vec2(1.0, 0.0)), 1.0);
  blend.add(std::make_unique<Constant>(Vec2(0.6, 0.8)), 1.0);  // sum (1.6, 0.8)
  const BlendResult r = blend.blend(robot(1.5));
  EXPECT_TRUE(r.clipped);
  EXPECT_LE(r.velocity.norm(), 1.5);
  EXPECT_NEAR(r.velocity.norm(), 1.5, 1e-12);
  EXPECT_NEAR(r.velocity.y() / r.velocity.x(), 0.5, 1e-12);  // direction kept
}

TEST(SchemaBlend, ZeroGainIsReportedWithoutEffectAndBadGainsThrow) {
  SchemaBlend blend;
  blend.add(std::make_unique<Constant>(Vec2(1.0, 0.0)), 0.0);
  const BlendResult r = blend.blend(robot(1.0));
  EXPECT_EQ(r.velocity, Vec2::Zero());
  EXPECT_EQ(r.terms.size(), 1u);
  EXPECT_THROW(blend.add(std::make_unique<Constant>(Vec2(1.0, 0.0)), -0.1), std::invalid_argument);
  EXPECT_THROW(blend.add(std::make_unique<Constant>(Vec2(1.0, 0.0)), NAN), std::invalid_argument);
  EXPECT_THROW(blend.add(nullptr, 1.0), std::invalid_argument);
}

TEST(ToVelocityCommand, HolonomicWorldFrameWithinLimit) {
  const MotionLimits limits{1.0, 2.0};
  const VelocityCommand a = to_velocity_command({0.3, -0.4}, {0, 0, 1.0}, Kinematics::Holonomic, limits);
  EXPECT_DOUBLE_EQ(a.vx, 0.3);
  EXPECT_DOUBLE_EQ(a.vy, -0.4);
  EXPECT_DOUBLE_EQ(a.omega, 0.0);
  const VelocityCommand b = to_velocity_command({3.0, 4.0}, {}, Kinematics::Holonomic, limits);
  EXPECT_NEAR(b.vx, 0.6, 1e-12);
  EXPECT_NEAR(b.vy, 0.8, 1e-12);
  EXPECT_TRUE(to_velocity_command({0.0, 0.0}, {}, Kinematics::Holonomic, limits).is_zero());
}

TEST(ToVelocityCommand, UnicycleFollowsGoToControllerConventions) {
  const MotionLimits limits{1.0, 2.0};
  // Aligned: straight ahead, no turn.
  const VelocityCommand ahead = to_velocity_command({0.5, 0.0}, {0, 0, 0}, Kinematics::Unicycle, limits);
  EXPECT_DOUBLE_EQ(ahead.vx, 0.5);
  EXPECT_DOUBLE_EQ(ahead.vy, 0.0);
  EXPECT_DOUBLE_EQ(ahead.omega, 0.0);
  // 0.2 rad off: omega = 3 * 0.2, speed scaled by 1 - 0.2 / 0.6.
  const VelocityCommand off =
      to_velocity_command({std::cos(0.2), std::sin(0.2)}, {0, 0, 0}, Kinematics::Unicycle, limits);
  EXPECT_NEAR(off.omega, 0.6, 1e-12);
  EXPECT_NEAR(off.vx, 1.0 - 0.2 / 0.6, 1e-12);
  // Beyond turn_in_place_rad: turn in place at the clipped rate.
  const VelocityCommand left = to_velocity_command({0.0, 1.0}, {0, 0, 0}, Kinematics::Unicycle, limits);
  EXPECT_DOUBLE_EQ(left.vx, 0.0);
  EXPECT_DOUBLE_EQ(left.omega, 2.0);
}

}  // namespace
}  // namespace autonomy::behavior
