// The fleet's traffic rule (services/behavior/core/traffic): passages derived from the map, the
// total order among claims, waiting outside, obstacles, the wait bound, holding points and the
// path a field drives.
#include "services/behavior/core/goal_tracker.hpp"
#include "services/behavior/core/traffic/brake.hpp"
#include "services/behavior/core/traffic/field_path.hpp"
#include "services/behavior/core/traffic/holding_point.hpp"
#include "services/behavior/core/traffic/passage.hpp"
#include "services/behavior/core/traffic/traffic_rule.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace autonomy::behavior::traffic {
namespace {

using geometry::Vec2;

// A wall along y = 5 across a 10 x 10 world with a 1 m doorway "D1" at x = 5 and a 3 m one "W".
WorldMap two_rooms() {
  WorldMap m;
  m.width_m = 10;
  m.height_m = 10;
  m.obstacles.push_back({0, 4.9, 4.5, 5.1});
  m.obstacles.push_back({5.5, 4.9, 6.5, 5.1});
  m.obstacles.push_back({9.5, 4.9, 10, 5.1});
  m.doors.push_back({"D1", Vec2(5, 5), 1.0, 0.0});
  m.doors.push_back({"W", Vec2(8, 5), 3.0, 0.0});
  return m;
}

std::vector<Passage> passages() { return narrow_passages(two_rooms(), {}); }

OtherRobot robot(const std::string& id, Vec2 at, ClaimState state = ClaimState::None, double request_s = 0.0,
                 bool has_path = true) {
  OtherRobot o;
  o.id = id;
  o.position = at;
  o.has_itinerary = true;
  o.has_path = has_path;
  if (state != ClaimState::None) o.claim = {"D1", state, request_s};
  return o;
}

// A path straight from (5, 2) north through the doorway.
std::vector<Vec2> north_path() {
  std::vector<Vec2> p;
  for (double y = 2.3; y <= 8.0; y += 0.3) p.emplace_back(5.0, y);
  return p;
}

TEST(PassageTest, OnlyDoorwaysTooNarrowForTwoAreReserved) {
  const auto p = passages();
  ASSERT_EQ(p.size(), 1u);  // W is 3 m: two 0.6 m robots and the margin fit
  EXPECT_EQ(p[0].id, "D1");
  EXPECT_EQ(p[0].name, "doorway D1");
  EXPECT_TRUE(p[0].contains(Vec2(5, 5)));
  EXPECT_TRUE(p[0].contains(Vec2(5.7, 5.6)));   // half along 0.8, across 0.7
  EXPECT_FALSE(p[0].contains(Vec2(5, 5.8)));
  EXPECT_NEAR(p[0].distance(Vec2(5, 6.7)), 1.0, 1e-9);
  EXPECT_EQ(narrow_passages(two_rooms(), {0.3, 2.0, 0.1}).size(), 2u);  // a wider margin: W too
  EXPECT_THROW(narrow_passages(two_rooms(), {0.0, 0.4, 0.1}), std::invalid_argument);
}

TEST(TrafficRuleTest, ALoneRobotIsGrantedAtOnce) {
  TrafficRule rule(passages(), "r1");
  auto far = robot("r9", Vec2(5, 14.0));  // 8.3 m from the box
  const auto d = rule.decide(Vec2(5, 3.6), north_path(), {far}, 10.0);
  EXPECT_EQ(d.action, TrafficAction::Drive);
  EXPECT_EQ(d.claim.state, ClaimState::Holding);
}

TEST(TrafficRuleTest, WithARobotNearThePassageIsGrantedAfterTheGrantDelay) {
  TrafficRule rule(passages(), "r1");
  const std::vector<OtherRobot> near{robot("r9", Vec2(8, 8))};  // near, but not claiming it
  auto d = rule.decide(Vec2(5, 2.0), north_path(), near, 10.0);
  EXPECT_EQ(d.action, TrafficAction::Drive);  // far from the box: approaches while requesting
  EXPECT_EQ(d.claim.state, ClaimState::Waiting);
  EXPECT_EQ(d.claim.request_time_s, 10.0);
  d = rule.decide(Vec2(5, 3.6), north_path(), near, 10.3);
  EXPECT_EQ(d.action, TrafficAction::Wait);  // close, the delay not over: stops, nobody named
  EXPECT_EQ(d.blocker, "");
  d = rule.decide(Vec2(5, 3.6), north_path(), near, 10.6);
  EXPECT_EQ(d.claim.state, ClaimState::Holding);
  EXPECT_EQ(d.claim.request_time_s, 10.0);  // the request keeps its time
  d = rule.decide(Vec2(5, 8.0), {}, near, 20.0);
  EXPECT_EQ(d.claim.state, ClaimState::None);  // through: released
}

TEST(TrafficRuleTest, TheRobotInsideWinsAndTheOtherWaitsNamingIt) {
  TrafficRule rule(passages(), "r1");
  const auto others = std::vector<OtherRobot>{robot("r2", Vec2(5, 5.2), ClaimState::Holding, 50.0)};
  const auto d = rule.decide(Vec2(5, 3.5), north_path(), others, 1.0);  // my request is earlier
  EXPECT_EQ(d.action, TrafficAction::Wait);
  EXPECT_EQ(d.blocker, "r2");
  EXPECT_EQ(d.reason, "waiting for r2 to clear doorway D1");
}

TEST(TrafficRuleTest, EarlierRequestThenLowerIdGoesFirst) {
  TrafficRule r1(passages(), "r1");
  TrafficRule r2(passages(), "r2");
  // Both 1 m from the box, r2 asked first.
  (void)r2.decide(Vec2(5, 7.6), {Vec2(5, 5), Vec2(5, 3)}, {}, 1.0);
  (void)r1.decide(Vec2(5, 2.4), north_path(), {}, 2.0);
  const auto d1 = r1.decide(Vec2(5, 3.2), north_path(), {robot("r2", Vec2(5, 6.8), ClaimState::Waiting, 1.0)}, 3.0);
  const auto d2 = r2.decide(Vec2(5, 6.8), {Vec2(5, 5), Vec2(5, 3)}, {robot("r1", Vec2(5, 3.2), ClaimState::Waiting, 2.0)}, 3.0);
  EXPECT_EQ(d1.action, TrafficAction::Wait);
  EXPECT_EQ(d2.claim.state, ClaimState::Holding);
  // Same request time: the lower id.
  TrafficRule a(passages(), "a"), b(passages(), "b");
  (void)a.decide(Vec2(5, 3.2), north_path(), {}, 5.0);
  (void)b.decide(Vec2(5, 6.8), {Vec2(5, 5)}, {}, 5.0);
  EXPECT_EQ(a.decide(Vec2(5, 3.2), north_path(), {robot("b", Vec2(5, 6.8), ClaimState::Waiting, 5.0)}, 6.0).claim.state,
            ClaimState::Holding);
  EXPECT_EQ(b.decide(Vec2(5, 6.8), {Vec2(5, 5)}, {robot("a", Vec2(5, 3.2), ClaimState::Waiting, 5.0)}, 6.0).action,
            TrafficAction::Wait);
}

TEST(TrafficRuleTest, NoRobotWaitsForOneThatWaitsForIt) {
  // Any set of claims on one passage: exactly one of the claimants proceeds, the rest wait for a
  // robot ahead of them in the same order (no cycle in wait-for).
  const std::vector<std::pair<std::string, double>> claims{{"r3", 4.0}, {"r1", 7.0}, {"r2", 4.0}, {"r4", 1.0}};
  int holding = 0;
  for (const auto& [id, t] : claims) {
    TrafficRule rule(passages(), id);
    (void)rule.decide(Vec2(5, 3.6), north_path(), {}, t);
    std::vector<OtherRobot> others;
    for (const auto& [oid, ot] : claims)
      if (oid != id) others.push_back(robot(oid, Vec2(5, 3.6), ClaimState::Waiting, ot));
    const auto d = rule.decide(Vec2(5, 3.6), north_path(), others, 10.0);
    if (id == "r4") {
      EXPECT_EQ(d.claim.state, ClaimState::Holding);
      ++holding;
    } else {
      EXPECT_EQ(d.action, TrafficAction::Wait) << id;
      EXPECT_EQ(d.blocker, "r4") << id;
    }
  }
  EXPECT_EQ(holding, 1);
}

TEST(TrafficRuleTest, ARobotInsideWithoutAFreshItineraryIsAnObstacle) {
  TrafficRule rule(passages(), "r1");
  auto dead = robot("r2", Vec2(5, 5), ClaimState::Holding, 0.0);
  dead.itinerary_age_s = 5.0;
  auto d = rule.decide(Vec2(5, 3.5), north_path(), {dead}, 10.0);
  EXPECT_EQ(d.action, TrafficAction::Obstacle);
  EXPECT_EQ(d.reason, "doorway D1 blocked by r2 (no itinerary for 5.0 s)");
  EXPECT_EQ(d.claim.state, ClaimState::None);
  auto parked = robot("r3", Vec2(5, 5), ClaimState::None, 0.0, false);
  d = rule.decide(Vec2(5, 3.5), north_path(), {parked}, 10.0);
  EXPECT_EQ(d.reason, "doorway D1 blocked by r3 (parked)");
  OtherRobot unknown;
  unknown.id = "x";
  unknown.position = Vec2(5, 5);
  EXPECT_EQ(rule.decide(Vec2(5, 3.5), north_path(), {unknown}, 10.0).reason, "doorway D1 blocked by x (no itinerary)");
  // A stale robot elsewhere holds nothing and blocks nothing.
  dead.position = Vec2(2, 2);
  EXPECT_EQ(rule.decide(Vec2(5, 3.5), north_path(), {dead}, 20.0).claim.state, ClaimState::Waiting);  // asks anew
  EXPECT_EQ(rule.decide(Vec2(5, 3.5), north_path(), {dead}, 20.5).claim.state, ClaimState::Holding);
}

TEST(TrafficRuleTest, AWaitLongerThanTheBoundGivesUpWithTheReason) {
  TrafficSettings s;
  s.max_wait_s = 30.0;
  TrafficRule rule(passages(), "r1", s);
  const std::vector<OtherRobot> others{robot("r2", Vec2(5, 5), ClaimState::Holding, 0.0)};
  EXPECT_EQ(rule.decide(Vec2(5, 3.5), north_path(), others, 100.0).action, TrafficAction::Wait);
  EXPECT_EQ(rule.decide(Vec2(5, 3.5), north_path(), others, 129.0).action, TrafficAction::Wait);
  const auto d = rule.decide(Vec2(5, 3.5), north_path(), others, 130.0);
  EXPECT_EQ(d.action, TrafficAction::GiveUp);
  EXPECT_EQ(d.reason, "waited 30.0 s for r2 to clear doorway D1");
}

TEST(TrafficRuleTest, InsideNeverWaits) {
  TrafficRule rule(passages(), "r2");
  const std::vector<OtherRobot> others{robot("r1", Vec2(5, 3.5), ClaimState::Waiting, 0.0)};
  const auto d = rule.decide(Vec2(5, 5.1), {Vec2(5, 4), Vec2(5, 3)}, others, 50.0);
  EXPECT_EQ(d.action, TrafficAction::Drive);
  EXPECT_EQ(d.claim.state, ClaimState::Holding);
}

TEST(TrafficRuleTest, ClaimWordsRoundTrip) {
  for (auto s : {ClaimState::None, ClaimState::Waiting, ClaimState::Holding}) EXPECT_EQ(claim_state_from(to_string(s)), s);
  EXPECT_FALSE(claim_state_from("granted"));
  EXPECT_THROW(TrafficRule(passages(), ""), std::invalid_argument);
}

TEST(FieldPathTest, FollowsTheFieldThroughTheDoorwayToTheGoal) {
  const OccupancyGrid grid(two_rooms(), 0.1, 0.4);
  const CostToGoField field(grid, Vec2(5, 8));
  const auto path = field_path(field, Vec2(2, 2), 100.0);
  ASSERT_FALSE(path.empty());
  EXPECT_NEAR((path.back() - Vec2(5, 8)).norm(), 0.0, 1e-9);
  bool through_d1 = false;
  for (const auto& p : path) through_d1 |= passages()[0].contains(p);
  EXPECT_TRUE(through_d1);
  EXPECT_LE(field_path(field, Vec2(2, 2), 2.0).size(), 9u);  // cut at the length asked
  EXPECT_TRUE(field_path(field, Vec2(5, 5.0), 5.0).size() > 0);
  EXPECT_TRUE(field_path(field, Vec2(1, 5.0), 5.0).empty());  // inside the wall
}

TEST(HoldingPointTest, WaitsOutsideEveryBoxOffTheOtherPath) {
  const OccupancyGrid grid(two_rooms(), 0.1, 0.4);
  const auto all = passages();
  // r2 comes out of D1 southwards and heads for (5, 2): its path runs down x = 5.
  std::vector<Vec2> their_path;
  for (double y = 5.0; y >= 2.0; y -= 0.3) their_path.emplace_back(5.0, y);
  const auto h = holding_point(grid, Vec2(5, 3.5), all[0], all, their_path);
  ASSERT_TRUE(h);
  EXPECT_GT(all[0].distance(*h), 0.1);
  for (const auto& p : their_path) EXPECT_GE((p - *h).norm(), 0.7);
  EXPECT_LT(h->y(), 4.9);  // on this robot's side of the wall
  EXPECT_FALSE(holding_point(grid, Vec2(1, 5), all[0], all, their_path));  // in the wall
}

TEST(BrakeTest, NoDrivingIntoARobotCloserThanTheGap) {
  const geometry::Pose2 east{0, 0, 0};
  const VelocityCommand forward{0.9, 0.0, 0.3};
  const std::vector<Disc> ahead{{Vec2(0.7, 0.0), 0.3}};  // 0.1 m between the discs
  auto c = brake_for_robots(east, Kinematics::Unicycle, 0.3, forward, ahead);
  EXPECT_EQ(c.vx, 0.0);
  EXPECT_EQ(c.omega, 0.3);  // turning in place stays allowed
  // Behind, or far enough: the command stands.
  EXPECT_EQ(brake_for_robots(east, Kinematics::Unicycle, 0.3, forward, {{Vec2(-0.7, 0.0), 0.3}}).vx, 0.9);
  EXPECT_EQ(brake_for_robots(east, Kinematics::Unicycle, 0.3, forward, {{Vec2(1.0, 0.0), 0.3}}).vx, 0.9);
  // Passing beside it, 0.7 m between the centres' lines (more than the discs and 5 cm): no brake.
  EXPECT_EQ(brake_for_robots(east, Kinematics::Unicycle, 0.3, forward, {{Vec2(0.3, 0.7), 0.3}}).vx, 0.9);
  EXPECT_EQ(brake_for_robots(east, Kinematics::Unicycle, 0.3, forward, {{Vec2(0.3, 0.6), 0.3}}).vx, 0.0);
  // Holonomic: the world-frame velocity counts, not the heading.
  EXPECT_EQ(brake_for_robots(east, Kinematics::Holonomic, 0.3, {0.0, 0.5, 0.0}, {{Vec2(0.0, 0.7), 0.3}}).vy, 0.0);
  EXPECT_EQ(brake_for_robots(east, Kinematics::Holonomic, 0.3, {0.0, -0.5, 0.0}, {{Vec2(0.0, 0.7), 0.3}}).vy, -0.5);
}

TEST(GoalTrackerWaitTest, WaitingIsPublishedOnceAndIsNoStall) {
  GoalTracker t(OccupancyGrid(two_rooms(), 0.1, 0.4));
  const geometry::Pose2 here{2, 2, 0};
  (void)t.set_goal("g", 2, 8, 0.2, 0.0);
  ASSERT_EQ(t.update(here, 0.0).changes.size(), 1u);  // Active
  auto r = t.wait("waiting for r2 to clear doorway D1", 1.0);
  ASSERT_EQ(r.changes.size(), 1u);
  EXPECT_EQ(r.changes[0].state, GoalState::Active);
  EXPECT_EQ(r.changes[0].reason, "waiting for r2 to clear doorway D1");
  EXPECT_TRUE(t.wait("waiting for r2 to clear doorway D1", 2.0).changes.empty());
  EXPECT_TRUE(t.waiting());
  for (double s = 1; s <= 30; s += 1) EXPECT_TRUE(t.update(here, s).changes.empty()) << s;
  r = t.proceed(30.0);
  ASSERT_EQ(r.changes.size(), 1u);
  EXPECT_EQ(r.changes[0].reason, "");
  EXPECT_FALSE(t.waiting());
  // The stall rule holds again from now.
  EXPECT_TRUE(t.update(here, 30.5).changes.empty());
  EXPECT_TRUE(t.update(here, 40.4).changes.empty());
  r = t.update(here, 40.5);
  ASSERT_EQ(r.changes.size(), 1u);
  EXPECT_EQ(r.changes[0].state, GoalState::Blocked);
}

}  // namespace
}  // namespace autonomy::behavior::traffic
