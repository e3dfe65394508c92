#pragma once
// Random office scheduling instances for tests and benchmarks, seeded and platform independent
// (std::mt19937_64 and integer arithmetic only, no std::*_distribution).
//
// The office: a straight hallway along x at y = 0 with rooms north (y = +6 m) and south (y = -6 m)
// of it, 4 m apart, each with a desk and the person working there, plus a mail station in the
// hallway (no room, no person). Travel: out of the room to the hallway, along it, into the other
// room, at 0.7 m/s, plus 4 s per door passed. People hand over in 15-40 s and are present
// 08:00-12:00 and 13:00-17:00, some only from 10:00. Jobs move one object (kind x colour, so some
// look alike) between two random places; a share of them has a deadline.
//
// Harder instances (off by default; a spec that leaves them off gives the same instance for a
// seed as before they existed, their dice are rolled after everything else): people with one
// short presence window around now (some leave before a courier can get there, some clash with
// each other), rooms whose door is closed (TravelMatrix::cut_off of their desk), and people who
// arrive only after now.
#include "services/courier/core/scheduler/scheduling_problem.hpp"

#include <cstdint>

namespace autonomy::courier::scheduling {

struct OfficeSpec {
  int jobs = 12;
  int couriers = 1;
  int rooms = 16;
  int capacity = 3;
  int deadline_percent = 50;  // share of jobs with a deadline
  int aboard_percent = 0;     // share of jobs whose object is already aboard a courier
  int kinds = 2;              // letter, parcel, book, ...
  int colours = 3;            // red, green, blue, ...
  bool presence = true;       // false: everybody always present
  // Share of people present only in one window [now - 1 h, now + 1..tight_max_s], instead of
  // their office hours.
  int tight_presence_percent = 0;
  int tight_max_s = 600;
  int closed_rooms = 0;  // rooms cut off at random (their desk; never the mail station)
  // Share of people who come in only later: present from now + 10..late_max_s to 17:00 (the
  // courier waits for them). Rolled after the closed rooms.
  int late_arrival_percent = 0;
  int late_max_s = 600;
  double now_s = 9.0 * 3600.0;
  std::uint64_t seed = 1;
};

SchedulingProblem random_office(const OfficeSpec& spec);

}  // namespace autonomy::courier::scheduling
