#include "simulator/core/door_observer.hpp"

#include "simulator/core/shapes.hpp"

#include <algorithm>
#include <cmath>

namespace autonomy::sim {

bool visible(const ObstacleMap& map, const std::vector<DoorView>& doors, const geometry::Vec2& a,
             const geometry::Vec2& b, std::size_t except) {
  for (std::size_t i = 0; i < doors.size(); ++i) {
    if (i == except) continue;
    const DoorLeaf leaf = doors[i].spec->leaf(doors[i].angle);
    if (segments_intersect(a, b, leaf.hinge, leaf.tip)) return false;
  }
  return map.clear(a, b);
}

std::vector<DoorObservation> DoorObserver::observe(const geometry::Pose2& pose, const ObstacleMap& map,
                                                   const std::vector<DoorView>& doors, Rng* noise) const {
  std::vector<DoorObservation> out;
  if (!(spec_.range_m > 0.0)) return out;
  const geometry::Vec2 p = pose.position();
  for (std::size_t i = 0; i < doors.size(); ++i) {
    const DoorSpec& door = *doors[i].spec;
    const geometry::Vec2 rel = door.position - p;
    const double distance = rel.norm();
    if (distance > spec_.range_m || !visible(map, doors, p, door.position, i)) continue;
    DoorObservation o;
    o.door_id = door.id;
    o.distance_m = distance;
    o.bearing_rad = geometry::wrap_angle(std::atan2(rel.y(), rel.x()) - pose.theta);
    o.angle_estimate = doors[i].angle;
    if (noise != nullptr && spec_.angle_noise_rad > 0.0) {
      o.angle_estimate = std::clamp(noise->normal(o.angle_estimate, spec_.angle_noise_rad), 0.0, door.max_angle);
    }
    out.push_back(std::move(o));
  }
  return out;
}

}  // namespace autonomy::sim
