#include "services/behavior/core/door_knowledge.hpp"

#include <cmath>
#include <stdexcept>

namespace autonomy::behavior {

namespace {

bool positive_finite_door(double v) { return std::isfinite(v) && v > 0.0; }

}  // namespace

DoorKnowledge::DoorKnowledge(DoorKnowledgeSettings settings) : settings_(settings) {
  if (!positive_finite_door(settings_.closed_below_rad) || !positive_finite_door(settings_.memory_s) ||
      !positive_finite_door(settings_.thickness_m) || !std::isfinite(settings_.open_above_rad) ||
      settings_.open_above_rad < settings_.closed_below_rad) {
    throw std::invalid_argument("door knowledge settings must be positive and finite, open_above >= closed_below");
  }
}

bool DoorKnowledge::update(const std::vector<DoorSighting>& sightings, double now_s, const WorldMap& map) {
  const std::vector<std::string> before = closed();
  for (const DoorSighting& s : sightings) {
    bool known = false;
    for (const Doorway& d : map.doors) known = known || d.id == s.door_id;
    if (!known || !std::isfinite(s.angle_estimate)) continue;
    const double opening = std::fabs(s.angle_estimate);
    if (opening < settings_.closed_below_rad)
      closed_since_[s.door_id] = now_s;
    else if (opening > settings_.open_above_rad)
      closed_since_.erase(s.door_id);
    else if (const auto it = closed_since_.find(s.door_id); it != closed_since_.end())
      it->second = now_s;  // between the thresholds: still closed, and seen so
  }
  for (auto it = closed_since_.begin(); it != closed_since_.end();) {
    if (now_s - it->second > settings_.memory_s)
      it = closed_since_.erase(it);
    else
      ++it;
  }
  return closed() != before;
}

std::vector<std::string> DoorKnowledge::closed() const {
  std::vector<std::string> out;
  for (const auto& [id, since] : closed_since_) out.push_back(id);
  return out;
}

WorldMap DoorKnowledge::apply(const WorldMap& map) const {
  WorldMap out = map;
  for (const Doorway& d : map.doors) {
    if (!believed_closed(d.id)) continue;
    const geometry::Vec2 along(std::cos(d.heading), std::sin(d.heading));
    const geometry::Vec2 across(-along.y(), along.x());
    const geometry::Vec2 a = along * (d.width_m / 2.0);
    const geometry::Vec2 t = across * (settings_.thickness_m / 2.0);
    out.polygons.push_back({"door " + d.id, {d.centre - a - t, d.centre + a - t, d.centre + a + t, d.centre - a + t}});
  }
  return out;
}

std::string describe_closed_doors(const std::vector<std::string>& ids) {
  if (ids.empty()) return "no door closed";
  std::string out = ids.size() == 1 ? "door " : "doors ";
  for (std::size_t i = 0; i < ids.size(); ++i) out += (i ? ", " : "") + ids[i];
  return out + " closed";
}

}  // namespace autonomy::behavior
