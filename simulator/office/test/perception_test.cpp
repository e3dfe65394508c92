#include "simulator/office/perception.hpp"
#include "simulator/office/test/office_fixture.hpp"

#include <gtest/gtest.h>

namespace autonomy::sim::office {
namespace {

using test::at_clock;
using test::small_office;

// A wall along x = 4 from y = 0 to y = 4 blocks sight between the two sides.
bool sight_past_wall(const geometry::Vec2& a, const geometry::Vec2& b) {
  if ((a.x() - 4.0) * (b.x() - 4.0) >= 0.0) return true;  // same side
  const double t = (4.0 - a.x()) / (b.x() - a.x());
  const double y = a.y() + t * (b.y() - a.y());
  return y > 4.0;
}

TEST(Perception, SeesObjectsAndPeopleAtVisiblePlacesInRange) {
  OfficeState office(small_office());
  const auto p = perceive(office, "r1", {3.0, 2.0}, 3.5, at_clock(9, 30), sight_past_wall);
  // In range: A-110 (1.4 m), anna-desk (1 m), meeting-table (3 m, behind the wall).
  EXPECT_EQ(p.seen_places, (std::vector<std::string>{"A-110", "anna-desk"}));
  ASSERT_EQ(p.objects.size(), 1u);
  EXPECT_EQ(p.objects[0].id, "letter-1");
  EXPECT_EQ(p.objects[0].colour, "red");
  EXPECT_EQ(p.objects[0].place, "anna-desk");
  ASSERT_EQ(p.people.size(), 1u);
  EXPECT_EQ(p.people[0].name, "Anna");
  EXPECT_DOUBLE_EQ(p.time_s, at_clock(9, 30));

  // Without the wall the envelope on the meeting table is seen too.
  const auto open = perceive(office, "r1", {3.0, 2.0}, 3.5, at_clock(9, 30), {});
  EXPECT_EQ(open.objects.size(), 2u);
  // At lunch Anna is not seen.
  EXPECT_TRUE(perceive(office, "r1", {3.0, 2.0}, 3.5, at_clock(12, 30), {}).people.empty());
}

TEST(Perception, IsACopyAndKnowsWhatTheRobotCarries) {
  OfficeState office(small_office());
  std::mt19937_64 rng(1);
  HandoverRequest r;
  r.robot_id = "r1";
  r.robot_position = {2, 2};
  r.place = "anna-desk";
  r.object_id = "letter-1";
  r.now_s = at_clock(10);
  const auto before = perceive(office, "r1", {2, 2}, 1.0, r.now_s, {});
  ASSERT_TRUE(office.request_load(r, rng).accepted);
  (void)office.advance(r.now_s + 20, {{"r1", {2, 2}}});
  EXPECT_EQ(before.objects.size(), 1u);  // the old percept still shows the letter lying there
  const auto after = perceive(office, "r1", {2, 2}, 1.0, r.now_s + 20, {});
  EXPECT_TRUE(after.objects.empty());
  EXPECT_EQ(after.carried, std::vector<std::string>{"letter-1"});
}

}  // namespace
}  // namespace autonomy::sim::office
