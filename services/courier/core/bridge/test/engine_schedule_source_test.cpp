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
    floor.places = {{"r1-desk", {3, 2, "R1", 1.0}}, {"r2-desk", {17, 2, "R2", 1.0}}, {"hall", {10, 8, "", 1.0}}};
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
