#pragma once
// Spacecraft fault protection's command-loss timer, as real spacecraft carry one: the commander
// (the executive) shows it is alive by commands, heartbeats and lockstep acks; when none came for
// `commander_timeout_s` of simulated time the spacecraft safes itself, and the next sign of the
// commander ends safe mode. Pure bookkeeping on simulated seconds: the Spacecraft decides what
// the safe configuration is, the node decides which samples are signs of the commander.
#include "simulator/spacecraft/spacecraft_spec.hpp"

#include <cstdint>
#include <optional>
#include <string>

namespace autonomy::sim::spacecraft {

class CommandLossTimer {
 public:
  explicit CommandLossTimer(FaultProtectionSpec spec) : spec_(std::move(spec)) {}

  bool enabled() const { return spec_.commander_timeout_s > 0.0; }
  const FaultProtectionSpec& spec() const { return spec_; }

  // A sign of the commander at time t_s. Returns true when it ended safe mode.
  bool heard(double t_s);
  // The commander has been silent for the timeout at t_s and the spacecraft is not safed yet.
  bool due(double t_s) const;
  // The spacecraft safed itself at t_s for `reason`.
  void safed(double t_s, std::string reason);

  bool safe_mode() const { return safe_mode_; }
  const std::string& reason() const { return reason_; }
  std::optional<double> safed_at_s() const { return safed_at_s_; }
  std::uint32_t safings() const { return safings_; }
  double silent_s(double t_s) const { return t_s - last_heard_s_; }

 private:
  FaultProtectionSpec spec_;
  double last_heard_s_ = 0.0;  // the run's start counts as heard: a commander gets its timeout
  bool safe_mode_ = false;
  std::string reason_;
  std::optional<double> safed_at_s_;
  std::uint32_t safings_ = 0;
};

}  // namespace autonomy::sim::spacecraft
