#include "services/courier/dds/office_file.hpp"

#include "services/courier/core/knowledge/knowledge_problems.hpp"
#include "simulator/scenario/scenario_loader.hpp"

#include <cmath>
#include <optional>

namespace autonomy::courier {

namespace {

PlaceKind place_kind(sim::office::PlaceKind k) {
  switch (k) {
    case sim::office::PlaceKind::room: return PlaceKind::room;
    case sim::office::PlaceKind::desk: return PlaceKind::desk;
    case sim::office::PlaceKind::table: return PlaceKind::table;
    case sim::office::PlaceKind::station: return PlaceKind::station;
  }
  return PlaceKind::desk;
}

// Beside the doorway on its hallway side, out of the way of robots going through, close enough
// for the door sensor: where a robot waits for a closed door to open (Floor::door_lookouts).
// Nothing when neither side of the door is a hallway or no free spot is found.
std::optional<Floor::Lookout> lookout_of(const sim::DoorSpec& door, const sim::Scenario& scenario) {
  constexpr double kOffWallM = 0.6;   // from the doorway line into the hallway
  constexpr double kBesideM = 0.7;    // past the door frame, along the wall
  constexpr double kClearanceM = 0.4; // from every obstacle (a robot's radius and a margin)
  const geometry::Vec2 along{std::cos(door.heading), std::sin(door.heading)};
  const geometry::Vec2 normal{-along.y(), along.x()};
  for (const double side : {1.0, -1.0}) {
    for (const double beside : {1.0, -1.0}) {
      const geometry::Vec2 spot =
          door.position + normal * (side * kOffWallM) + along * (beside * (door.width / 2 + kBesideM));
      bool in_hallway = false;
      for (const auto& room : scenario.rooms)
        if (room.kind == "hallway" && room.bounds && room.bounds->contains(spot)) in_hallway = true;
      if (!in_hallway) continue;
      bool clear = true;
      for (const auto& o : scenario.world.obstacles)
        if (o.inflated(kClearanceM).contains(spot)) clear = false;
      if (clear) return Floor::Lookout{spot.x(), spot.y()};
    }
  }
  return std::nullopt;
}

CourierRobotSpec robot_of(const sim::RobotSpec& r) {
  return {r.id, static_cast<int>(std::min<std::uint32_t>(r.capacity, 1000u)), r.radius, r.max_speed};
}

}  // namespace

CourierOfficeResult load_courier_office(const std::string& scenario_path) {
  CourierOfficeResult result;
  const sim::ScenarioLoadResult loaded = sim::load_scenario_file(scenario_path);
  if (!loaded.ok()) {
    result.error = loaded.error_text();
    return result;
  }
  const sim::Scenario& scenario = *loaded.scenario;
  if (!scenario.office) {
    result.error = scenario_path + ": the scenario has no office (people, objects or loading stations)";
    return result;
  }
  const sim::office::OfficeSpec& spec = *scenario.office;
  CourierOffice office;

  OfficeKnowledge& k = office.knowledge;
  k.clock.day_start_s = spec.clock.day_start_s;
  for (const auto& p : spec.places) {
    k.places.push_back({p.name, place_kind(p.kind), p.room, p.position.x(), p.position.y(), {}});
    if (p.kind != sim::office::PlaceKind::room)
      office.floor.places[p.name] = {p.position.x(), p.position.y(), p.room, p.radius};
  }
  for (const auto& person : spec.people) {
    Person out;
    out.name = person.name;
    out.desk = person.desk;
    for (const auto& w : person.presence) out.presence.push_back({w.start_s, w.end_s});
    out.handover_s = person.handover_time.mean_s;  // the expected duration
    if (auto desk = office.floor.places.find(out.desk); desk != office.floor.places.end()) desk->second.person = out.name;
    k.people.push_back(std::move(out));
  }
  for (const auto& s : spec.stations) k.stations.push_back({s.place, s.handover_time.mean_s});
  for (const auto& o : spec.objects) {
    KnownObject known{o.id, o.kind, o.colour, "", "", ""};
    if (o.location.kind == sim::office::ObjectLocation::Kind::place)
      known.place = o.location.name;
    else
      known.carrier = o.location.name;
    k.objects.push_back(std::move(known));
  }
  if (const auto problems = knowledge_problems(k); !problems.empty()) {
    result.error = scenario_path + ": the office cannot be used by the courier:";
    for (const auto& p : problems) result.error += "\n  " + p;
    return result;
  }

  const sim::WorldSpec& world = scenario.world;
  office.map.width_m = world.width;
  office.map.height_m = world.height;
  office.map.obstacles = world.obstacles;
  office.map.polygons = world.polygons;
  for (const auto& layer : world.rasters) office.map.rasters.push_back(layer.raster);
  for (const auto& d : world.doors) {
    office.map.doors.push_back({d.id, d.position, d.width, d.heading});
    office.floor.doors.insert(d.id);
    if (const auto lookout = lookout_of(d, scenario)) office.floor.door_lookouts[d.id] = *lookout;
    // A door leads into each of its rooms that is not a hallway; the first door of a room wins.
    for (const auto& room : d.rooms) {
      bool hallway = room.empty();
      for (const auto& r : scenario.rooms)
        if (r.name == room && r.kind == "hallway") hallway = true;
      if (!hallway) office.floor.door_of_room.emplace(room, d.id);
    }
  }
  for (const auto& r : scenario.rooms)
    if (r.bounds && office.floor.door_of_room.count(r.name))
      office.floor.room_areas[r.name] = {r.bounds->min_x, r.bounds->min_y, r.bounds->max_x, r.bounds->max_y};
  for (const auto& p : scenario.parking) office.floor.parking.push_back({p.name, p.position.x(), p.position.y()});
  for (const auto& r : world.robots_at_start)
    if (r.kind == "courier") office.robots.push_back(robot_of(r));
  for (const auto& r : world.known_robots)
    if (r.kind == "courier") office.robots.push_back(robot_of(r));
  office.attach_defaults = robot_of(world.attach_defaults);
  result.office = std::move(office);
  return result;
}

}  // namespace autonomy::courier
