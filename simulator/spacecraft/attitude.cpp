#include "simulator/spacecraft/attitude.hpp"

#include <algorithm>
#include <cmath>

namespace autonomy::sim::spacecraft {
namespace {

constexpr double kDegPerRad = 180.0 / M_PI;

double angle_between(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  // atan2 of |a x b| and a . b stays accurate near 0 and pi, where acos does not.
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

}  // namespace

Attitude::Attitude(const AttitudeSpec& spec, const std::vector<TargetSpec>& targets)
    : spec_(spec), targets_(targets), mode_(spec.control_mode) {
  for (TargetSpec& t : targets_) t.direction.normalize();
  if (knows_target(spec.initial_target)) {
    q_ = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(),
                                            direction(spec.initial_target));
    pointing_ = spec.initial_target;
  }
}

bool Attitude::knows_target(const std::string& target) const {
  return std::any_of(targets_.begin(), targets_.end(),
                     [&](const TargetSpec& t) { return t.name == target; });
}

bool Attitude::knows_mode(const std::string& mode) const {
  return mode_spec(mode) != nullptr;
}

const ControlModeSpec* Attitude::mode_spec(const std::string& mode) const {
  for (const ControlModeSpec& m : spec_.modes)
    if (m.name == mode) return &m;
  return nullptr;
}

Eigen::Vector3d Attitude::direction(const std::string& target) const {
  for (const TargetSpec& t : targets_)
    if (t.name == target) return t.direction;
  return Eigen::Vector3d::UnitZ();
}

bool Attitude::mode_usable(const std::string& mode, const std::set<std::string>& stuck) const {
  const ControlModeSpec* m = mode_spec(mode);
  if (!m) return false;
  return std::none_of(m->actuators.begin(), m->actuators.end(),
                      [&](const std::string& a) { return stuck.count(a) > 0; });
}

double Attitude::remaining_deg() const {
  return turn_ ? turn_->remaining_rad * kDegPerRad : 0.0;
}

double Attitude::angle_to_deg(const std::string& target) const {
  return angle_between(boresight(), direction(target)) * kDegPerRad;
}

double Attitude::pointing_error_deg() const {
  const std::string& target = turn_ ? turn_->target : pointing_;
  return target.empty() ? 0.0 : angle_to_deg(target);
}

void Attitude::turn_to(const std::string& target) {
  const Eigen::Vector3d from = boresight();
  const Eigen::Vector3d to = direction(target);
  const double angle = angle_between(from, to);
  if (angle < 1e-9) {  // already there: nothing to turn
    turn_.reset();
    pointing_ = target;
    return;
  }
  Eigen::Vector3d axis = from.cross(to);
  if (axis.norm() < 1e-12) {
    // Opposite directions: any axis perpendicular to the boresight is a shortest rotation.
    axis =
        from.cross(std::abs(from.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY());
  }
  turn_ = Turn{target, axis.normalized(), angle};
  pointing_.clear();
}

bool Attitude::hold() {
  if (!turn_) return false;
  turn_.reset();  // pointing at no target: the boresight stays where the turn left it
  return true;
}

void Attitude::step(double dt_s, const std::set<std::string>& stuck) {
  last_rate_deg_s_ = 0.0;
  if (!turn_) return;
  const ControlModeSpec* m = mode_spec(mode_);
  if (!m || !mode_usable(mode_, stuck)) return;  // no torque about the failed thruster's axis
  const double max_step = m->max_rate_deg_s / kDegPerRad * dt_s;
  // A remainder below a nano-radian is rounding, not a further step.
  const bool last = turn_->remaining_rad <= max_step + 1e-9;
  const double delta = last ? turn_->remaining_rad : max_step;
  q_ = (Eigen::Quaterniond(Eigen::AngleAxisd(delta, turn_->axis)) * q_).normalized();
  last_rate_deg_s_ = delta * kDegPerRad / dt_s;
  turn_->remaining_rad -= delta;
  if (last) {
    pointing_ = turn_->target;
    turn_.reset();
  }
}

}  // namespace autonomy::sim::spacecraft
