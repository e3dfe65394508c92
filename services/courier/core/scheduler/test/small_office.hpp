#pragma once
// A three-place office for hand-computed test cases:
//   0 "hall"  (hallway, no room)     courier r1 starts here
//   1 "A-111 table" (room A-111)     10 s from the hall
//   2 "A-120 desk"  (room A-120)     25 s from the hall, 20 s from A-111
// Stations only (no people) unless a test adds them; every handover takes 5 s; now = 10:00.
#include "services/courier/core/scheduler/scheduling_problem.hpp"

#include <string>

namespace autonomy::courier::scheduling::test {

inline SchedulingProblem small_office(int capacity = 2) {
  SchedulingProblem p;
  p.now_s = 36000.0;
  for (const char* name : {"hall", "A-111 table", "A-120 desk"}) {
    Location l;
    l.name = name;
    l.station_handover_s = 5.0;
    p.locations.push_back(l);
  }
  p.locations[1].room = "A-111";
  p.locations[2].room = "A-120";
  p.travel = TravelMatrix(3);
  const double t[3][3] = {{0, 10, 25}, {10, 0, 20}, {25, 20, 0}};
  for (std::size_t a = 0; a < 3; ++a)
    for (std::size_t b = 0; b < 3; ++b) p.travel.set(a, b, t[a][b]);
  Courier c;
  c.id = "r1";
  c.capacity = capacity;
  c.location = 0;
  c.available_s = p.now_s;
  p.couriers.push_back(c);
  return p;
}

inline Job job(const std::string& id, int from, int to, const std::string& colour = "red",
               const std::string& kind = "letter") {
  Job j;
  j.id = id;
  j.object = {kind, colour};
  j.pickup.location = from;
  j.delivery.location = to;
  return j;
}

constexpr StopRef P(int j) {
  return {j, StopKind::kPickup};
}
constexpr StopRef D(int j) {
  return {j, StopKind::kDelivery};
}

}  // namespace autonomy::courier::scheduling::test
