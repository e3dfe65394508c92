// The fleet's rule for rooms (room_claims.cpp): one robot in a room at a time. A robot whose next
// stop is in a room another robot is in or bound for waits beside the door and says for whom;
// robots waiting for one room go in the order they began to wait; two robots each in the room the
// other needs both get in; a robot parked in a room does not hold it.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "services/courier/core/execution/test/fleet_fixture.hpp"
#include "services/courier/core/execution/test/paper_floor.hpp"

namespace autonomy::courier {
namespace {

using test_support::delivery;
using test_support::FleetTest;

// The paper's floor with the rooms' areas (the library A-110 south of the hallway, the meeting
// room A-111 north of it), a parking spot in a corner of the meeting room and one in the hallway.
Floor floor_with_rooms() {
  Floor f = test_support::paper_floor();
  f.room_areas["A-110"] = {0.0, 0.0, 10.0, 6.9};
  f.room_areas["A-111"] = {0.0, 9.1, 8.0, 16.0};
  f.room_areas["A-114"] = {16.0, 0.0, 22.0, 6.9};
  f.parking = {{"a111-corner", 7.3, 15.3}, {"hall-mid", 9.0, 8.4}};
  return f;
}

class RoomClaimsTest : public FleetTest {
 protected:
  RoomClaimsTest() : FleetTest(floor_with_rooms()) {}

  // The goal `robot` got in `o`, if any.
  static const NavGoalOrder* goal_of(const Orders& o, const std::string& robot) {
    for (const auto& g : o.goals)
      if (g.robot == robot) return &g;
    return nullptr;
  }
  bool bound_for(const std::string& robot, const std::string& place) const {
    const auto it = goals_.find(robot);
    return it != goals_.end() && it->second.goal_id.find("/" + place + "/") != std::string::npos;
  }
  std::vector<std::string> waits() const { return texts(ExecutionEvent::Kind::waiting); }
};

TEST_F(RoomClaimsTest, TwoRobotsForOneDeskGoInOneAfterTheOther) {
  exec_.add_robot("rhino", 3);
  exec_.add_robot("rhino2", 3);
  exec_.on_pose("rhino", 6.0, 8.0);
  exec_.on_pose("rhino2", 12.0, 8.0);
  scheduler_.prefer = {{"job-1", "rhino"}, {"job-2", "rhino2"}};
  exec_.add_job(delivery("job-1", "red", "librarian-desk", "a114-desk"), now_);
  exec_.add_job(delivery("job-2", "blue", "librarian-desk", "meeting-table"), now_);
  Orders o = step();
  // rhino goes in; rhino2 waits beside the library's door (its lookout), saying for whom.
  EXPECT_TRUE(bound_for("rhino", "librarian-desk"));
  const NavGoalOrder* lookout = goal_of(o, "rhino2");
  ASSERT_NE(lookout, nullptr);
  EXPECT_DOUBLE_EQ(lookout->x, 2.8);
  EXPECT_DOUBLE_EQ(lookout->y, 7.6);
  ASSERT_EQ(waits().size(), 1u);
  EXPECT_EQ(waits()[0], "rhino2 waits for rhino to clear A-110 before librarian-desk (09:00:00)");
  const Job* waiting = exec_.job("job-2");
  EXPECT_EQ(waiting->state, JobState::underway);
  EXPECT_EQ(waiting->phase, JobPhase::to_pickup);
  EXPECT_EQ(waiting->robot, "rhino2");
  EXPECT_EQ(waiting->reason, "waiting for rhino to clear A-110");

  // rhino loads and sets off for A-114, but is still in the library: rhino2 still waits.
  reach("rhino", 3.5, 4.5);
  complete("rhino");
  EXPECT_TRUE(bound_for("rhino", "a114-desk"));
  exec_.on_pose("rhino2", 2.8, 7.6);
  exec_.on_goal("rhino2", goals_.at("rhino2").goal_id, GoalOutcome::reached, "", now_);
  exec_.on_pose("rhino", 1.7, 6.0);  // in the doorway, on its way out
  now_ += 2;
  step();
  EXPECT_FALSE(bound_for("rhino2", "librarian-desk"));
  EXPECT_EQ(waits().size(), 1u);  // said once

  // Out in the hallway: the library is free, rhino2 goes in and its job no longer waits.
  exec_.on_pose("rhino", 3.0, 8.0);
  now_ += 2;
  step();
  EXPECT_TRUE(bound_for("rhino2", "librarian-desk"));
  EXPECT_EQ(exec_.job("job-2")->reason, "");
  EXPECT_EQ(exec_.job("job-2")->state, JobState::underway);
}

TEST_F(RoomClaimsTest, TheScheduleSeesAWaitingRobotFreeWhenTheHolderIsPlannedToLeave) {
  exec_.add_robot("rhino", 3);
  exec_.add_robot("rhino2", 3);
  exec_.on_pose("rhino", 6.0, 8.0);
  exec_.on_pose("rhino2", 12.0, 8.0);
  scheduler_.prefer = {{"job-1", "rhino"}, {"job-2", "rhino2"}, {"job-3", "rhino2"}};
  const double t0 = now_;
  exec_.add_job(delivery("job-1", "red", "librarian-desk", "a114-desk"), now_);
  exec_.add_job(delivery("job-2", "blue", "librarian-desk", "meeting-table"), now_);
  step();
  ASSERT_EQ(waits().size(), 1u);
  // A new job makes a new schedule: rhino2 is seen free when rhino's stop at the librarian's
  // desk ends as the last schedule timed it (60 s per stop here); rhino at once.
  now_ += 5;
  exec_.add_job(delivery("job-3", "green", "hallway-west", "a114-desk"), now_);
  step();
  const PlanRequest& request = scheduler_.requests.back();
  ASSERT_EQ(request.robots.size(), 2u);
  EXPECT_EQ(request.robots[0].id, "rhino");
  EXPECT_DOUBLE_EQ(request.robots[0].available_s, now_);
  EXPECT_EQ(request.robots[1].id, "rhino2");
  EXPECT_DOUBLE_EQ(request.robots[1].available_s, t0 + 60);
}

TEST_F(RoomClaimsTest, RobotsWaitingForOneRoomGoInTheOrderTheyBeganToWait) {
  // rhino3 is in the meeting room; rhino2 begins to wait for it, then rhino (first by id).
  exec_.add_robot("rhino", 3);
  exec_.add_robot("rhino2", 3);
  exec_.add_robot("rhino3", 3);
  exec_.on_pose("rhino", 30.0, 8.0);
  exec_.on_pose("rhino2", 12.0, 8.0);
  exec_.on_pose("rhino3", 4.0, 10.7);
  scheduler_.prefer = {{"job-1", "rhino3"}, {"job-2", "rhino2"}};
  exec_.add_job(delivery("job-1", "red", "meeting-table", "a114-desk"), now_);
  exec_.add_job(delivery("job-2", "blue", "a114-desk", "meeting-table"), now_);
  step();
  // rhino3 is at the table: it loads. rhino2 picks up at A-114 and then waits for the room.
  ASSERT_EQ(handovers_.count("rhino3"), 1u);
  reach("rhino2", 19.0, 2.6);
  complete("rhino2");
  EXPECT_FALSE(bound_for("rhino2", "meeting-table"));
  ASSERT_EQ(waits().size(), 1u);
  EXPECT_EQ(waits()[0].rfind("rhino2 waits for rhino3 to clear A-111", 0), 0u) << waits()[0];
  exec_.on_pose("rhino2", 5.2, 8.4);  // at the lookout
  exec_.on_goal("rhino2", goals_.at("rhino2").goal_id, GoalOutcome::reached, "", now_);

  now_ += 10;
  scheduler_.prefer["job-3"] = "rhino";
  exec_.add_job(delivery("job-3", "green", "hallway-west", "meeting-table"), now_);
  step();
  reach("rhino", 1.5, 8.0);
  complete("rhino");
  // rhino, with a smaller id, waits behind rhino2: parked out of the hallway (not at the lookout
  // rhino2 holds, nor at the spot in the meeting room it waits for).
  ASSERT_EQ(waits().size(), 2u);
  EXPECT_EQ(waits()[1].rfind("rhino waits for rhino3 to clear A-111", 0), 0u) << waits()[1];
  EXPECT_FALSE(bound_for("rhino", "meeting-table"));
  EXPECT_NE(goals_.at("rhino").goal_id.find("rhino/park/"), std::string::npos) << goals_.at("rhino").goal_id;
  EXPECT_DOUBLE_EQ(goals_.at("rhino").x, 9.0);
  const auto heading = texts(ExecutionEvent::Kind::heading);
  EXPECT_EQ(heading.back().rfind("rhino parks at hall-mid (9.0, 8.4), out of the way: waiting for A-111", 0), 0u)
      << heading.back();

  // rhino3 finishes its load and leaves for A-114: rhino2 goes in, rhino waits for rhino2 now.
  complete("rhino3");
  exec_.on_pose("rhino3", 6.0, 8.0);
  now_ += 2;
  step();
  EXPECT_TRUE(bound_for("rhino2", "meeting-table"));
  EXPECT_FALSE(bound_for("rhino", "meeting-table"));
  now_ += 1;
  step();
  EXPECT_FALSE(bound_for("rhino", "meeting-table"));
  EXPECT_EQ(exec_.job("job-3")->reason, "waiting for rhino2 to clear A-111");

  // rhino2 unloads and leaves: rhino's turn.
  reach("rhino2", 4.0, 10.7);
  complete("rhino2");
  exec_.on_pose("rhino2", 9.0, 8.0);
  now_ += 2;
  step();
  EXPECT_TRUE(bound_for("rhino", "meeting-table"));
  EXPECT_EQ(exec_.job("job-3")->reason, "");
}

TEST_F(RoomClaimsTest, TwoRobotsEachInTheRoomTheOtherNeedsBothGetIn) {
  exec_.add_robot("rhino", 3);
  exec_.add_robot("rhino2", 3);
  exec_.on_pose("rhino", 3.5, 4.5);    // in the library
  exec_.on_pose("rhino2", 4.0, 10.7);  // in the meeting room
  scheduler_.prefer = {{"job-1", "rhino"}, {"job-2", "rhino2"}};
  exec_.add_job(delivery("job-1", "red", "meeting-table", "a114-desk"), now_);
  exec_.add_job(delivery("job-2", "blue", "librarian-desk", "a114-desk"), now_);
  Orders o = step();
  // Each waits outside the room it needs: out of the room the other needs.
  const NavGoalOrder* out1 = goal_of(o, "rhino");
  const NavGoalOrder* out2 = goal_of(o, "rhino2");
  ASSERT_NE(out1, nullptr);
  ASSERT_NE(out2, nullptr);
  EXPECT_DOUBLE_EQ(out1->x, 5.2);  // A-111's lookout
  EXPECT_DOUBLE_EQ(out2->x, 2.8);  // A-110's lookout
  exec_.on_pose("rhino", 5.2, 8.4);
  exec_.on_pose("rhino2", 2.8, 7.6);
  exec_.on_goal("rhino", out1->goal_id, GoalOutcome::reached, "", now_);
  exec_.on_goal("rhino2", out2->goal_id, GoalOutcome::reached, "", now_);
  now_ += 2;
  step();
  EXPECT_TRUE(bound_for("rhino", "meeting-table"));
  EXPECT_TRUE(bound_for("rhino2", "librarian-desk"));
}

TEST_F(RoomClaimsTest, ARobotParkedInARoomDoesNotHoldItOneDrivingToItsSpotDoes) {
  exec_.add_robot("rhino", 3);
  exec_.add_robot("rhino2", 3);
  exec_.on_pose("rhino", 6.0, 14.0);  // in the meeting room, off its parking spot
  exec_.on_pose("rhino2", 12.0, 8.0);
  scheduler_.prefer = {{"job-1", "rhino2"}};
  exec_.add_job(delivery("job-1", "red", "meeting-table", "a114-desk"), now_);
  Orders o = step();
  // rhino, idle, drives to the room's spot; until it is there it is in the way.
  const NavGoalOrder* park = goal_of(o, "rhino");
  ASSERT_NE(park, nullptr);
  EXPECT_DOUBLE_EQ(park->x, 7.3);
  EXPECT_FALSE(bound_for("rhino2", "meeting-table"));
  ASSERT_EQ(waits().size(), 1u);
  EXPECT_EQ(waits()[0], "rhino2 waits for rhino to clear A-111 before meeting-table (09:00:00)");

  // Parked: out of the way, the room is free.
  exec_.on_pose("rhino", 7.3, 15.3);
  exec_.on_goal("rhino", park->goal_id, GoalOutcome::reached, "", now_);
  now_ += 2;
  step();
  EXPECT_TRUE(bound_for("rhino2", "meeting-table"));
  EXPECT_EQ(exec_.job("job-1")->reason, "");
}

TEST_F(RoomClaimsTest, APlaceInTheHallwayTakesOneRobotAtATimeTheNextWaitsWhereItIs) {
  exec_.add_robot("rhino", 3);
  exec_.add_robot("rhino2", 3);
  exec_.add_robot("rhino3", 3);
  exec_.on_pose("rhino", 6.0, 8.0);
  exec_.on_pose("rhino2", 12.0, 8.0);
  exec_.on_pose("rhino3", 14.0, 8.0);
  scheduler_.prefer = {{"job-1", "rhino"}, {"job-2", "rhino2"}, {"job-3", "rhino3"}};
  exec_.add_job(delivery("job-1", "red", "hallway-west", "a114-desk"), now_);
  exec_.add_job(delivery("job-2", "blue", "hallway-west", "meeting-table"), now_);
  exec_.add_job(delivery("job-3", "green", "hallway-west", "librarian-desk"), now_);
  step();
  // rhino drives to the place; rhino2, first in line, stops where it is (no lookout in the
  // hallway, the wait is one handover); rhino3, second in line, parks.
  EXPECT_TRUE(bound_for("rhino", "hallway-west"));
  EXPECT_FALSE(bound_for("rhino2", "hallway-west"));
  EXPECT_FALSE(bound_for("rhino3", "hallway-west"));
  EXPECT_EQ(goals_.count("rhino2"), 0u);
  ASSERT_EQ(goals_.count("rhino3"), 1u);
  EXPECT_NE(goals_.at("rhino3").goal_id.find("rhino3/park/"), std::string::npos) << goals_.at("rhino3").goal_id;
  EXPECT_EQ(exec_.job("job-2")->reason, "waiting for rhino to clear hallway-west");
  EXPECT_EQ(exec_.job("job-3")->reason, "waiting for rhino to clear hallway-west");  // the holder named

  // rhino loads and leaves: on its way but still on the place, it holds it; off it, rhino2 goes.
  reach("rhino", 1.5, 8.0);
  complete("rhino");
  EXPECT_TRUE(bound_for("rhino", "a114-desk"));
  now_ += 2;
  step();
  EXPECT_FALSE(bound_for("rhino2", "hallway-west"));
  exec_.on_pose("rhino", 4.0, 8.0);
  now_ += 2;
  step();
  EXPECT_TRUE(bound_for("rhino2", "hallway-west"));
  EXPECT_EQ(exec_.job("job-2")->reason, "");
  EXPECT_FALSE(bound_for("rhino3", "hallway-west"));
  EXPECT_EQ(exec_.job("job-3")->reason, "waiting for rhino2 to clear hallway-west");

  // rhino2 loads and leaves: rhino3's turn.
  reach("rhino2", 1.5, 8.0);
  complete("rhino2");
  exec_.on_pose("rhino2", 5.0, 8.0);
  now_ += 2;
  step();
  EXPECT_TRUE(bound_for("rhino3", "hallway-west"));
  EXPECT_EQ(exec_.job("job-3")->reason, "");
}

TEST_F(RoomClaimsTest, ARobotWaitingOnAHallwayPlaceDoesNotHoldItAgainstTheRobotItWaitsFor) {
  // rhino3 is in the meeting room and goes to the hallway place next; rhino loads on that place
  // and then needs the meeting room. Holding the place while it waits would be a cycle.
  exec_.add_robot("rhino", 3);
  exec_.add_robot("rhino3", 3);
  exec_.on_pose("rhino", 1.5, 8.0);
  exec_.on_pose("rhino3", 4.0, 10.7);
  scheduler_.prefer = {{"job-1", "rhino"}, {"job-2", "rhino3"}};
  exec_.add_job(delivery("job-1", "red", "hallway-west", "meeting-table"), now_);
  exec_.add_job(delivery("job-2", "blue", "meeting-table", "hallway-west"), now_);
  step();
  ASSERT_EQ(handovers_.count("rhino"), 1u);
  ASSERT_EQ(handovers_.count("rhino3"), 1u);
  complete("rhino");
  complete("rhino3");
  now_ += 1;
  step();
  // rhino, still on the place, waits for the room; rhino3 is sent out to the place all the same.
  EXPECT_FALSE(bound_for("rhino", "meeting-table"));
  EXPECT_EQ(exec_.job("job-1")->reason, "waiting for rhino3 to clear A-111");
  EXPECT_TRUE(bound_for("rhino3", "hallway-west"));
}

}  // namespace
}  // namespace autonomy::courier
