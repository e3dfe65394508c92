#include "services/behavior/core/schemas/schema_blend.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace autonomy::behavior {

void SchemaBlend::add(std::unique_ptr<MotorSchema> schema, double gain) {
  if (!schema) throw std::invalid_argument("schema blend: null schema");
  if (!(std::isfinite(gain) && gain >= 0.0)) {
    throw std::invalid_argument("schema blend: gain of " + std::string(schema->name()) +
                                " must be finite and >= 0");
  }
  entries_.push_back({std::move(schema), gain});
}

BlendResult SchemaBlend::blend(const Perception& p) const {
  BlendResult r;
  r.terms.reserve(entries_.size());
  for (const Entry& e : entries_) {
    const geometry::Vec2 v = e.gain != 0.0 ? e.schema->vote(p) : geometry::Vec2::Zero();
    assert(std::isfinite(v.x()) && std::isfinite(v.y()) && "motor schemas vote finite vectors");
    r.terms.push_back({e.schema->name(), e.gain, v});
    r.weighted_sum += e.gain * v;
  }
  const double max_speed = std::max(0.0, p.limits.max_speed_mps);
  r.velocity = r.weighted_sum * max_speed;
  const double n = r.velocity.norm();
  if (n > max_speed) {
    r.clipped = true;
    r.velocity *= max_speed / n;
    // Rounding can leave |v| a few ulps above the limit; the limit is a contract.
    if (r.velocity.norm() > max_speed) r.velocity *= std::nextafter(1.0, 0.0);
  }
  return r;
}

VelocityCommand to_velocity_command(const geometry::Vec2& desired_world, const geometry::Pose2& pose,
                                    Kinematics kinematics, const MotionLimits& limits,
                                    const UnicycleSteering& steering) {
  VelocityCommand cmd;
  const double speed = std::min(desired_world.norm(), std::max(0.0, limits.max_speed_mps));
  if (!(speed > 0.0) || !std::isfinite(speed)) return cmd;
  if (kinematics == Kinematics::Holonomic) {
    const geometry::Vec2 v = desired_world * (speed / desired_world.norm());
    cmd.vx = v.x();
    cmd.vy = v.y();
    return cmd;
  }
  const double error =
      geometry::wrap_angle(std::atan2(desired_world.y(), desired_world.x()) - pose.theta);
  cmd.omega = std::clamp(steering.heading_gain * error, -limits.max_omega_rps, limits.max_omega_rps);
  const double alignment = 1.0 - std::abs(error) / steering.turn_in_place_rad;
  cmd.vx = alignment > 0.0 ? speed * alignment : 0.0;
  return cmd;
}

}  // namespace autonomy::behavior
