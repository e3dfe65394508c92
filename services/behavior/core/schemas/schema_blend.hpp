#pragma once
// The motor-schema controller's output stage (Arkin 1989): each active schema votes, each vote is
// multiplied by its gain, the weighted votes are summed, and the sum becomes a velocity:
//   desired = limits.max_speed_mps * sum_i (gain_i * vote_i),  then clipped to |desired| <= max speed.
// Votes are dimensionless (1 = full strength), so a gain of 1 on a lone move-to-goal drives at
// full speed, and the paper's 0.66 reactive : 0.34 plan split is literally two gains.
//
// to_velocity_command() turns the desired world-frame vector into a VelocityCommand with the same
// conventions as GoToController: holonomic robots get (vx, vy) in the world frame and omega = 0;
// unicycles turn towards the vector at heading_gain * error (clipped to max omega) and drive
// forward at |desired| * (1 - |error| / turn_in_place_rad), i.e. they turn in place above that
// error. A zero vector gives a zero command.
#include "common/geometry/geometry.hpp"
#include "services/behavior/core/schemas/motor_schema.hpp"
#include "services/behavior/core/velocity_command.hpp"

#include <memory>
#include <string_view>
#include <vector>

namespace autonomy::behavior {

struct SchemaTerm {
  std::string_view name;  // the schema's name(); valid while the blend lives
  double gain = 0.0;
  geometry::Vec2 vote = geometry::Vec2::Zero();  // before the gain
};

struct BlendResult {
  geometry::Vec2 velocity = geometry::Vec2::Zero();  // world frame, m/s, within max speed
  geometry::Vec2 weighted_sum = geometry::Vec2::Zero();  // sum of gain * vote, dimensionless
  bool clipped = false;                                  // the sum asked for more than max speed
  std::vector<SchemaTerm> terms;                         // in the order the schemas were added
};

class SchemaBlend {
 public:
  // Throws std::invalid_argument on a null schema or a negative or non-finite gain. A zero gain is
  // allowed (the schema is reported but has no effect).
  void add(std::unique_ptr<MotorSchema> schema, double gain);

  [[nodiscard]] BlendResult blend(const Perception& p) const;

  std::size_t size() const { return entries_.size(); }
  bool empty() const { return entries_.empty(); }

 private:
  struct Entry {
    std::unique_ptr<MotorSchema> schema;
    double gain;
  };
  std::vector<Entry> entries_;
};

struct UnicycleSteering {
  double heading_gain = 3.0;       // rad/s per rad, as GoToConfig
  double turn_in_place_rad = 0.6;  // as GoToConfig
};

[[nodiscard]] VelocityCommand to_velocity_command(const geometry::Vec2& desired_world,
                                                  const geometry::Pose2& pose,
                                                  Kinematics kinematics,
                                                  const MotionLimits& limits,
                                                  const UnicycleSteering& steering = {});

}  // namespace autonomy::behavior
