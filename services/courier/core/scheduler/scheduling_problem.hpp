#pragma once
// The courier scheduling problem (FAXBOT's SCHEDULE-DELIVERIES input, generalised): couriers, the
// delivery jobs they carry out, the people who hand objects over and the travel times between
// places. Plain data; times are seconds of the day (the caller's clock, e.g. 10:30 = 37800), so
// nothing here reads a clock.
//
// Model (what a schedule must respect; schedule_evaluation.hpp checks it, every engine obeys it)
//   - A job is one object moved from its pickup place to its delivery place. A job waiting for
//     pickup needs two stops (pickup, then delivery) on one courier; a job whose object is already
//     aboard courier X needs only its delivery stop, on X.
//   - Capacity: a pickup is only allowed while fewer than `capacity` objects are aboard.
//   - Look-alikes: a pickup is not allowed while an object of the same class (kind and colour,
//     the paper's two red letters) is aboard. The state the courier starts in is taken as given
//     (objects already aboard are never refused), only new pickups are checked.
//   - A stop is a handover at a place: with a person (who must be present for the whole handover:
//     the courier may arrive early and wait for the presence window to open) or at a station
//     (no person, always available, the location's station handover time).
//   - Travel times are a matrix; +inf means "no route" (e.g. behind a door believed closed). A
//     job whose pickup or delivery cannot be reached, or whose person is never present again, is
//     left out of the schedule and reported as unschedulable with a reason.
//   - Consecutive stops at the same location form one visit: they share the arrival (no travel
//     between them), their handovers follow each other and the visit counts as one interruption.
//   - A courier's forced prefix is a sequence of stops it must do first, in that order (the
//     executor's "deliver job J now, is every other deadline still kept?").
//
// Objective, lexicographic (objective.hpp): late jobs, total lateness, total completion time
// (sum over jobs of completion - now), travel time, interruptions (visits). The last term only
// breaks ties: visits to one person are merged where that costs nothing on the four others.
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace autonomy::courier::scheduling {

constexpr double kNoRoute = std::numeric_limits<double>::infinity();

// Seconds between every ordered pair of locations, row = from, column = to. The diagonal is 0.
class TravelMatrix {
 public:
  TravelMatrix() = default;
  explicit TravelMatrix(std::size_t locations, double fill = kNoRoute);

  std::size_t size() const { return n_; }
  double at(std::size_t from, std::size_t to) const { return s_[from * n_ + to]; }
  void set(std::size_t from, std::size_t to, double seconds) { s_[from * n_ + to] = seconds; }
  // Every route into and out of `location` becomes +inf (a door seen closed); the diagonal stays.
  void cut_off(std::size_t location);
  const std::vector<double>& values() const { return s_; }

 private:
  std::size_t n_ = 0;
  std::vector<double> s_;
};

struct Location {
  std::string name;  // unique, e.g. "A-120 desk"
  std::string room;  // the room whose door must be open to get there; empty = no door (hallway)
  std::optional<double> x_m;  // map position, used by the paper's hallway sort (optional)
  std::optional<double> y_m;
  double station_handover_s = 0.0;  // handover time for stops without a person
};

// [start_s, end_s) in seconds of the day.
struct TimeWindow {
  double start_s = 0.0;
  double end_s = 0.0;
};

struct Person {
  std::string name;
  double handover_s = 0.0;
  // Sorted, disjoint. Empty = always present.
  std::vector<TimeWindow> presence;
};

// Objects of one class look alike: a courier never carries two of them at once.
struct ObjectClass {
  std::string kind;    // "letter"
  std::string colour;  // "red"
  bool operator==(const ObjectClass& o) const { return kind == o.kind && colour == o.colour; }
};

// A handover place: a location and, optionally, the person there (index into people; -1 =
// station, no presence constraint).
struct Place {
  int location = -1;
  int person = -1;
};

enum class JobStatus : std::uint8_t { kWaitingForPickup, kAboard };
enum class StopKind : std::uint8_t { kPickup, kDelivery };
const char* to_string(StopKind k);

struct Job {
  std::string id;
  ObjectClass object;
  Place pickup;  // ignored when aboard
  Place delivery;
  std::optional<double> deadline_s;  // the delivery's handover must finish by then
  JobStatus status = JobStatus::kWaitingForPickup;
  int aboard_courier = -1;  // index into couriers when status == kAboard
};

// One stop of a schedule: job index and which of its two handovers.
struct StopRef {
  int job = -1;
  StopKind kind = StopKind::kPickup;
  bool operator==(const StopRef& o) const { return job == o.job && kind == o.kind; }
};

struct Courier {
  std::string id;
  int capacity = 1;
  int location = -1;         // where it is (or will be when available)
  double available_s = 0.0;  // it can start then (max with now_s)
  std::vector<StopRef> forced_prefix;
};

struct SchedulingProblem {
  double now_s = 0.0;
  std::vector<Location> locations;
  TravelMatrix travel;
  std::vector<Person> people;
  std::vector<Courier> couriers;
  std::vector<Job> jobs;
  // The hallway's y for the paper's north/south split; unset = median of the locations' y.
  std::optional<double> hallway_y_m;
  // The schedule being executed, per courier (optional): engines that improve a solution start
  // from it, after dropping stops that are no longer valid (rescheduling after a door event).
  std::vector<std::vector<StopRef>> previous_order;
};

// The first structural error ("jobs[2].delivery.location: 14 is not a location (12)"), or empty.
// Engines refuse a problem with such an error (ScheduleStatus::kInvalidProblem).
std::string problem_error(const SchedulingProblem& problem);

// The earliest handover start >= arrival_s such that [start, start + duration_s] lies inside one
// presence window of `person` (always arrival_s for a station, person < 0); +inf if none.
double earliest_handover_start(const SchedulingProblem& problem, int person, double arrival_s,
                               double duration_s);

double handover_duration(const SchedulingProblem& problem, const Place& place);

// Who hands over at a place, for messages: the person's name or the location's name.
std::string describe_place(const SchedulingProblem& problem, const Place& place);

}  // namespace autonomy::courier::scheduling
