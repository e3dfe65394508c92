#include "services/courier/core/knowledge/name_lookup.hpp"

#include "services/courier/core/knowledge/office_knowledge.hpp"
#include "services/courier/core/knowledge/test/paper_office.hpp"

#include <gtest/gtest.h>

namespace autonomy::courier {
namespace {

TEST(EditDistance, CountsInsertionsDeletionsSubstitutionsAndSwaps) {
  EXPECT_EQ(edit_distance("", ""), 0u);
  EXPECT_EQ(edit_distance("abc", ""), 3u);
  EXPECT_EQ(edit_distance("", "ab"), 2u);
  EXPECT_EQ(edit_distance("A-111", "a-111"), 0u);  // case-insensitive
  EXPECT_EQ(edit_distance("A-112", "A-111"), 1u);
  EXPECT_EQ(edit_distance("A-112", "A-121"), 1u);  // a swap of neighbours is one edit
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);
  EXPECT_EQ(edit_distance("michael", "micheal"), 1u);
  EXPECT_EQ(edit_distance("ca", "abc"), 3u);  // optimal string alignment, not full Damerau
}

TEST(ClosestNames, NearestFirstWithinALengthDependentDistance) {
  const std::vector<std::string> rooms = {"A-110", "A-111", "A-120", "A-121", "A-114"};
  EXPECT_EQ(closest_names("A-112", rooms), (std::vector<std::string>{"A-110", "A-111", "A-121"}));
  EXPECT_EQ(closest_names("A-112", rooms, 2), (std::vector<std::string>{"A-110", "A-111"}));
  EXPECT_TRUE(closest_names("B-999", rooms).empty());
  EXPECT_EQ(closest_names("Micheal", {"Michael", "Anna"}), (std::vector<std::string>{"Michael"}));
  EXPECT_TRUE(closest_names("xyz", {"Michael"}).empty());
}

TEST(DidYouMean, JoinsWithCommasAndOr) {
  EXPECT_EQ(did_you_mean({}), "");
  EXPECT_EQ(did_you_mean({"A"}), "did you mean A?");
  EXPECT_EQ(did_you_mean({"A-111", "A-121"}), "did you mean A-111 or A-121?");
  EXPECT_EQ(did_you_mean({"a", "b", "c"}), "did you mean a, b or c?");
}

TEST(LookupName, PlacesRoomsPeopleAndRoles) {
  OfficeKnowledge k = test::paper_office();
  k.people[3].roles = {"professor"};  // Wolfram
  const NameMeaning room = lookup_name(k, "a-120");
  ASSERT_NE(room.place, nullptr);
  EXPECT_EQ(room.place->name, "A-120");
  EXPECT_EQ(room.place->kind, PlaceKind::room);
  EXPECT_EQ(lookup_name(k, "Mail Room").place->name, "A-116");  // an alias
  const NameMeaning michael = lookup_name(k, "MICHAEL");
  EXPECT_EQ(michael.place, nullptr);
  ASSERT_EQ(michael.people.size(), 1u);
  EXPECT_EQ(michael.people[0]->desk, "michael-desk");
  const NameMeaning professor = lookup_name(k, "professor");
  ASSERT_EQ(professor.people.size(), 1u);
  EXPECT_EQ(professor.people[0]->name, "Wolfram");
  EXPECT_TRUE(lookup_name(k, "A-122").empty());
}

TEST(KnownNames, PlacesAliasesPeopleAndRoles) {
  OfficeKnowledge k = test::paper_office();
  k.people[0].roles = {"keeper"};
  const auto all = known_names(k);
  const auto places = known_names(k, true);
  auto has = [](const std::vector<std::string>& v, const char* s) {
    return std::find(v.begin(), v.end(), s) != v.end();
  };
  EXPECT_TRUE(has(all, "mail room"));
  EXPECT_TRUE(has(all, "Michael"));
  EXPECT_TRUE(has(all, "keeper"));
  EXPECT_TRUE(has(places, "A-121"));
  EXPECT_FALSE(has(places, "Michael"));
  EXPECT_EQ(all.size(), places.size() + k.people.size() + 1);
}

}  // namespace
}  // namespace autonomy::courier
