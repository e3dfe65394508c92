#pragma once
// What the courier knows of its office, as plain data with queries: the places (rooms, desks,
// tables, loading stations), who sits where and when, the objects it knows of and where they were
// last known to be, the day clock and the destinations it has learned. This is the symbolic world
// model FAXBOT interprets commands against (Beetz & Bennewitz); it is the courier's belief, not the
// simulator's truth: the node fills it from the scenario's office section and updates objects from
// handover statuses.
//
// Names (places, aliases, people, roles, object ids) are matched case-insensitively everywhere;
// knowledge_problems() checks that this leaves every name unambiguous.
#include "services/courier/core/knowledge/day_clock.hpp"
#include "services/courier/core/knowledge/destination_frequencies.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace autonomy::courier {

enum class PlaceKind { room, desk, table, station };

const char* to_string(PlaceKind kind);  // "room", "desk", "table", "station"

struct Place {
  std::string name;  // unique, e.g. "A-111", "michael-desk", "meeting-table"
  PlaceKind kind = PlaceKind::desk;
  std::string room;         // the room place it is in; empty for rooms and places in no room
  double x = 0.0, y = 0.0;  // metres, map frame
  std::vector<std::string> aliases;  // other names for it ("mail room" for A-116), unique too
};

// [start_s, end_s) in seconds of the day; 0 <= start_s < end_s <= 86400.
struct DailyInterval {
  double start_s = 0.0;
  double end_s = 0.0;
  bool contains(double seconds_of_day) const {
    return seconds_of_day >= start_s && seconds_of_day < end_s;
  }
};

struct Person {
  std::string name;                     // unique among people, e.g. "Michael", "librarian"
  std::vector<std::string> roles;       // words that name them by what they do: "librarian"
  std::string desk;                     // the place where they work and hand things over
  std::vector<DailyInterval> presence;  // when they are at the desk, every day, increasing
  double handover_s = 10.0;             // expected duration of one handover with them
  bool present_at(double seconds_of_day) const;
};

// A place where loading and unloading never need a person (the mail room's tray).
struct LoadingStation {
  std::string place;
  double handover_s = 5.0;
};

struct KnownObject {
  std::string id;         // unique, e.g. "letter-4"
  std::string kind;       // "letter", "book", ...
  std::string colour;     // "red"; may be empty when unknown
  std::string place;      // where it was last known to lie; empty when carried or unknown
  std::string carrier;    // robot id while aboard a courier; empty otherwise
  std::string addressee;  // person it is addressed to, when known ("the letter for Michael")
};

struct OfficeKnowledge {
  std::vector<Place> places;  // rooms are places of kind room
  std::vector<Person> people;
  std::vector<LoadingStation> stations;
  std::vector<KnownObject> objects;
  DayClock clock;
  DestinationFrequencies learned;

  // Lookups by name or alias (case-insensitive); nullptr when unknown.
  const Place* find_place(std::string_view name) const;
  const Person* find_person(std::string_view name) const;  // by name only
  const KnownObject* find_object(std::string_view id) const;
  const LoadingStation* station_at(std::string_view place) const;

  std::vector<const Person*> people_with_role(std::string_view role) const;  // name or role word
  // The people whose desk is `place` (normally at most one).
  std::vector<const Person*> people_at(std::string_view place) const;
  const Person* person_at(std::string_view place) const;  // the first of people_at, or nullptr
  std::vector<const Place*> rooms() const;
  // The places (not rooms) whose room is `room`, in declaration order.
  std::vector<const Place*> places_in_room(std::string_view room) const;
  // Objects lying at `place` (not carried) matching kind and colour; an empty filter matches all.
  std::vector<const KnownObject*> objects_matching(std::string_view kind, std::string_view colour,
                                                   std::string_view place = {}) const;
  // Objects aboard robot `carrier`.
  std::vector<const KnownObject*> objects_carried_by(std::string_view carrier) const;

  // Every distinct object kind and colour known, lower-cased and sorted (the language's nouns).
  std::vector<std::string> object_kinds() const;
  std::vector<std::string> colours() const;
};

}  // namespace autonomy::courier
