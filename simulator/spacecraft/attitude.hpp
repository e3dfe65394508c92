#pragma once
// Attitude control: the spacecraft's orientation, turns towards a target at the control mode's
// maximum rate about the eigen-axis (the shortest rotation), and which control modes can turn
// at all (a mode that needs a thruster stuck closed cannot).
#include "simulator/spacecraft/spacecraft_spec.hpp"

#include <Eigen/Geometry>

#include <optional>
#include <set>
#include <string>

namespace autonomy::sim::spacecraft {

class Attitude {
 public:
  // `spec` and `targets` are checked by the Spacecraft (initial target and mode exist).
  Attitude(const AttitudeSpec& spec, const std::vector<TargetSpec>& targets);

  const Eigen::Quaterniond& orientation() const { return q_; }
  Eigen::Vector3d boresight() const { return q_ * Eigen::Vector3d::UnitZ(); }
  bool turning() const { return turn_.has_value(); }
  const std::string& pointing_target() const { return pointing_; }  // empty while turning
  std::string turn_target() const { return turn_ ? turn_->target : std::string(); }
  double remaining_deg() const;
  const std::string& control_mode() const { return mode_; }
  double last_rate_deg_s() const { return last_rate_deg_s_; }
  // Angle between the boresight and the target pointed at (or turned to), degrees.
  double pointing_error_deg() const;
  double angle_to_deg(const std::string& target) const;

  bool knows_target(const std::string& target) const;
  bool knows_mode(const std::string& mode) const;
  // The mode can turn: none of its actuators is in `stuck`.
  bool mode_usable(const std::string& mode, const std::set<std::string>& stuck) const;

  // Starts a turn to `target` (known); a target already within tolerance ends at once.
  void turn_to(const std::string& target);
  void set_mode(const std::string& mode) { mode_ = mode; }
  // Stops a turn under way where it is (fault protection holds attitude); false when none was.
  bool hold();
  // Turns by at most the mode's rate times dt (none when the mode is not usable).
  void step(double dt_s, const std::set<std::string>& stuck);

 private:
  struct Turn {
    std::string target;
    Eigen::Vector3d axis;  // inertial frame, unit
    double remaining_rad;
  };
  const ControlModeSpec* mode_spec(const std::string& mode) const;
  Eigen::Vector3d direction(const std::string& target) const;

  AttitudeSpec spec_;
  std::vector<TargetSpec> targets_;  // directions normalised
  Eigen::Quaterniond q_ = Eigen::Quaterniond::Identity();
  std::string pointing_;
  std::string mode_;
  std::optional<Turn> turn_;
  double last_rate_deg_s_ = 0.0;
};

}  // namespace autonomy::sim::spacecraft
