#pragma once
// The courier paper's floor as the executive tests use it: the four rooms of the two example
// deliveries and the hallway, each room behind its own door.
#include "services/courier/core/execution/courier_executive.hpp"

namespace autonomy::courier::test_support {

inline Floor paper_floor() {
  Floor f;
  f.places["meeting-table"] = {4.0, 10.7, "A-111", 1.0};
  f.places["librarian-desk"] = {3.5, 4.5, "A-110", 1.0};
  f.places["a114-desk"] = {19.0, 2.6, "A-114", 1.0};
  f.places["michael-desk"] = {37.5, 2.6, "A-120", 1.0};
  f.places["hallway-west"] = {1.5, 8.0, "", 1.0};
  for (const char* room : {"A-110", "A-111", "A-114", "A-120"}) f.door_of_room[room] = room;
  // In the hallway beside each door: where a robot waits for a closed door to open.
  f.door_lookouts = {{"A-110", {2.8, 7.6}}, {"A-111", {5.2, 8.4}}, {"A-114", {17.8, 7.6}}, {"A-120", {36.3, 7.6}}};
  return f;
}

}  // namespace autonomy::courier::test_support
