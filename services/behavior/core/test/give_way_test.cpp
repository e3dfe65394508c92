// Meeting outside the narrow passages (services/behavior/core/traffic/give_way.hpp): who gives
// way to whom in a hallway wide enough for two, and where it stands aside.
#include "services/behavior/core/traffic/give_way.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace autonomy::behavior::traffic {
namespace {

using geometry::Vec2;

// A 20 m hallway with 1.8 m free between its walls (y = 1.1 ... 2.9), like the office's.
WorldMap give_way_hall() {
  WorldMap m;
  m.width_m = 20;
  m.height_m = 4;
  m.obstacles.push_back({0, 0.9, 20, 1.1});
  m.obstacles.push_back({0, 2.9, 20, 3.1});
  return m;
}

// A straight path from `from` along x towards `to_x`, a point every 0.3 m.
std::vector<Vec2> give_way_line(Vec2 from, double to_x) {
  std::vector<Vec2> p;
  const double step = to_x > from.x() ? 0.3 : -0.3;
  for (double x = from.x() + step; std::abs(x - to_x) > 0.15; x += step) p.emplace_back(x, from.y());
  return p;
}

OtherRobot give_way_robot(const std::string& id, Vec2 at, std::vector<Vec2> path, ClaimState state = ClaimState::None) {
  OtherRobot o;
  o.id = id;
  o.position = at;
  o.has_itinerary = true;
  o.has_path = !path.empty();
  o.path = std::move(path);
  if (state != ClaimState::None) o.claim = {"", state, 0.0};
  return o;
}

TEST(GiveWayTest, HeadOnTheLaterInTheOrderGivesWayAndTheOtherDrivesOn) {
  const Vec2 a(5, 2), b(8, 2);
  const auto r1 = give_way_robot("r1", a, give_way_line(a, 15));
  const auto r2 = give_way_robot("r2", b, give_way_line(b, 1));
  EXPECT_EQ(give_way_to("r2", b, false, r2.path, {r1}, {}, 2.0), "r1");
  EXPECT_FALSE(give_way_to("r1", a, false, r1.path, {r2}, {}, 2.0));
  // Far apart their stretches do not meet yet.
  const Vec2 c(14, 2);
  EXPECT_FALSE(give_way_to("r2", c, false, give_way_line(c, 1), {r1}, {}, 2.0));
}

TEST(GiveWayTest, FollowingTheSameWayIsNoMeeting) {
  const Vec2 a(5, 2), b(6, 2);
  const auto r1 = give_way_robot("r1", a, give_way_line(a, 15));
  EXPECT_FALSE(give_way_to("r2", b, false, give_way_line(b, 15), {r1}, {}, 2.0));
}

TEST(GiveWayTest, NobodyGivesWayToAStandingOrStaleRobot) {
  const Vec2 a(5, 2), b(7, 2);
  const auto mine = give_way_line(b, 1);
  // Standing aside itself (waiting with its side point), or without a path, or not heard of for
  // longer than the expiry: it waits for nobody's passing, so nobody waits for it.
  EXPECT_FALSE(give_way_to("r2", b, false, mine, {give_way_robot("r1", a, {Vec2(5, 1.6)}, ClaimState::Waiting)}, {}, 2.0));
  EXPECT_FALSE(give_way_to("r2", b, false, mine, {give_way_robot("r1", a, {})}, {}, 2.0));
  auto stale = give_way_robot("r1", a, give_way_line(a, 15));
  stale.itinerary_age_s = 2.5;
  EXPECT_FALSE(give_way_to("r2", b, false, mine, {stale}, {}, 2.0));
}

TEST(GiveWayTest, ARobotInAPassageOrHoldingOneComesFirst) {
  WorldMap m = give_way_hall();
  m.obstacles.push_back({10.5, 0, 10.6, 1.0});  // (the box needs no walls to count)
  m.doors.push_back({"D", Vec2(10, 1), 1.0, 0.0});
  const auto boxes = narrow_passages(m, {});
  ASSERT_EQ(boxes.size(), 1u);
  const Vec2 in_door(10, 1.2), me(12, 2);
  const auto r9 = give_way_robot("r9", in_door, give_way_line(Vec2(10, 2), 15));
  EXPECT_TRUE(meets_first(in_door, {}, boxes));
  EXPECT_EQ(give_way_to("r1", me, false, give_way_line(me, 5), {r9}, boxes, 2.0), "r9");
  EXPECT_FALSE(give_way_to("r1", me, true, give_way_line(me, 5), {r9}, boxes, 2.0));  // both first: the id
  // Holding a reservation counts as being in it.
  EXPECT_TRUE(meets_first(Vec2(15, 2), {"D", ClaimState::Holding, 0.0}, boxes));
  EXPECT_FALSE(meets_first(Vec2(15, 2), {"D", ClaimState::Waiting, 0.0}, boxes));
}

TEST(GiveWayTest, TheSidePointIsOffTheirPathNearbyAndOutsideEveryPassage) {
  WorldMap m = give_way_hall();
  m.doors.push_back({"D", Vec2(8.5, 1), 1.0, 0.0});
  const auto boxes = narrow_passages(m, {});
  const OccupancyGrid grid(m, 0.1, 0.4);
  const Vec2 me(8, 2);
  std::vector<Vec2> theirs = give_way_line(Vec2(4, 2), 15);
  const auto p = side_point(grid, me, theirs, boxes);
  ASSERT_TRUE(p);
  EXPECT_GE(std::abs(p->y() - 2.0), 0.4);  // as far aside as the inflated wall lets it
  EXPECT_LE((*p - me).norm(), 2.0);
  EXPECT_GT(boxes[0].distance(*p), 0.0);
  EXPECT_FALSE(side_point(grid, Vec2(30, 2), theirs, boxes));  // off the grid
  // A robot already stands aside on the south side here: this one keeps 1.4 m from it.
  const auto q = side_point(grid, me, theirs, boxes, {Vec2(8, 1.55)});
  ASSERT_TRUE(q);
  EXPECT_GE((*q - Vec2(8, 1.55)).norm(), 1.4);
}

TEST(GiveWayTest, BadSettingsAreRejected) {
  GiveWaySettings s;
  s.clearance_m = 0.0;
  EXPECT_THROW(give_way_to("r1", Vec2(1, 2), false, {Vec2(2, 2)}, {}, {}, 2.0, s), std::invalid_argument);
}

}  // namespace
}  // namespace autonomy::behavior::traffic
