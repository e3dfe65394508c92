#include "services/courier/core/knowledge/office_knowledge.hpp"

#include "services/courier/core/knowledge/name_lookup.hpp"

#include <algorithm>

namespace autonomy::courier {

const char* to_string(PlaceKind kind) {
  switch (kind) {
    case PlaceKind::room:
      return "room";
    case PlaceKind::desk:
      return "desk";
    case PlaceKind::table:
      return "table";
    case PlaceKind::station:
      return "station";
  }
  return "place";
}

bool Person::present_at(double seconds_of_day) const {
  return std::any_of(presence.begin(), presence.end(),
                     [&](const DailyInterval& i) { return i.contains(seconds_of_day); });
}

const Place* OfficeKnowledge::find_place(std::string_view name) const {
  for (const Place& p : places) {
    if (same_name(p.name, name)) return &p;
    for (const std::string& a : p.aliases)
      if (same_name(a, name)) return &p;
  }
  return nullptr;
}

const Person* OfficeKnowledge::find_person(std::string_view name) const {
  for (const Person& p : people)
    if (same_name(p.name, name)) return &p;
  return nullptr;
}

const KnownObject* OfficeKnowledge::find_object(std::string_view id) const {
  for (const KnownObject& o : objects)
    if (same_name(o.id, id)) return &o;
  return nullptr;
}

const LoadingStation* OfficeKnowledge::station_at(std::string_view place) const {
  for (const LoadingStation& s : stations)
    if (same_name(s.place, place)) return &s;
  return nullptr;
}

std::vector<const Person*> OfficeKnowledge::people_with_role(std::string_view role) const {
  std::vector<const Person*> found;
  for (const Person& p : people) {
    bool match = same_name(p.name, role);
    for (const std::string& r : p.roles) match = match || same_name(r, role);
    if (match) found.push_back(&p);
  }
  return found;
}

std::vector<const Person*> OfficeKnowledge::people_at(std::string_view place) const {
  std::vector<const Person*> found;
  for (const Person& p : people)
    if (same_name(p.desk, place)) found.push_back(&p);
  return found;
}

const Person* OfficeKnowledge::person_at(std::string_view place) const {
  for (const Person& p : people)
    if (same_name(p.desk, place)) return &p;
  return nullptr;
}

std::vector<const Place*> OfficeKnowledge::rooms() const {
  std::vector<const Place*> found;
  for (const Place& p : places)
    if (p.kind == PlaceKind::room) found.push_back(&p);
  return found;
}

std::vector<const Place*> OfficeKnowledge::places_in_room(std::string_view room) const {
  std::vector<const Place*> found;
  for (const Place& p : places)
    if (p.kind != PlaceKind::room && same_name(p.room, room)) found.push_back(&p);
  return found;
}

std::vector<const KnownObject*> OfficeKnowledge::objects_matching(std::string_view kind,
                                                                  std::string_view colour,
                                                                  std::string_view place) const {
  std::vector<const KnownObject*> found;
  for (const KnownObject& o : objects) {
    if (o.place.empty()) continue;  // aboard a robot or lost: not lying anywhere
    if (!kind.empty() && !same_name(o.kind, kind)) continue;
    if (!colour.empty() && !same_name(o.colour, colour)) continue;
    if (!place.empty() && !same_name(o.place, place)) continue;
    found.push_back(&o);
  }
  return found;
}

std::vector<const KnownObject*> OfficeKnowledge::objects_carried_by(
    std::string_view carrier) const {
  std::vector<const KnownObject*> found;
  for (const KnownObject& o : objects)
    if (!o.carrier.empty() && same_name(o.carrier, carrier)) found.push_back(&o);
  return found;
}

namespace {
std::vector<std::string> sorted_unique(std::vector<std::string> words) {
  words.erase(std::remove(words.begin(), words.end(), std::string()), words.end());
  std::sort(words.begin(), words.end());
  words.erase(std::unique(words.begin(), words.end()), words.end());
  return words;
}
}  // namespace

std::vector<std::string> OfficeKnowledge::object_kinds() const {
  std::vector<std::string> words;
  for (const KnownObject& o : objects) words.push_back(lower_case(o.kind));
  return sorted_unique(std::move(words));
}

std::vector<std::string> OfficeKnowledge::colours() const {
  std::vector<std::string> words;
  for (const KnownObject& o : objects) words.push_back(lower_case(o.colour));
  return sorted_unique(std::move(words));
}

}  // namespace autonomy::courier
