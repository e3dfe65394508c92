#include "services/courier/core/knowledge/knowledge_problems.hpp"

#include "services/courier/core/knowledge/office_knowledge.hpp"
#include "services/courier/core/knowledge/test/paper_office.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace autonomy::courier {
namespace {

using test::hm;

TEST(KnowledgeProblems, ThePaperOfficeIsUsable) {
  EXPECT_EQ(knowledge_problems(test::paper_office()), std::vector<std::string>{});
}

TEST(KnowledgeProblems, PlaceNamesAndAliases) {
  OfficeKnowledge k = test::paper_office();
  k.places.push_back({"a-110", PlaceKind::desk, "", 0, 0, {}});  // A-110 differs only in case
  k.places.push_back({"", PlaceKind::desk, "", 0, 0, {}});
  k.places.push_back(
      {"nan-place", PlaceKind::desk, "", std::numeric_limits<double>::quiet_NaN(), 0, {}});
  k.places[1].aliases = {"library", "Michael-Desk", "A-110"};  // one new, one taken, one own
  k.places.push_back({"desk\t2", PlaceKind::desk, "A-777", 0, 0, {}});
  k.places.push_back({"lectern-2", PlaceKind::desk, "meeting-table", 0, 0, {}});
  k.places.push_back({"room-in-room", PlaceKind::room, "A-110", 0, 0, {}});
  EXPECT_EQ(knowledge_problems(k),
            (std::vector<std::string>{
                "place a-110 is declared twice",
                "place '' is empty",
                "place nan-place has a non-finite position",
                "place 'desk\t2' has a character that is not printable ASCII",
                "alias 'Michael-Desk' of place A-110 is already a name of michael-desk",
                "alias 'A-110' of place A-110 repeats one of its names",
                "place desk\t2 is in unknown room A-777",
                "place lectern-2 is in meeting-table, which is a table, not a room",
                "room room-in-room is inside room A-110",
            }));
}

TEST(KnowledgeProblems, People) {
  OfficeKnowledge k = test::paper_office();
  k.people.push_back({"michael", {""}, "nowhere", {{hm(9, 0), hm(8, 0)}}, -1.0});
  k.people.push_back(
      {"A-114", {}, "a114-desk", {{hm(9, 0), hm(12, 0)}, {hm(11, 0), hm(13, 0)}}, 5});
  k.people.push_back({"Night",
                      {},
                      "a114-desk",
                      {{hm(22, 0), hm(25, 0)}},
                      std::numeric_limits<double>::infinity()});
  EXPECT_EQ(knowledge_problems(k),
            (std::vector<std::string>{
                "person michael is declared twice",
                "role of person michael '' is empty",
                "person michael sits at unknown place nowhere",
                "person michael has presence 09:00-08:00 that is empty or outside the day",
                "person michael has a handover time that is negative or not finite",
                "person A-114 has the name of place A-114",
                "person A-114 has presence 11:00-13:00 overlapping or before the one before it",
                "person Night has presence 22:00-25:00 that is empty or outside the day",
                "person Night has a handover time that is negative or not finite",
            }));
}

TEST(KnowledgeProblems, StationsObjectsAndTheClock) {
  OfficeKnowledge k = test::paper_office();
  k.stations.push_back({"mail-tray", -2});
  k.stations.push_back({"roof", 1});
  k.objects.push_back({"letter-1", "letter", "", "", "", ""});
  k.objects.push_back({"thing", "", "", "attic", "", ""});
  k.objects.push_back({"letter-9", "letter", "", "a114-desk", "rhino", "Santa"});
  k.clock.day_start_s = kSecondsPerDay;
  EXPECT_EQ(knowledge_problems(k),
            (std::vector<std::string>{
                "loading station at mail-tray is declared twice",
                "loading station at mail-tray has a handover time that is negative or not finite",
                "loading station at unknown place roof",
                "object letter-1 is declared twice",
                "object thing has no kind",
                "object thing lies at unknown place attic",
                "object letter-9 is both at a114-desk and aboard rhino",
                "object letter-9 is addressed to unknown person Santa",
                "day start is outside [00:00, 24:00)",
            }));
}

}  // namespace
}  // namespace autonomy::courier
