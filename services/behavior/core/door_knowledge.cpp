#include "services/behavior/core/door_knowledge.hpp"

#include <cmath>
#include <stdexcept>

namespace autonomy::behavior {

namespace {

bool positive_finite_door(double v) { return std::isfinite(v) && v > 0.0; }

}  // namespace

DoorKnowledge::DoorKnowledge(DoorKnowledgeSettings settings) : settings_(settings) {
  if (!positive_finite_door(settings_.closed_below_rad) || !positive_finite_door(settings_.memory_s) ||
      !positive_finite_door(settings_.thickness_m) || !positive_finite_door(settings_.leaf_thickness_m) ||
      !positive_finite_door(settings_.leaf_moved_rad) || !std::isfinite(settings_.leaf_tip_margin_m) ||
      settings_.leaf_tip_margin_m < 0.0 || !std::isfinite(settings_.open_above_rad) ||
      settings_.open_above_rad < settings_.closed_below_rad) {
    throw std::invalid_argument("door knowledge settings must be positive and finite, open_above >= closed_below");
  }
}

bool DoorKnowledge::update(const std::vector<DoorSighting>& sightings, double now_s, const WorldMap& map) {
  const std::vector<std::string> before = closed();
  bool leaf_moved = false;
  for (const DoorSighting& s : sightings) {
    const Doorway* door = nullptr;
    for (const Doorway& d : map.doors)
      if (d.id == s.door_id) door = &d;
    if (door == nullptr || !std::isfinite(s.angle_estimate)) continue;
    const double opening = std::fabs(s.angle_estimate);
    if (opening >= settings_.closed_below_rad && door->open_angle != 0.0 &&
        std::fabs(opening - open_leaf_angle(*door)) > settings_.leaf_moved_rad) {
      leaf_angle_[s.door_id] = opening;
      leaf_moved = leaf_moved || !believed_closed(s.door_id);  // a closed door's leaf is not planned
    }
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
  return leaf_moved || closed() != before;
}

double DoorKnowledge::open_leaf_angle(const Doorway& d) const {
  const auto it = leaf_angle_.find(d.id);
  return it != leaf_angle_.end() ? it->second : std::fabs(d.open_angle);
}

std::vector<std::string> DoorKnowledge::closed() const {
  std::vector<std::string> out;
  for (const auto& [id, since] : closed_since_) out.push_back(id);
  return out;
}

WorldMap DoorKnowledge::apply(const WorldMap& map) const {
  WorldMap out = map;
  for (const Doorway& d : map.doors) {
    const geometry::Vec2 along(std::cos(d.heading), std::sin(d.heading));
    const geometry::Vec2 across(-along.y(), along.x());
    if (believed_closed(d.id)) {
      const geometry::Vec2 a = along * (d.width_m / 2.0);
      const geometry::Vec2 t = across * (settings_.thickness_m / 2.0);
      out.polygons.push_back({"door " + d.id, {d.centre - a - t, d.centre + a - t, d.centre + a + t, d.centre - a + t}});
      continue;
    }
    if (d.open_angle == 0.0) continue;  // the map does not say where the leaf stands
    // The leaf turned about the hinge (the doorway's end opposite the latch) towards its open side.
    const double turn = d.heading + std::copysign(open_leaf_angle(d), d.open_angle);
    const geometry::Vec2 hinge = d.centre - along * (d.width_m / 2.0);
    const geometry::Vec2 leaf(std::cos(turn), std::sin(turn));
    const geometry::Vec2 tip = hinge + leaf * (d.width_m + settings_.leaf_tip_margin_m);
    const geometry::Vec2 t = geometry::Vec2(-leaf.y(), leaf.x()) * (settings_.leaf_thickness_m / 2.0);
    out.polygons.push_back({"door " + d.id + " leaf", {hinge - t, tip - t, tip + t, hinge + t}});
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
