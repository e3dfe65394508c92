#include "simulator/office/perception.hpp"

namespace autonomy::sim::office {

OfficePercept perceive(const OfficeState& office, const std::string& robot_id,
                       const geometry::Vec2& robot_position, double range_m, double now_s,
                       const LineOfSight& line_of_sight) {
  OfficePercept percept;
  percept.time_s = now_s;
  for (const Place& place : office.spec().places) {
    if ((place.position - robot_position).norm() > range_m) continue;
    if (line_of_sight && !line_of_sight(robot_position, place.position)) continue;
    percept.seen_places.push_back(place.name);
    for (const ObjectItem& o : office.objects())
      if (o.location.is_at(place.name)) percept.objects.push_back({o.id, o.kind, o.colour, place.name});
    for (const std::string& name : office.people_present(place.name, now_s))
      percept.people.push_back({name, place.name});
  }
  percept.carried = office.carried_by(robot_id);
  return percept;
}

}  // namespace autonomy::sim::office
