#pragma once
// The office floor of deploy/scenarios/office.pbtxt as the courier's knowledge (what the node
// builds from the scenario), for tests: the paper's rooms A-110 .. A-121, the librarian, Jan,
// Anna, Wolfram, Michael and Sebastian at their desks, the mail tray, and the objects lying around.
#include "services/courier/core/knowledge/office_knowledge.hpp"

namespace autonomy::courier::test {

inline double hm(int h, int m) {
  return h * 3600.0 + m * 60.0;
}

inline OfficeKnowledge paper_office() {
  OfficeKnowledge k;
  k.clock.day_start_s = hm(8, 30);
  for (const char* room : {"hallway", "A-110", "A-112", "A-114", "A-116", "A-118", "A-120", "A-111",
                           "A-113", "A-115", "A-117", "A-119", "A-121"})
    k.places.push_back({room, PlaceKind::room, "", 0.0, 0.0, {}});
  k.places[4].aliases = {"mail room"};
  auto place = [&](const char* name, PlaceKind kind, const char* room, double x, double y) {
    k.places.push_back({name, kind, room, x, y, {}});
  };
  place("librarian-desk", PlaceKind::desk, "A-110", 3.5, 4.5);
  place("meeting-table", PlaceKind::table, "A-111", 4, 10.7);
  place("a112-desk", PlaceKind::desk, "A-112", 13, 2.6);
  place("a114-desk", PlaceKind::desk, "A-114", 19, 2.6);
  place("a116-desk", PlaceKind::desk, "A-116", 25, 2.6);
  place("a118-desk", PlaceKind::desk, "A-118", 31, 2.6);
  place("michael-desk", PlaceKind::desk, "A-120", 37.5, 2.6);
  place("a113-desk", PlaceKind::desk, "A-113", 11, 13.4);
  place("classroom-lectern", PlaceKind::table, "A-115", 21.2, 12.4);
  place("a117-desk", PlaceKind::desk, "A-117", 27, 13.4);
  place("a119-desk", PlaceKind::desk, "A-119", 32.5, 13.4);
  place("a121-desk", PlaceKind::desk, "A-121", 37.5, 13.4);
  place("hallway-west", PlaceKind::desk, "hallway", 1.5, 8);
  place("hallway-east", PlaceKind::desk, "hallway", 38.5, 8);
  place("mail-tray", PlaceKind::station, "A-116", 25, 4.5);

  auto person = [&](const char* name, const char* desk, std::vector<DailyInterval> presence,
                    double handover_s) {
    k.people.push_back({name, {}, desk, std::move(presence), handover_s});
  };
  person("librarian", "librarian-desk", {{hm(8, 0), hm(12, 0)}, {hm(13, 0), hm(17, 0)}}, 12);
  person("Jan", "a112-desk", {{hm(9, 0), hm(12, 30)}, {hm(13, 30), hm(18, 0)}}, 14);
  person("Anna", "a114-desk", {{hm(8, 30), hm(16, 30)}}, 10);
  person("Wolfram", "a118-desk", {{hm(10, 0), hm(12, 0)}, {hm(14, 0), hm(19, 0)}}, 20);
  person("Michael", "michael-desk", {{hm(8, 45), hm(12, 15)}, {hm(13, 15), hm(17, 45)}}, 10);
  person("Sebastian", "a121-desk", {{hm(11, 0), hm(20, 0)}}, 15);
  k.stations.push_back({"mail-tray", 4});

  k.objects = {
      {"book-green", "book", "green", "librarian-desk", "", ""},
      {"book-red", "book", "red", "librarian-desk", "", ""},
      {"letter-1", "letter", "white", "michael-desk", "", ""},
      {"letter-2", "letter", "yellow", "a112-desk", "", ""},
      {"letter-3", "letter", "blue", "meeting-table", "", ""},
      {"envelope-1", "envelope", "brown", "mail-tray", "", ""},
      {"envelope-2", "envelope", "white", "mail-tray", "", ""},
      // The paper's red letter on the meeting table, and a letter lying on Wolfram's desk.
      {"letter-red", "letter", "red", "meeting-table", "", ""},
      {"letter-4", "letter", "white", "a118-desk", "", ""},
  };
  return k;
}

}  // namespace autonomy::courier::test
