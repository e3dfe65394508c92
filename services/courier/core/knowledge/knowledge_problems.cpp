#include "services/courier/core/knowledge/knowledge_problems.hpp"

#include "services/courier/core/knowledge/name_lookup.hpp"
#include "services/courier/core/knowledge/office_knowledge.hpp"

#include <cmath>
#include <map>
#include <set>

namespace autonomy::courier {

namespace {

// Why a name cannot be used in commands, or empty when it can.
std::string name_problem(const std::string& name) {
  if (name.empty()) return "is empty";
  if (name.front() == ' ' || name.back() == ' ') return "starts or ends with a space";
  for (unsigned char c : name)
    if (c < 0x20 || c > 0x7e) return "has a character that is not printable ASCII";
  return {};
}

bool usable_seconds(double s) {
  return std::isfinite(s) && s >= 0.0;
}

}  // namespace

std::vector<std::string> knowledge_problems(const OfficeKnowledge& k) {
  std::vector<std::string> problems;
  auto check_name = [&](const std::string& what, const std::string& name) {
    const std::string why = name_problem(name);
    if (!why.empty()) problems.push_back(what + " '" + name + "' " + why);
    return why.empty();
  };

  // One namespace for place names and aliases, lower-cased, to the place that owns the name.
  std::map<std::string, std::string> place_names;
  for (const Place& p : k.places) {
    check_name("place", p.name);
    if (!place_names.emplace(lower_case(p.name), p.name).second)
      problems.push_back("place " + p.name + " is declared twice");
    if (!std::isfinite(p.x) || !std::isfinite(p.y))
      problems.push_back("place " + p.name + " has a non-finite position");
  }
  for (const Place& p : k.places)
    for (const std::string& a : p.aliases) {
      if (!check_name("alias of place " + p.name, a)) continue;
      auto [it, fresh] = place_names.emplace(lower_case(a), p.name);
      if (fresh) continue;
      if (it->second == p.name)
        problems.push_back("alias '" + a + "' of place " + p.name + " repeats one of its names");
      else
        problems.push_back("alias '" + a + "' of place " + p.name + " is already a name of " +
                           it->second);
    }
  for (const Place& p : k.places) {
    if (p.room.empty()) continue;
    const Place* room = k.find_place(p.room);
    if (room == nullptr)
      problems.push_back("place " + p.name + " is in unknown room " + p.room);
    else if (room->kind != PlaceKind::room)
      problems.push_back("place " + p.name + " is in " + p.room + ", which is a " +
                         to_string(room->kind) + ", not a room");
    else if (p.kind == PlaceKind::room)
      problems.push_back("room " + p.name + " is inside room " + p.room);
  }

  std::set<std::string> people;
  for (const Person& person : k.people) {
    const std::string who = "person " + person.name;
    check_name("person", person.name);
    if (!people.insert(lower_case(person.name)).second)
      problems.push_back(who + " is declared twice");
    if (place_names.count(lower_case(person.name)))
      problems.push_back(who + " has the name of place " + place_names.at(lower_case(person.name)));
    for (const std::string& r : person.roles) check_name("role of " + who, r);
    if (k.find_place(person.desk) == nullptr)
      problems.push_back(who + " sits at unknown place " + person.desk);
    double previous_end = 0.0;
    for (const DailyInterval& i : person.presence) {
      const std::string range =
          format_clock(std::max(0.0, i.start_s)) + "-" + format_clock(std::max(0.0, i.end_s));
      if (!(i.start_s >= 0.0 && i.start_s < i.end_s && i.end_s <= kSecondsPerDay))
        problems.push_back(who + " has presence " + range + " that is empty or outside the day");
      else if (i.start_s < previous_end)
        problems.push_back(who + " has presence " + range +
                           " overlapping or before the one before it");
      previous_end = std::max(previous_end, i.end_s);
    }
    if (!usable_seconds(person.handover_s))
      problems.push_back(who + " has a handover time that is negative or not finite");
  }

  std::set<std::string> stations;
  for (const LoadingStation& s : k.stations) {
    if (k.find_place(s.place) == nullptr)
      problems.push_back("loading station at unknown place " + s.place);
    if (!stations.insert(lower_case(s.place)).second)
      problems.push_back("loading station at " + s.place + " is declared twice");
    if (!usable_seconds(s.handover_s))
      problems.push_back("loading station at " + s.place +
                         " has a handover time that is negative or not finite");
  }

  std::set<std::string> ids;
  for (const KnownObject& o : k.objects) {
    const std::string what = "object " + o.id;
    check_name("object", o.id);
    if (!ids.insert(lower_case(o.id)).second) problems.push_back(what + " is declared twice");
    if (o.kind.empty()) problems.push_back(what + " has no kind");
    if (!o.place.empty() && k.find_place(o.place) == nullptr)
      problems.push_back(what + " lies at unknown place " + o.place);
    if (!o.place.empty() && !o.carrier.empty())
      problems.push_back(what + " is both at " + o.place + " and aboard " + o.carrier);
    if (!o.addressee.empty() && k.find_person(o.addressee) == nullptr)
      problems.push_back(what + " is addressed to unknown person " + o.addressee);
  }

  if (!(k.clock.day_start_s >= 0.0 && k.clock.day_start_s < kSecondsPerDay))
    problems.push_back("day start is outside [00:00, 24:00)");
  return problems;
}

}  // namespace autonomy::courier
