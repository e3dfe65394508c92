#include "services/courier/core/execution/door_belief.hpp"

#include <cmath>
#include <stdexcept>

namespace autonomy::courier {

DoorBelief::DoorBelief(DoorBeliefSettings settings) : settings_(settings) {
  if (!std::isfinite(settings.closed_below_rad) || !std::isfinite(settings.open_above_rad) ||
      settings.closed_below_rad < 0.0 || settings.open_above_rad <= settings.closed_below_rad)
    throw std::invalid_argument("door belief: need 0 <= closed_below_rad < open_above_rad");
}

DoorChange DoorBelief::observe(const std::string& door_id, double angle_rad, double now_s, const std::string& robot) {
  if (!std::isfinite(angle_rad) || !std::isfinite(now_s)) return DoorChange::none;
  const double opening = std::fabs(angle_rad);
  auto [it, inserted] = doors_.try_emplace(door_id);
  DoorView& v = it->second;
  const bool was_open = inserted ? true : v.open;
  if (was_open && opening < settings_.closed_below_rad) v.open = false;
  if (!was_open && opening > settings_.open_above_rad) v.open = true;
  v.angle_rad = angle_rad;
  v.seen_at_s = now_s;
  v.seen_by = robot;
  v.open_assumed = false;
  if (was_open == v.open) return DoorChange::none;
  return v.open ? DoorChange::opened : DoorChange::closed;
}

std::vector<std::string> DoorBelief::expire_closed(double before_s) {
  std::vector<std::string> expired;
  for (auto& [id, v] : doors_)
    if (!v.open && v.seen_at_s < before_s) {
      v.open = true;
      v.open_assumed = true;
      expired.push_back(id);
    }
  return expired;
}

bool DoorBelief::believed_open(const std::string& door_id) const {
  const auto it = doors_.find(door_id);
  return it == doors_.end() || it->second.open;
}

std::optional<DoorView> DoorBelief::view(const std::string& door_id) const {
  const auto it = doors_.find(door_id);
  if (it == doors_.end()) return std::nullopt;
  return it->second;
}

}  // namespace autonomy::courier
