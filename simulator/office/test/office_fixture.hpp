#pragma once
// A small office shared by the office tests (built fresh by every test: nothing global).
//
//   A-110 (room)        anna-desk (2,2) r 0.8   Anna 09:00-12:00, 13:00-17:30, 20 s fixed
//                        meeting-table (6,2)     nobody
//   A-114 (room)        bob-desk (8,8) r 0.8    Bob 10:00-11:00, uniform 5..15 s
//   mailroom (station)  (10,1) r 1.0            loading station, 5 s
// The run starts at 08:30, so simulated time 1800 s is 09:00.
#include "simulator/office/office_spec.hpp"

namespace autonomy::sim::office::test {

inline double at_clock(double hours, double minutes = 0.0) {
  return hours * 3600.0 + minutes * 60.0 - 8.5 * 3600.0;  // simulated seconds
}

inline OfficeSpec small_office() {
  OfficeSpec s;
  s.clock.day_start_s = 8.5 * 3600.0;
  s.places = {
      {"A-110", PlaceKind::room, "", {4, 3}, 4.0},
      {"anna-desk", PlaceKind::desk, "A-110", {2, 2}, 0.8},
      {"meeting-table", PlaceKind::table, "A-110", {6, 2}, 0.8},
      {"A-114", PlaceKind::room, "", {8, 8}, 3.0},
      {"bob-desk", PlaceKind::desk, "A-114", {8, 8}, 0.8},
      {"mailroom", PlaceKind::station, "", {10, 1}, 1.0},
  };
  s.people = {
      {"Anna", "anna-desk", {{9 * 3600.0, 12 * 3600.0}, {13 * 3600.0, 17.5 * 3600.0}},
       HandoverTimeModel::fixed(20.0)},
      {"Bob", "bob-desk", {{10 * 3600.0, 11 * 3600.0}}, HandoverTimeModel::uniform(5.0, 15.0)},
  };
  s.stations = {{"mailroom", HandoverTimeModel::fixed(5.0)}};
  s.objects = {
      {"letter-1", "letter", "red", ObjectLocation::at_place("anna-desk")},
      {"letter-2", "letter", "red", ObjectLocation::at_place("mailroom")},
      {"book-1", "book", "green", ObjectLocation::at_place("mailroom")},
      {"envelope-1", "envelope", "white", ObjectLocation::at_place("meeting-table")},
  };
  return s;
}

}  // namespace autonomy::sim::office::test
