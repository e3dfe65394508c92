// The executive with several robots: a robot joining while jobs run gets work at the next
// reschedule; a robot that leaves has its queued jobs reallocated and the object it carried
// reported stranded with its last known place, until it comes back. And the roster that turns
// heartbeats into joins and leaves.
#include "services/courier/core/execution/courier_executive.hpp"
#include "services/courier/core/execution/fleet_roster.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "services/courier/core/execution/test/fleet_fixture.hpp"
#include "services/courier/core/execution/test/paper_floor.hpp"

namespace autonomy::courier {
namespace {

using test_support::paper_floor;

using test_support::delivery;
using test_support::FleetScheduler;
using test_support::FleetTest;

TEST_F(FleetTest, ARobotJoiningWhileJobsRunGetsWorkAtTheNextReschedule) {
  exec_.add_robot("rhino", 3);
  exec_.on_pose("rhino", 1.5, 8.0);
  exec_.add_job(delivery("job-1", "red", "meeting-table", "michael-desk"), now_);
  exec_.add_job(delivery("job-2", "green", "librarian-desk", "a114-desk"), now_);
  step();
  EXPECT_EQ(exec_.route("rhino").size(), 4u);  // alone: both jobs
  EXPECT_EQ(goals_.count("rhino2"), 0u);

  now_ += 5;
  exec_.add_robot("rhino2", 2);
  step();
  // Not located yet: not planned for.
  EXPECT_EQ(scheduler_.requests.back().robots.size(), 1u);
  exec_.on_pose("rhino2", 10.0, 8.0);
  scheduler_.prefer["job-2"] = "rhino2";
  step();
  ASSERT_EQ(scheduler_.requests.back().robots.size(), 2u);
  EXPECT_EQ(scheduler_.requests.back().robots[1].capacity, 2);
  ASSERT_EQ(goals_.count("rhino2"), 1u);
  EXPECT_NE(goals_["rhino2"].goal_id.find("librarian-desk"), std::string::npos)
      << goals_["rhino2"].goal_id;
  EXPECT_EQ(exec_.job("job-2")->robot, "rhino2");
  EXPECT_EQ(exec_.job("job-2")->allocation, "assigned to rhino2: test");
  ASSERT_EQ(texts(ExecutionEvent::Kind::robot_joined).size(), 2u);
  EXPECT_EQ(texts(ExecutionEvent::Kind::robot_joined)[1], "rhino2 joined the fleet (capacity 2)");
}

TEST_F(FleetTest, AGoalBlockedByTrafficIsTriedAgainLaterAndGivenUpOnlyAfterSixBlocks) {
  exec_.add_robot("rhino", 3);
  exec_.add_robot("rhino2", 3);
  exec_.on_pose("rhino", 12.0, 8.0);
  exec_.on_pose("rhino2", 30.0, 8.0);
  scheduler_.prefer = {{"job-1", "rhino"}};
  exec_.add_job(delivery("job-1", "red", "meeting-table", "michael-desk"), now_);
  step();
  for (int block = 1; block <= 5; ++block) {
    const std::string goal = goals_.at("rhino").goal_id;
    ASSERT_NE(goal.find("meeting-table"), std::string::npos) << goal;
    now_ += 12;
    exec_.on_goal("rhino", goal, GoalOutcome::blocked, "no progress for 10.0 s, 3.1 m from goal", now_);
    step();
    // It waits 5 s times the blocks so far, then the same place again; the job is not given up.
    now_ += 5.0 * block - 1.0;
    step();
    EXPECT_EQ(goals_.at("rhino").goal_id, goal) << "block " << block;
    now_ += 1.0;
    step();
    EXPECT_NE(goals_.at("rhino").goal_id, goal) << "block " << block;
    EXPECT_EQ(exec_.job("job-1")->state, JobState::underway) << "block " << block;
  }
  now_ += 12;
  exec_.on_goal("rhino", goals_.at("rhino").goal_id, GoalOutcome::blocked,
                "no route to goal (4.00, 10.70): robot rhino2 (parked) at (1.6, 9.0) in doorway A-111", now_);
  step();
  EXPECT_EQ(exec_.job("job-1")->state, JobState::failed);
  EXPECT_EQ(exec_.job("job-1")->reason.rfind("cannot reach meeting-table: no route to goal", 0), 0u)
      << exec_.job("job-1")->reason;
}

TEST_F(FleetTest, ARobotWhoseJobWentToAnotherGoesHomeOutOfTheWay) {
  exec_.add_robot("rhino", 3);
  exec_.add_robot("rhino2", 3);
  exec_.on_pose("rhino", 1.5, 8.0);
  exec_.on_pose("rhino2", 30.0, 8.0);
  scheduler_.prefer = {{"job-1", "rhino"}, {"job-2", "rhino2"}};
  exec_.add_job(delivery("job-1", "red", "meeting-table", "michael-desk"), now_);
  exec_.add_job(delivery("job-2", "green", "librarian-desk", "a114-desk"), now_);
  step();
  ASSERT_EQ(goals_.count("rhino2"), 1u);
  const std::string goal = goals_["rhino2"].goal_id;
  exec_.on_goal("rhino2", goal, GoalOutcome::active, "", now_);
  // A reschedule gives the green book to rhino: rhino2's drive west is no longer needed.
  scheduler_.prefer["job-2"] = "rhino";
  now_ += 10;
  exec_.add_job(delivery("job-3", "blue", "meeting-table", "a114-desk"), now_);
  scheduler_.prefer["job-3"] = "rhino";
  exec_.on_pose("rhino2", 20.0, 7.5);  // half way, in the hallway
  const Orders o = step();
  EXPECT_EQ(exec_.job("job-2")->robot, "rhino");
  // Not stopped where it is (in the others' way) but sent back to where it joined.
  ASSERT_EQ(o.goals.size(), 1u);
  EXPECT_EQ(o.goals[0].robot, "rhino2");
  EXPECT_NE(o.goals[0].goal_id, goal);
  EXPECT_NE(o.goals[0].goal_id.find("rhino2/home/"), std::string::npos);
  EXPECT_DOUBLE_EQ(o.goals[0].x, 30.0);
  EXPECT_DOUBLE_EQ(o.goals[0].y, 8.0);
  EXPECT_TRUE(o.cancels.empty());
  // Home: nothing more for it; the old goal's status changes nothing.
  exec_.on_goal("rhino2", goal, GoalOutcome::preempted, "preempted", now_);
  exec_.on_pose("rhino2", 30.0, 8.0);
  exec_.on_goal("rhino2", o.goals[0].goal_id, GoalOutcome::reached, "", now_);
  const Orders after = step();
  for (const auto& g : after.goals) EXPECT_NE(g.robot, "rhino2");
  EXPECT_TRUE(after.cancels.empty());
}

TEST_F(FleetTest, AloneARobotWhoseJobEndedStopsInsteadOfDrivingOn) {
  exec_.add_robot("rhino", 3);
  exec_.on_pose("rhino", 1.5, 8.0);
  exec_.add_job(delivery("job-1", "red", "meeting-table", "michael-desk"), now_);
  step();
  const std::string goal = goals_.at("rhino").goal_id;
  exec_.on_goal("rhino", goal, GoalOutcome::active, "", now_);
  EXPECT_FALSE(exec_.cancel("job-1", "not needed", now_));
  const Orders o = step();
  ASSERT_EQ(o.cancels.size(), 1u);
  EXPECT_EQ(o.cancels[0].goal_id, goal);
  EXPECT_EQ(o.cancels[0].reason, "nothing left for rhino at meeting-table");
}

TEST_F(FleetTest, ALostRobotsQueuedJobsGoToTheOtherAndItsObjectIsStrandedWhereItWasLastSeen) {
  exec_.add_robot("rhino", 3);
  exec_.add_robot("rhino2", 3);
  exec_.on_pose("rhino", 1.5, 8.0);
  exec_.on_pose("rhino2", 10.0, 8.0);
  scheduler_.prefer = {{"job-1", "rhino2"}, {"job-2", "rhino2"}, {"job-3", "rhino"}};
  exec_.add_job(delivery("job-1", "red", "meeting-table", "michael-desk"), now_);
  exec_.add_job(delivery("job-2", "green", "librarian-desk", "a114-desk"), now_);
  exec_.add_job(delivery("job-3", "blue", "librarian-desk", "meeting-table"), now_);
  step();
  reach("rhino2", 4.0, 10.7);  // at the meeting table
  ASSERT_EQ(handovers_.count("rhino2"), 1u);
  complete("rhino2");  // the red letter is aboard rhino2
  ASSERT_EQ(exec_.job("job-1")->object_carrier, "rhino2");
  exec_.on_pose("rhino2", 19.2, 3.1);  // on its way, near the A-114 desk

  now_ += 7;
  exec_.remove_robot("rhino2", "heartbeat lost", now_);
  step();
  const Job* stranded = exec_.job("job-1");
  EXPECT_EQ(stranded->state, JobState::stranded);
  EXPECT_EQ(stranded->robot, "rhino2");
  EXPECT_EQ(stranded->reason,
            "red stranded aboard rhino2, last seen at (19.2, 3.1) near a114-desk in A-114 at "
            "09:00:47: heartbeat lost");
  ASSERT_EQ(texts(ExecutionEvent::Kind::stranded).size(), 1u);
  EXPECT_EQ(texts(ExecutionEvent::Kind::stranded)[0], "job job-1: " + stranded->reason);
  ASSERT_EQ(texts(ExecutionEvent::Kind::robot_left).size(), 1u);
  // The stranded job is no one's to plan; job-2 is now rhino's.
  for (const PlanJob& j : scheduler_.requests.back().jobs) EXPECT_NE(j.id, "job-1");
  ASSERT_EQ(scheduler_.requests.back().robots.size(), 1u);
  EXPECT_EQ(exec_.job("job-2")->robot, "rhino");
  EXPECT_NE(exec_.job("job-2")->allocation.find(
                "(reallocated: rhino2 left (heartbeat lost) at 09:00:47)"),
            std::string::npos)
      << exec_.job("job-2")->allocation;
  ASSERT_EQ(texts(ExecutionEvent::Kind::reallocated).size(), 1u);
  EXPECT_EQ(texts(ExecutionEvent::Kind::reallocated)[0],
            "job job-2 reallocated: rhino2 left (heartbeat lost)");
  EXPECT_EQ(exec_.robot_ids(), std::vector<std::string>{"rhino"});

  // rhino2 comes back (its behavior restarted): the letter's job goes on, on rhino2.
  now_ += 60;
  exec_.add_robot("rhino2", 3);
  exec_.on_pose("rhino2", 19.2, 3.1);
  EXPECT_EQ(exec_.job("job-1")->state, JobState::queued);
  step();
  ASSERT_EQ(texts(ExecutionEvent::Kind::resumed).size(), 1u);
  EXPECT_EQ(texts(ExecutionEvent::Kind::robot_joined).back(),
            "rhino2 is back in the fleet (capacity 3)");
  ASSERT_EQ(goals_.count("rhino2"), 1u);
  EXPECT_NE(goals_["rhino2"].goal_id.find("michael-desk"), std::string::npos)
      << goals_["rhino2"].goal_id;
  EXPECT_EQ(exec_.job("job-1")->state, JobState::underway);
}

TEST_F(FleetTest, AHandoverUnansweredWhenTheRobotWasLostIsAskedAgainWithItsIdWhenItIsBack) {
  exec_.add_robot("rhino", 3);
  exec_.on_pose("rhino", 1.5, 8.0);
  exec_.add_job(delivery("job-1", "red", "meeting-table", "michael-desk"), now_);
  step();
  reach("rhino", 4.0, 10.7);
  ASSERT_EQ(handovers_.count("rhino"), 1u);
  const std::string request = handovers_["rhino"].request_id;
  exec_.remove_robot("rhino", "stopped", now_);
  step();
  EXPECT_EQ(exec_.job("job-1")->state, JobState::stranded);
  EXPECT_NE(exec_.job("job-1")->reason.find(
                "red may be aboard rhino (its load at meeting-table was not answered)"),
            std::string::npos)
      << exec_.job("job-1")->reason;
  handovers_.clear();
  exec_.add_robot("rhino", 3);
  exec_.on_pose("rhino", 4.0, 10.7);
  step();
  ASSERT_EQ(handovers_.count("rhino"), 1u);
  EXPECT_EQ(handovers_["rhino"].request_id, request);
}

TEST_F(FleetTest, CancellingAStrandedJobEndsItSayingWhereTheObjectIs) {
  exec_.add_robot("rhino", 3);
  exec_.on_pose("rhino", 1.5, 8.0);
  exec_.add_job(delivery("job-1", "red", "meeting-table", "michael-desk"), now_);
  step();
  reach("rhino", 4.0, 10.7);
  complete("rhino");
  exec_.remove_robot("rhino", "heartbeat lost", now_);
  step();
  EXPECT_FALSE(exec_.cancel("job-1", "", now_));
  const Job* job = exec_.job("job-1");
  EXPECT_EQ(job->state, JobState::cancelled);
  EXPECT_NE(job->reason.find("red stranded aboard rhino"), std::string::npos) << job->reason;
}

// The floor with parking spots at the hallway's dead ends (Scenario.parking).
class FleetParkingTest : public FleetTest {
 protected:
  static Floor floor_with_parking() {
    Floor f = paper_floor();
    f.parking = {{"hall-west-end", 0.55, 8.0}, {"hall-east-end", 39.4, 7.6}, {"hall-east", 38.2, 8.4}};
    return f;
  }
  FleetParkingTest() : FleetTest(floor_with_parking()) {}
  // The park goal sent to `robot` in `o`, if any.
  static const NavGoalOrder* park_goal(const Orders& o, const std::string& robot) {
    for (const auto& g : o.goals)
      if (g.robot == robot) return &g;
    return nullptr;
  }
};

TEST_F(FleetParkingTest, IdleRobotsOfAFleetParkEachAtTheNearestSpotNoOtherHolds) {
  exec_.add_robot("rhino", 3);
  exec_.add_robot("rhino2", 3);
  exec_.add_robot("rhino3", 3);
  exec_.add_robot("rhino4", 3);
  exec_.on_pose("rhino", 5.0, 8.0);
  exec_.on_pose("rhino2", 35.0, 8.0);
  exec_.on_pose("rhino3", 37.0, 8.0);
  exec_.on_pose("rhino4", 20.0, 8.0);
  Orders o = step();
  if (o.goals.empty()) o = step();  // the first step may only plan
  // rhino2 took hall-east (the nearer of the two east spots); rhino3, nearer to hall-east than
  // rhino2 but later, gets the other; rhino4 finds none free and stays home (where it joined).
  const std::map<std::string, std::pair<double, double>> expected = {
      {"rhino", {0.55, 8.0}}, {"rhino2", {38.2, 8.4}}, {"rhino3", {39.4, 7.6}}};
  ASSERT_EQ(o.goals.size(), 3u);
  for (const auto& [robot, xy] : expected) {
    const NavGoalOrder* g = park_goal(o, robot);
    ASSERT_NE(g, nullptr) << robot;
    EXPECT_DOUBLE_EQ(g->x, xy.first) << robot;
    EXPECT_DOUBLE_EQ(g->y, xy.second) << robot;
    EXPECT_NE(g->goal_id.find(robot + "/park/"), std::string::npos) << g->goal_id;
  }
  EXPECT_EQ(park_goal(o, "rhino4"), nullptr);
  const auto heading = texts(ExecutionEvent::Kind::heading);
  EXPECT_NE(std::find_if(heading.begin(), heading.end(),
                         [](const std::string& t) { return t.rfind("rhino parks at hall-west-end (0.6, 8.0), out of the way", 0) == 0; }),
            heading.end());

  // Parked: nothing more for them, however often the executive steps.
  for (const auto& [robot, xy] : expected) {
    exec_.on_pose(robot, xy.first, xy.second);
    exec_.on_goal(robot, park_goal(o, robot)->goal_id, GoalOutcome::reached, "", now_);
  }
  now_ += 5;
  EXPECT_TRUE(step().goals.empty());

  // rhino4, moved away from home, drives back there: no spot is free.
  exec_.on_pose("rhino4", 25.0, 8.0);
  now_ += 5;
  const Orders home = step();
  ASSERT_EQ(home.goals.size(), 1u);
  EXPECT_NE(home.goals[0].goal_id.find("rhino4/home/"), std::string::npos);
  EXPECT_DOUBLE_EQ(home.goals[0].x, 20.0);
}

TEST_F(FleetParkingTest, ARobotSentToWorkFreesItsSpotOnceItHasLeftIt) {
  exec_.add_robot("rhino", 3);
  exec_.add_robot("rhino2", 3);
  exec_.on_pose("rhino", 0.55, 8.0);   // parked west
  exec_.on_pose("rhino2", 10.0, 8.0);
  Orders o = step();
  if (o.goals.empty()) o = step();
  // rhino stands on the west spot and holds it; rhino2 parks east, though west is nearer.
  const NavGoalOrder* g2 = park_goal(o, "rhino2");
  ASSERT_NE(g2, nullptr);
  EXPECT_DOUBLE_EQ(g2->x, 38.2);
  EXPECT_EQ(park_goal(o, "rhino"), nullptr);
  exec_.on_pose("rhino2", 38.2, 8.4);
  exec_.on_goal("rhino2", g2->goal_id, GoalOutcome::reached, "", now_);

  // rhino gets a job and leaves its spot; rhino2, idle, is already parked and stays (its own
  // spot, not the nearest free one, is where it waits).
  scheduler_.prefer = {{"job-1", "rhino"}};
  exec_.add_job(delivery("job-1", "red", "meeting-table", "michael-desk"), now_);
  now_ += 5;
  o = step();
  ASSERT_NE(park_goal(o, "rhino"), nullptr);
  EXPECT_NE(park_goal(o, "rhino")->goal_id.find("meeting-table"), std::string::npos);
  EXPECT_EQ(park_goal(o, "rhino2"), nullptr);

  // A third robot joining beside the west end takes it once rhino has driven off (1 m or more).
  exec_.add_robot("rhino3", 3);
  exec_.on_pose("rhino3", 2.5, 8.0);
  exec_.on_pose("rhino", 1.2, 8.0);  // still on the spot
  now_ += 5;
  o = step();
  if (park_goal(o, "rhino3") == nullptr) o = step();
  ASSERT_NE(park_goal(o, "rhino3"), nullptr);
  EXPECT_DOUBLE_EQ(park_goal(o, "rhino3")->x, 39.4);  // the west spot is still stood on
  exec_.on_pose("rhino3", 30.0, 8.0);
  exec_.on_pose("rhino", 4.0, 10.0);
  now_ += 5;
  step();
  // rhino3 holds hall-east-end from then on: a spot is not swapped for a nearer one on the way.
  EXPECT_TRUE(step().goals.empty());
}

TEST_F(FleetParkingTest, ARobotWaitingForAClosedDoorWithTheObjectAboardParksOutOfTheHallway) {
  exec_.add_robot("rhino", 3);
  exec_.add_robot("rhino2", 3);
  exec_.on_pose("rhino", 4.0, 10.7);  // at the meeting table
  exec_.on_pose("rhino2", 39.4, 7.6);  // parked at the east end
  scheduler_.prefer = {{"job-1", "rhino"}};
  exec_.add_job(delivery("job-1", "red", "meeting-table", "michael-desk"), now_);
  step();
  ASSERT_EQ(handovers_.count("rhino"), 1u);
  complete("rhino");
  ASSERT_NE(goals_.at("rhino").goal_id.find("michael-desk"), std::string::npos);
  exec_.on_pose("rhino", 20.0, 8.0);
  exec_.on_door("rhino", "A-120", 0.0, now_);  // Michael's door, seen closed on the way
  now_ += 1;
  step();
  const Job* job = exec_.job("job-1");
  EXPECT_EQ(job->state, JobState::opportunistic);
  EXPECT_EQ(job->object_carrier, "rhino");
  // Alone it would wait beside A-120 (its lookout); in a fleet it parks, out of the others' way.
  const std::string goal = goals_.at("rhino").goal_id;
  EXPECT_NE(goal.find("rhino/park/"), std::string::npos) << goal;
  EXPECT_DOUBLE_EQ(goals_.at("rhino").x, 38.2);
}

TEST(FleetRoster, CouriersJoinWhenReadyAndLeaveWhenStoppedGoneOrSilent) {
  FleetRoster roster({"rhino"}, 3.0);
  EXPECT_TRUE(roster.on_heartbeat("rhino", BeatKind::starting, {}, 0.0).empty());
  auto c = roster.on_heartbeat("rhino", BeatKind::ready, {}, 0.5);  // declared in the scenario
  ASSERT_EQ(c.size(), 1u);
  EXPECT_TRUE(c[0].joined);
  EXPECT_TRUE(roster.on_heartbeat("rhino", BeatKind::ready, {}, 1.0).empty());
  // Not declared and no capability: a scout, not ours.
  EXPECT_TRUE(roster.on_heartbeat("scout", BeatKind::ready, {}, 1.0).empty());
  EXPECT_FALSE(roster.member("scout"));
  c = roster.on_heartbeat("rhino2", BeatKind::ready, {"courier"}, 1.0);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].robot, "rhino2");

  c = roster.on_heartbeat("rhino2", BeatKind::no_writers, {}, 2.0);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_FALSE(c[0].joined);
  EXPECT_EQ(c[0].why, "heartbeat lost");
  EXPECT_FALSE(roster.member("rhino2"));

  EXPECT_TRUE(roster.expire(3.9).empty());  // rhino heard at 1.0
  c = roster.expire(4.5);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].why, "heartbeat lost: none for 4 s");
  c = roster.on_heartbeat("rhino", BeatKind::ready, {}, 5.0);  // back
  ASSERT_EQ(c.size(), 1u);
  EXPECT_TRUE(c[0].joined);
  c = roster.on_heartbeat("rhino", BeatKind::stopping, {}, 6.0);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].why, "stopped");
}

}  // namespace
}  // namespace autonomy::courier
