#include "simulator/spacecraft/fault_protection.hpp"

namespace autonomy::sim::spacecraft {

bool CommandLossTimer::heard(double t_s) {
  last_heard_s_ = t_s;
  if (!safe_mode_) return false;
  safe_mode_ = false;
  return true;
}

bool CommandLossTimer::due(double t_s) const {
  // A hair of tolerance: 600 one-second steps must reach 600 s, not 599.9999999.
  return enabled() && !safe_mode_ && silent_s(t_s) >= spec_.commander_timeout_s - 1e-9;
}

void CommandLossTimer::safed(double t_s, std::string reason) {
  safe_mode_ = true;
  reason_ = std::move(reason);
  safed_at_s_ = t_s;
  ++safings_;
}

}  // namespace autonomy::sim::spacecraft
