#include "services/courier/core/knowledge/office_knowledge.hpp"

#include "services/courier/core/knowledge/test/paper_office.hpp"

#include <gtest/gtest.h>

namespace autonomy::courier {
namespace {

using test::hm;

std::vector<std::string> ids(const std::vector<const KnownObject*>& objects) {
  std::vector<std::string> out;
  for (const KnownObject* o : objects) out.push_back(o->id);
  return out;
}

TEST(OfficeKnowledge, FindsPlacesPeopleObjectsAndStationsIgnoringCase) {
  const OfficeKnowledge k = test::paper_office();
  ASSERT_NE(k.find_place("MEETING-TABLE"), nullptr);
  EXPECT_EQ(k.find_place("meeting-table")->room, "A-111");
  EXPECT_EQ(k.find_place("nowhere"), nullptr);
  ASSERT_NE(k.find_person("wolfram"), nullptr);
  EXPECT_EQ(k.find_person("wolfram")->desk, "a118-desk");
  EXPECT_EQ(k.find_person("a118-desk"), nullptr);
  ASSERT_NE(k.find_object("Letter-4"), nullptr);
  EXPECT_EQ(k.find_object("letter-4")->place, "a118-desk");
  ASSERT_NE(k.station_at("mail-tray"), nullptr);
  EXPECT_DOUBLE_EQ(k.station_at("mail-tray")->handover_s, 4.0);
  EXPECT_EQ(k.station_at("michael-desk"), nullptr);
}

TEST(OfficeKnowledge, PeopleByRoleAndByDesk) {
  OfficeKnowledge k = test::paper_office();
  k.people[1].roles = {"secretary"};                      // Jan
  k.people[2].roles = {"secretary"};                      // Anna
  ASSERT_EQ(k.people_with_role("librarian").size(), 1u);  // the name counts as a role
  EXPECT_EQ(k.people_with_role("Secretary").size(), 2u);
  EXPECT_TRUE(k.people_with_role("janitor").empty());
  ASSERT_NE(k.person_at("michael-desk"), nullptr);
  EXPECT_EQ(k.person_at("michael-desk")->name, "Michael");
  EXPECT_EQ(k.person_at("meeting-table"), nullptr);
  EXPECT_TRUE(k.people_at("a116-desk").empty());
}

TEST(OfficeKnowledge, PresenceIsHalfOpen) {
  const OfficeKnowledge k = test::paper_office();
  const Person& wolfram = *k.find_person("Wolfram");
  EXPECT_FALSE(wolfram.present_at(hm(9, 59)));
  EXPECT_TRUE(wolfram.present_at(hm(10, 0)));
  EXPECT_FALSE(wolfram.present_at(hm(12, 0)));
  EXPECT_TRUE(wolfram.present_at(hm(18, 59)));
}

TEST(OfficeKnowledge, RoomsAndTheirPlaces) {
  const OfficeKnowledge k = test::paper_office();
  EXPECT_EQ(k.rooms().size(), 13u);
  const auto in_a116 = k.places_in_room("a-116");
  ASSERT_EQ(in_a116.size(), 2u);
  EXPECT_EQ(in_a116[0]->name, "a116-desk");
  EXPECT_EQ(in_a116[1]->name, "mail-tray");
  EXPECT_TRUE(k.places_in_room("A-999").empty());
}

TEST(OfficeKnowledge, ObjectsMatchingByKindColourAndPlace) {
  OfficeKnowledge k = test::paper_office();
  EXPECT_EQ(ids(k.objects_matching("book", "", "librarian-desk")),
            (std::vector<std::string>{"book-green", "book-red"}));
  EXPECT_EQ(ids(k.objects_matching("letter", "red")), (std::vector<std::string>{"letter-red"}));
  EXPECT_EQ(ids(k.objects_matching("", "white")),
            (std::vector<std::string>{"letter-1", "envelope-2", "letter-4"}));
  k.objects[0].place.clear();  // the green book aboard a robot
  k.objects[0].carrier = "rhino";
  EXPECT_EQ(ids(k.objects_matching("book", "green")), std::vector<std::string>{});
  EXPECT_EQ(ids(k.objects_carried_by("RHINO")), (std::vector<std::string>{"book-green"}));
}

TEST(OfficeKnowledge, KindsAndColoursAreLowerCasedAndSorted) {
  OfficeKnowledge k = test::paper_office();
  k.objects.push_back({"parcel-1", "Parcel", "", "mail-tray", "", ""});
  EXPECT_EQ(k.object_kinds(), (std::vector<std::string>{"book", "envelope", "letter", "parcel"}));
  EXPECT_EQ(k.colours(),
            (std::vector<std::string>{"blue", "brown", "green", "red", "white", "yellow"}));
}

}  // namespace
}  // namespace autonomy::courier
