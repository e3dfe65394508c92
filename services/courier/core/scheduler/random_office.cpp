#include "services/courier/core/scheduler/random_office.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

namespace autonomy::courier::scheduling {

namespace {

class Dice {
 public:
  explicit Dice(std::uint64_t seed) : rng_(seed) {}
  // Uniform in [0, n) by rejection on the raw 64-bit output (n > 0).
  std::uint64_t below(std::uint64_t n) {
    const std::uint64_t limit = ~0ull - (~0ull % n);
    std::uint64_t x;
    do x = rng_();
    while (x >= limit);
    return x % n;
  }
  int in(int lo, int hi) {
    return lo + static_cast<int>(below(static_cast<std::uint64_t>(hi - lo + 1)));
  }
  bool percent(int p) { return static_cast<int>(below(100)) < p; }

 private:
  std::mt19937_64 rng_;
};

const char* const kKinds[] = {"letter", "parcel", "book", "folder", "disk", "key"};
const char* const kColours[] = {"red", "green", "blue", "yellow", "white", "black"};

}  // namespace

SchedulingProblem random_office(const OfficeSpec& spec) {
  Dice dice(spec.seed);
  SchedulingProblem p;
  p.now_s = spec.now_s;
  p.hallway_y_m = 0.0;
  // Locations: the mail station, then one desk per room.
  Location station;
  station.name = "mail station";
  station.x_m = 0.0;
  station.y_m = 0.0;
  station.station_handover_s = 10.0;
  p.locations.push_back(station);
  for (int r = 0; r < spec.rooms; ++r) {
    Location desk;
    const bool north = r % 2 == 0;
    desk.room =
        std::string(north ? "A-1" : "A-2") + (r / 2 < 10 ? "0" : "") + std::to_string(r / 2 + 10);
    desk.name = desk.room + " desk";
    desk.x_m = 4.0 * (r / 2) + 2.0;
    desk.y_m = north ? 6.0 : -6.0;
    p.locations.push_back(desk);
    Person person;
    person.name = "person " + desk.room;
    person.handover_s = 15.0 + 5.0 * dice.in(0, 5);
    if (spec.presence) {
      const double from = dice.percent(20) ? 10.0 : 8.0;
      person.presence = {{from * 3600.0, 12.0 * 3600.0}, {13.0 * 3600.0, 17.0 * 3600.0}};
    }
    p.people.push_back(person);
  }
  const std::size_t n = p.locations.size();
  p.travel = TravelMatrix(n);
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = 0; b < n; ++b) {
      if (a == b) continue;
      const Location& la = p.locations[a];
      const Location& lb = p.locations[b];
      const double metres = std::abs(*la.y_m) + std::abs(*la.x_m - *lb.x_m) + std::abs(*lb.y_m);
      const int doors = (la.room.empty() ? 0 : 1) + (lb.room.empty() ? 0 : 1);
      p.travel.set(a, b, std::round(metres / 0.7 + 4.0 * doors));
    }
  for (int c = 0; c < spec.couriers; ++c) {
    Courier courier;
    courier.id = "r" + std::to_string(c + 1);
    courier.capacity = spec.capacity;
    courier.location = c == 0 ? 0 : dice.in(0, static_cast<int>(n) - 1);
    courier.available_s = spec.now_s;
    p.couriers.push_back(courier);
  }
  // Deadlines spread over the time the jobs take (about 90 s each per courier).
  const int horizon = std::max(300, 100 * spec.jobs / std::max(1, spec.couriers));
  std::vector<int> aboard(static_cast<std::size_t>(spec.couriers), 0);
  for (int j = 0; j < spec.jobs; ++j) {
    Job job;
    job.id = "j" + std::to_string(j + 1);
    job.object = {kKinds[dice.below(static_cast<std::uint64_t>(std::min(spec.kinds, 6)))],
                  kColours[dice.below(static_cast<std::uint64_t>(std::min(spec.colours, 6)))]};
    auto place = [&](int location) {
      Place pl;
      pl.location = location;
      pl.person = location == 0 ? -1 : location - 1;
      return pl;
    };
    const int from = dice.in(0, static_cast<int>(n) - 1);
    int to = dice.in(0, static_cast<int>(n) - 2);
    if (to >= from) ++to;
    job.pickup = place(from);
    job.delivery = place(to);
    if (dice.percent(spec.deadline_percent))
      job.deadline_s = spec.now_s + 120.0 + 10.0 * dice.in(0, horizon / 10);
    const int c = dice.in(0, spec.couriers - 1);
    if (dice.percent(spec.aboard_percent) && aboard[static_cast<std::size_t>(c)] < spec.capacity) {
      job.status = JobStatus::kAboard;
      job.aboard_courier = c;
      ++aboard[static_cast<std::size_t>(c)];
    }
    p.jobs.push_back(job);
  }
  if (spec.tight_presence_percent > 0)
    for (Person& person : p.people)
      if (dice.percent(spec.tight_presence_percent))
        person.presence = {{spec.now_s - 3600.0,
                            spec.now_s + 10.0 * dice.in(1, std::max(1, spec.tight_max_s / 10))}};
  for (int k = 0; k < std::min(spec.closed_rooms, spec.rooms); ++k)
    p.travel.cut_off(static_cast<std::size_t>(dice.in(1, spec.rooms)));
  if (spec.late_arrival_percent > 0)
    for (Person& person : p.people)
      if (dice.percent(spec.late_arrival_percent))
        person.presence = {
            {spec.now_s + 10.0 * dice.in(1, std::max(1, spec.late_max_s / 10)), 17.0 * 3600.0}};
  return p;
}

}  // namespace autonomy::courier::scheduling
