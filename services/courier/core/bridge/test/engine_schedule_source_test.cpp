// The bridge on a small two-room floor drawn here: travel times from the grid (doors closed are
// walls), presence windows from the knowledge, the exact engine's routes back as plan stops.
#include "services/courier/core/bridge/engine_schedule_source.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace autonomy::courier {
namespace {

// 20 x 10 m: a hallway y in [5, 10], rooms R1 (x < 10) and R2 (x > 10) south of it, each entered
// through a 1.2 m doorway in the wall at y = 5 (doors D1 at x = 5, D2 at x = 15).
struct SmallOffice {
  OfficeKnowledge knowledge;
  Floor floor;
  behavior::WorldMap map;
  SmallOffice() {
    map.width_m = 20;
    map.height_m = 10;
    map.obstacles = {{0, 4.9, 4.4, 5.1}, {5.6, 4.9, 14.4, 5.1}, {15.6, 4.9, 20, 5.1}, {9.9, 0, 10.1, 4.9}};
    map.doors = {{"D1", geometry::Vec2(5.0, 5.0), 1.2, 0.0}, {"D2", geometry::Vec2(15.0, 5.0), 1.2, 0.0}};
    floor.places = {{"r1-desk", {3, 2, "R1", 1.0, "Ann"}}, {"r2-desk", {17, 2, "R2", 1.0, "Bob"}},
                    {"hall", {10, 8, "", 1.0, ""}}};
    floor.door_of_room = {{"R1", "D1"}, {"R2", "D2"}};
    knowledge.places = {{"r1-desk", PlaceKind::desk, "R1", 3, 2, {}},
                        {"r2-desk", PlaceKind::desk, "R2", 17, 2, {}},
                        {"hall", PlaceKind::table, "", 10, 8, {}}};
    knowledge.people = {{"Ann", {}, "r1-desk", {{0, 86400}}, 10.0}, {"Bob", {}, "r2-desk", {{36000, 43200}}, 20.0}};
    knowledge.stations = {{"hall", 4.0}};
  }
};

EngineSourceSettings settings() {
  EngineSourceSettings s;
  s.speed_mps = 1.0;
  s.robot_radius_m = 0.3;
  s.resolution_m = 0.1;
  return s;
}

TEST(EngineScheduleSource, TravelTimesComeFromTheGridAndClosedDoorsCutRoomsOff) {
  SmallOffice o;
  EngineScheduleSource source(o.knowledge, o.floor, o.map, settings());
  const double open = source.travel_s("r1-desk", "r2-desk", {});
  // Out of R1 through D1, along the hallway, into R2 through D2: longer than the 14 m straight line.
  EXPECT_GT(open, 14.0);
  EXPECT_LT(open, 14.0 + 2 * 3.2 + 1.5);
  EXPECT_TRUE(std::isinf(source.travel_s("r1-desk", "r2-desk", {"D2"})));
  EXPECT_TRUE(std::isfinite(source.travel_s("r1-desk", "hall", {"D2"})));
}

TEST(EngineScheduleSource, PlansRoutesWithPresenceAndReportsJobsBehindClosedDoors) {
  SmallOffice o;
  EngineScheduleSource source(o.knowledge, o.floor, o.map, settings());
  PlanRequest request;
  request.now_s = 9 * 3600.0;  // Bob is in from 10:00
  request.robots = {{"r", 10.0, 8.0, 2}};
  request.jobs = {{"to-bob", "letter/red", "r1-desk", "r2-desk", std::nullopt, ""},
                  {"to-hall", "book/green", "r1-desk", "hall", 9 * 3600.0 + 300, ""}};
  const Plan plan = source.plan(request);
  EXPECT_EQ(plan.engine, "exact");
  EXPECT_TRUE(plan.proved_optimal);
  EXPECT_TRUE(plan.unschedulable.empty());
  ASSERT_EQ(plan.routes.count("r"), 1u);
  const auto& stops = plan.routes.at("r");
  ASSERT_EQ(stops.size(), 4u);
  EXPECT_EQ(plan.late_jobs, 0);
  // Bob's unload cannot start before 10:00: it comes last.
  EXPECT_EQ(stops.back().job_id, "to-bob");
  EXPECT_FALSE(stops.back().load);
  EXPECT_GE(stops.back().finish_s, 36000.0 + 20.0 - 1e-6);
  EXPECT_EQ(stops.back().room, "R2");
  EXPECT_GE(plan.completion_s.at("to-bob"), 36000.0);

  request.closed_doors = {"D2"};
  const Plan cut = source.plan(request);
  ASSERT_EQ(cut.unschedulable.count("to-bob"), 1u);
  EXPECT_EQ(cut.routes.at("r").size(), 2u);  // the other job goes on
}

TEST(EngineScheduleSource, ForcedFirstJobLeadsTheRoute) {
  SmallOffice o;
  EngineScheduleSource source(o.knowledge, o.floor, o.map, settings());
  PlanRequest request;
  request.now_s = 11 * 3600.0;
  request.robots = {{"r", 10.0, 8.0, 2}};
  request.jobs = {{"a", "letter/red", "hall", "r1-desk", std::nullopt, "r"},
                  {"b", "book/green", "hall", "r2-desk", std::nullopt, "r"}};
  request.first = {"b"};
  const Plan plan = source.plan(request);
  ASSERT_FALSE(plan.routes.at("r").empty());
  EXPECT_EQ(plan.routes.at("r").front().job_id, "b");
}

TEST(EngineScheduleSource, SeveralRobotsGetJobsWithTheAllocationRuleInWords) {
  SmallOffice o;
  EngineScheduleSource source(o.knowledge, o.floor, o.map, settings());
  PlanRequest request;
  request.now_s = 11 * 3600.0;  // Bob is in
  // One robot in each room: each job is for the robot beside its pickup.
  request.robots = {{"west", 3.0, 3.0, 1}, {"east", 17.0, 3.0, 1}};
  request.jobs = {{"from-ann", "letter/red", "r1-desk", "hall", std::nullopt, ""},
                  {"from-bob", "book/green", "r2-desk", "hall", std::nullopt, ""}};
  const Plan plan = source.plan(request);
  EXPECT_EQ(plan.engine, "exact");
  ASSERT_EQ(plan.routes.count("west"), 1u);
  ASSERT_EQ(plan.routes.count("east"), 1u);
  ASSERT_EQ(plan.routes.at("west").size(), 2u);
  EXPECT_EQ(plan.routes.at("west")[0].job_id, "from-ann");
  EXPECT_EQ(plan.routes.at("east")[0].job_id, "from-bob");
  ASSERT_EQ(plan.allocation.count("from-ann"), 1u);
  EXPECT_EQ(plan.allocation.at("from-ann").rfind("assigned to west: ", 0), 0u) << plan.allocation.at("from-ann");
  EXPECT_NE(plan.allocation.at("from-ann").find(" earlier than east"), std::string::npos) << plan.allocation.at("from-ann");
  EXPECT_EQ(plan.allocation.at("from-bob").rfind("assigned to east: ", 0), 0u) << plan.allocation.at("from-bob");

  // Alone: no choice, no words.
  request.robots.resize(1);
  EXPECT_TRUE(source.plan(request).allocation.empty());
}

TEST(EngineScheduleSource, ARobotFreeOnlyLaterSetsOutThenOrLeavesTheJobToAnother) {
  SmallOffice o;
  EngineScheduleSource source(o.knowledge, o.floor, o.map, settings());
  PlanRequest request;
  request.now_s = 11 * 3600.0;
  // "west" waits 120 s for a room (room_claims.cpp); "east" is free now but 10 m farther away.
  request.robots = {{"west", 6.0, 8.0, 2, request.now_s + 120}, {"east", 16.0, 8.0, 2, 0.0}};
  request.jobs = {{"to-hall", "letter/red", "r1-desk", "hall", std::nullopt, ""}};
  Plan plan = source.plan(request);
  // Waiting, the nearer robot would finish later than the farther one that can go now.
  ASSERT_EQ(plan.routes.count("east"), 1u);
  EXPECT_EQ(plan.routes.count("west") ? plan.routes.at("west").size() : 0u, 0u);

  // Alone, it sets out when it is free: its first stop is reached no sooner than that.
  request.robots.resize(1);
  plan = source.plan(request);
  ASSERT_EQ(plan.routes.at("west").size(), 2u);
  EXPECT_GE(plan.routes.at("west")[0].arrival_s, request.now_s + 120);
  // Free "now" (0, or any time not after now) means at once.
  request.robots[0].available_s = 0.0;
  plan = source.plan(request);
  EXPECT_LT(plan.routes.at("west")[0].arrival_s, request.now_s + 120);
}

TEST(EngineScheduleSource, AnObjectKeptAboardTakesItsPlaceAndIsNotDelivered) {
  SmallOffice o;
  EngineScheduleSource source(o.knowledge, o.floor, o.map, settings());
  PlanRequest request;
  request.now_s = 11 * 3600.0;
  request.robots = {{"r", 10.0, 8.0, 1}};  // room for one object
  PlanJob kept{"waiting", "letter/red", "", "r2-desk", std::nullopt, "r"};
  kept.keep_aboard = true;
  request.jobs = {kept, {"new", "book/green", "r1-desk", "hall", std::nullopt, ""}};
  Plan plan = source.plan(request);
  // The robot is full: nothing is planned, and the kept object's delivery is left out.
  EXPECT_TRUE(plan.routes.count("r") == 0 || plan.routes.at("r").empty());
  EXPECT_EQ(plan.unschedulable.count("waiting"), 1u);
  EXPECT_EQ(plan.unschedulable.count("new"), 1u);

  // Not kept: it is delivered first, then the new job fits.
  request.jobs[0].keep_aboard = false;
  plan = source.plan(request);
  ASSERT_EQ(plan.routes.at("r").size(), 3u);
  EXPECT_EQ(plan.routes.at("r")[0].job_id, "waiting");
  EXPECT_TRUE(plan.unschedulable.empty());
}

TEST(EngineScheduleSource, ExactOnlyWhileTheAssignmentsCanBeEnumerated) {
  SmallOffice o;
  EngineScheduleSource source(o.knowledge, o.floor, o.map, settings());
  PlanRequest request;
  request.now_s = 11 * 3600.0;
  for (int r = 0; r < 4; ++r) request.robots.push_back({"r" + std::to_string(r), 10.0, 8.0, 3});
  for (int j = 0; j < 7; ++j)  // 4^7 = 16384 assignments: still exact
    request.jobs.push_back({"j" + std::to_string(j), "letter/c" + std::to_string(j), "r1-desk", "hall", std::nullopt, ""});
  EXPECT_EQ(source.engine_for(source.problem_for(request)), "exact");
  request.jobs.push_back({"j7", "letter/c7", "r1-desk", "hall", std::nullopt, ""});  // 4^8
  EXPECT_EQ(source.engine_for(source.problem_for(request)), "large");
  request.robots.resize(1);  // one robot, 8 jobs: exact again (exact_max_jobs 8)
  EXPECT_EQ(source.engine_for(source.problem_for(request)), "exact");
}

}  // namespace
}  // namespace autonomy::courier

namespace autonomy::courier {
namespace {

// What experience taught changes the plan: Bob's door is usually closed 10:00-11:00 (three
// days said so), so his delivery waits for 11:00; seen open a minute ago, it does not.
TEST(EngineScheduleSource, LearnedDoorHabitsHandoverAndTravelTimesShapeThePlan) {
  SmallOffice o;
  EngineScheduleSource source(o.knowledge, o.floor, o.map, settings());
  Experience learned;
  for (std::int64_t day = 1; day <= 3; ++day) {
    learned.door("D2", 36000 + 60, false, day);
    learned.door("D2", 37800 + 60, false, day);
  }
  for (double s : {30.0, 40.0, 50.0}) learned.handover("Bob", s);
  for (int i = 0; i < 3; ++i) learned.travel("r1-desk", "r2-desk", 100.0);
  source.use_experience(&learned);

  PlanRequest request;
  request.now_s = 36000.0;
  request.robots = {{"r", 3.0, 2.0, 1}};
  request.jobs = {{"to-bob", "letter/red", "r1-desk", "r2-desk", std::nullopt, ""}};
  const auto problem = source.problem_for(request);
  ASSERT_EQ(problem.people.size(), 2u);
  EXPECT_DOUBLE_EQ(problem.people[1].handover_s, 40.0);  // Bob: learned, not the nominal 20
  ASSERT_EQ(problem.people[1].presence.size(), 1u);
  EXPECT_DOUBLE_EQ(problem.people[1].presence[0].start_s, 39600.0);  // 11:00, not 10:00
  EXPECT_DOUBLE_EQ(problem.people[1].presence[0].end_s, 43200.0);
  EXPECT_EQ(problem.people[0].presence.size(), 1u);  // Ann's door taught nothing
  EXPECT_DOUBLE_EQ(problem.people[0].presence[0].start_s, 0.0);

  const Plan plan = source.plan(request);
  ASSERT_EQ(plan.routes.at("r").size(), 2u);
  EXPECT_GE(plan.routes.at("r").back().arrival_s, 36000.0 + 100.0 - 1e-6);  // the learned drive
  EXPECT_GE(plan.completion_s.at("to-bob"), 39600.0 + 40.0 - 1e-6);

  // Seen open lately: the habit does not apply, Bob gets it now.
  request.doors_seen_open = {"D2"};
  const Plan now = source.plan(request);
  EXPECT_LT(now.completion_s.at("to-bob"), 39600.0);

  // Closed all of Bob's hours: unschedulable, and the reason says what was learned.
  for (double t = 39600; t < 43200; t += 1800)
    for (std::int64_t day = 1; day <= 3; ++day) learned.door("D2", t + 60, false, day);
  request.doors_seen_open.clear();
  const Plan none = source.plan(request);
  ASSERT_EQ(none.unschedulable.count("to-bob"), 1u);
  EXPECT_NE(none.unschedulable.at("to-bob").find("learned: D2 usually closed 10:00-12:00"), std::string::npos)
      << none.unschedulable.at("to-bob");
}

// A door believed closed makes the map's times detours: a learned time, driven with the doors
// open, may lengthen them but never shortens them.
TEST(EngineScheduleSource, LearnedTravelNeverShortensADetourAroundAClosedDoor) {
  SmallOffice o;
  EngineScheduleSource source(o.knowledge, o.floor, o.map, settings());
  Experience learned;
  for (int i = 0; i < 3; ++i) learned.travel("r1-desk", "hall", 1.0);
  source.use_experience(&learned);
  PlanRequest request;
  request.now_s = 36000.0;
  request.robots = {{"r", 3.0, 2.0, 1}};
  request.jobs = {{"to-hall", "letter/red", "r1-desk", "hall", std::nullopt, ""}};
  const auto index = [](const scheduling::SchedulingProblem& p, const std::string& name) {
    for (std::size_t i = 0; i < p.locations.size(); ++i)
      if (p.locations[i].name == name) return i;
    ADD_FAILURE() << "no location " << name;
    return std::size_t{0};
  };
  const auto open = source.problem_for(request);
  EXPECT_DOUBLE_EQ(open.travel.at(index(open, "r1-desk"), index(open, "hall")), 1.0);
  request.closed_doors = {"D2"};
  const auto closed = source.problem_for(request);
  const double map_estimate = source.travel_s("r1-desk", "hall", {"D2"});
  ASSERT_GT(map_estimate, 1.0);
  EXPECT_DOUBLE_EQ(closed.travel.at(index(closed, "r1-desk"), index(closed, "hall")), map_estimate);
}

}  // namespace
}  // namespace autonomy::courier
