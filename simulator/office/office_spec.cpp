#include "simulator/office/office_spec.hpp"

#include "simulator/core/number_format.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>

namespace autonomy::sim::office {

const char* to_string(PlaceKind kind) {
  switch (kind) {
    case PlaceKind::room: return "room";
    case PlaceKind::desk: return "desk";
    case PlaceKind::table: return "table";
    case PlaceKind::station: return "station";
  }
  return "?";
}

HandoverTimeModel HandoverTimeModel::fixed(double seconds) {
  HandoverTimeModel m;
  m.kind = Kind::fixed;
  m.mean_s = seconds;
  m.min_s = m.max_s = seconds;
  return m;
}

HandoverTimeModel HandoverTimeModel::uniform(double min_s, double max_s) {
  HandoverTimeModel m;
  m.kind = Kind::uniform;
  m.min_s = min_s;
  m.max_s = max_s;
  m.mean_s = 0.5 * (min_s + max_s);
  return m;
}

HandoverTimeModel HandoverTimeModel::normal(double mean_s, double sd_s, double min_s, double max_s) {
  HandoverTimeModel m;
  m.kind = Kind::normal;
  m.mean_s = mean_s;
  m.sd_s = sd_s;
  m.min_s = min_s;
  m.max_s = max_s;
  return m;
}

namespace {

// [0, 1) from the top 53 bits of one 64-bit output: the same on every standard library.
double unit(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

}  // namespace

double HandoverTimeModel::sample(std::mt19937_64& rng) const {
  const double u1 = unit(rng), u2 = unit(rng);
  switch (kind) {
    case Kind::fixed: return mean_s;
    case Kind::uniform: return min_s + (max_s - min_s) * u1;
    case Kind::normal: {
      // Box-Muller; 1 - u1 is in (0, 1] so the logarithm is finite.
      const double z = std::sqrt(-2.0 * std::log(1.0 - u1)) * std::cos(2.0 * M_PI * u2);
      return std::clamp(mean_s + sd_s * z, min_s, max_s);
    }
  }
  return mean_s;
}

namespace {

std::optional<std::string> model_problem(const HandoverTimeModel& m) {
  const bool finite = std::isfinite(m.mean_s) && std::isfinite(m.sd_s) && std::isfinite(m.min_s) &&
                      std::isfinite(m.max_s);
  if (!finite) return "has a non-finite handover time";
  switch (m.kind) {
    case HandoverTimeModel::Kind::fixed:
      if (m.mean_s < 0.0) return "has a negative handover time " + format_number(m.mean_s) + " s";
      break;
    case HandoverTimeModel::Kind::uniform:
    case HandoverTimeModel::Kind::normal:
      if (m.min_s < 0.0 || m.min_s > m.max_s)
        return "has a handover time range [" + format_number(m.min_s) + ", " + format_number(m.max_s) +
               "] s that is not 0 <= min <= max";
      if (m.kind == HandoverTimeModel::Kind::normal && m.sd_s < 0.0)
        return "has a negative handover time standard deviation " + format_number(m.sd_s) + " s";
      break;
  }
  return std::nullopt;
}

}  // namespace

std::vector<std::string> office_spec_problems(const OfficeSpec& spec) {
  std::vector<std::string> problems;
  if (!(spec.clock.day_start_s >= 0.0 && spec.clock.day_start_s < kSecondsPerDay))
    problems.push_back("day start " + format_number(spec.clock.day_start_s) +
                       " s is not within [0, 86400)");

  std::map<std::string, const Place*> places;
  for (const Place& p : spec.places) {
    if (p.name.empty()) problems.push_back("a place has no name");
    if (!places.emplace(p.name, &p).second) problems.push_back("place " + p.name + " is declared twice");
    if (!(p.radius > 0.0) || !std::isfinite(p.radius))
      problems.push_back("place " + p.name + " has radius " + format_number(p.radius) + " m, not > 0");
    if (!std::isfinite(p.position.x()) || !std::isfinite(p.position.y()))
      problems.push_back("place " + p.name + " has a non-finite position");
  }
  for (const Place& p : spec.places) {
    if (p.room.empty()) continue;
    auto room = places.find(p.room);
    if (room == places.end())
      problems.push_back("place " + p.name + " is in unknown room " + p.room);
    else if (room->second->kind != PlaceKind::room)
      problems.push_back("place " + p.name + " is in " + p.room + ", which is a " +
                         to_string(room->second->kind) + ", not a room");
    else if (p.kind == PlaceKind::room)
      problems.push_back("room " + p.name + " is inside room " + p.room);
  }

  std::set<std::string> people;
  for (const Person& person : spec.people) {
    const std::string who = "person " + person.name;
    if (person.name.empty()) problems.push_back("a person has no name");
    if (!people.insert(person.name).second) problems.push_back(who + " is declared twice");
    if (!places.count(person.desk)) problems.push_back(who + " sits at unknown place " + person.desk);
    double previous_end = 0.0;
    for (const DailyInterval& i : person.presence) {
      const std::string range = format_clock(std::max(0.0, i.start_s)) + "-" + format_clock(std::max(0.0, i.end_s));
      if (!(i.start_s >= 0.0 && i.start_s < i.end_s && i.end_s <= kSecondsPerDay))
        problems.push_back(who + " has presence " + range + " that is not within one day, start before end");
      else if (i.start_s < previous_end)
        problems.push_back(who + " has presence " + range + " overlapping or before the previous interval");
      previous_end = std::max(previous_end, i.end_s);
    }
    if (auto p = model_problem(person.handover_time)) problems.push_back(who + " " + *p);
  }

  std::set<std::string> station_places;
  for (const LoadingStation& s : spec.stations) {
    if (!places.count(s.place)) problems.push_back("loading station at unknown place " + s.place);
    if (!station_places.insert(s.place).second)
      problems.push_back("loading station at " + s.place + " is declared twice");
    if (auto p = model_problem(s.handover_time)) problems.push_back("loading station at " + s.place + " " + *p);
  }

  std::set<std::string> objects;
  for (const ObjectItem& o : spec.objects) {
    if (o.id.empty()) problems.push_back("an object has no id");
    if (!objects.insert(o.id).second) problems.push_back("object " + o.id + " is declared twice");
    if (o.location.name.empty())
      problems.push_back("object " + o.id + " has no location");
    else if (o.location.kind == ObjectLocation::Kind::place && !places.count(o.location.name))
      problems.push_back("object " + o.id + " is at unknown place " + o.location.name);
  }
  return problems;
}

}  // namespace autonomy::sim::office
