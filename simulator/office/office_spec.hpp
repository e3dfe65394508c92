#pragma once
// The office a courier works in, as plain data: named places (rooms, desks, tables, loading
// stations), the people who sit at them and when they are in, and the objects lying around.
// Vocabulary from Beetz & Bennewitz's FAXBOT office courier ("deliver the green book from the
// librarian's desk in room A-110 to the desk in room A-114"): loading and unloading need a
// person at the place, and how long it takes depends on that person.
//
// Built at the edge (scenario files) and checked there with office_spec_problems(); OfficeState
// refuses a spec with problems.
#include "common/geometry/geometry.hpp"
#include "simulator/office/time_of_day.hpp"

#include <random>
#include <string>
#include <vector>

namespace autonomy::sim::office {

enum class PlaceKind { room, desk, table, station };

const char* to_string(PlaceKind kind);

struct Place {
  std::string name;  // unique, e.g. "A-111", "michael-desk", "A-111-meeting-table"
  PlaceKind kind = PlaceKind::desk;
  std::string room;  // the room place it is in; empty for rooms and places in no room (hallway)
  geometry::Vec2 position{0.0, 0.0};
  // A robot whose centre is within this distance of position is "at" the place.
  double radius = 1.0;
};

// How long one handover (loading or unloading) takes, in seconds. Sampled from the generator the
// caller passes, with hand-written transforms of its raw output (not std::*_distribution, whose
// algorithms differ between standard libraries), so a seed gives the same durations everywhere.
struct HandoverTimeModel {
  enum class Kind { fixed, uniform, normal };
  Kind kind = Kind::fixed;
  double mean_s = 10.0;  // fixed: the duration; normal: the mean
  double sd_s = 0.0;     // normal only
  double min_s = 0.0;    // uniform: the range; normal: the clip range (a draw is clamped into it)
  double max_s = 0.0;

  static HandoverTimeModel fixed(double seconds);
  static HandoverTimeModel uniform(double min_s, double max_s);
  static HandoverTimeModel normal(double mean_s, double sd_s, double min_s, double max_s);

  // Draws one duration. Uses exactly two outputs of rng for every kind, so adding or changing a
  // person's model does not shift the draws of the handovers after it.
  double sample(std::mt19937_64& rng) const;
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
  std::string name;  // unique among people
  std::string desk;  // the place where they work and hand things over (a desk, table, ...)
  std::vector<DailyInterval> presence;  // when they are at it, every day, in increasing order
  HandoverTimeModel handover_time;
};

// A place where loading and unloading never need a person (a mail room robot arm, a tray).
struct LoadingStation {
  std::string place;  // must name a place
  HandoverTimeModel handover_time;
};

// Where an object is: lying at a place, or carried by a robot.
struct ObjectLocation {
  enum class Kind { place, carrier };
  Kind kind = Kind::place;
  std::string name;  // place name or robot id

  static ObjectLocation at_place(std::string place) { return {Kind::place, std::move(place)}; }
  static ObjectLocation carried_by(std::string robot) { return {Kind::carrier, std::move(robot)}; }
  bool is_at(const std::string& place) const { return kind == Kind::place && name == place; }
  bool is_carried_by(const std::string& robot) const {
    return kind == Kind::carrier && name == robot;
  }
  bool operator==(const ObjectLocation& o) const { return kind == o.kind && name == o.name; }
};

struct ObjectItem {
  std::string id;      // unique, e.g. "letter-1"
  std::string kind;    // "letter", "book", "envelope", ...
  std::string colour;  // "red", "green", ...
  ObjectLocation location;
};

struct OfficeSpec {
  std::vector<Place> places;
  std::vector<Person> people;
  std::vector<LoadingStation> stations;
  std::vector<ObjectItem> objects;  // where they are at simulated time 0
  DayClock clock;
};

// Every problem with `spec`, one sentence each, in a stable order; empty when usable. Checks
// unique names and ids, rooms naming room places, positive radii, people's desks and stations
// naming places, ordered non-overlapping presence intervals within the day, usable handover
// models (non-negative, min <= max, finite), objects at known places (carriers are not checked:
// robots may attach later), and a day start within [0, 86400).
std::vector<std::string> office_spec_problems(const OfficeSpec& spec);

}  // namespace autonomy::sim::office
