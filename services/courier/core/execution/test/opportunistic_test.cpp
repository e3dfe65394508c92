// Jobs behind closed doors (opportunistic.cpp): for any room, pickup or delivery, the job waits
// for its door with its object aboard while it can still be done, the robot watches the door when
// it has nothing else to do, and the object goes back only when the job can no longer be done:
// its deadline given up, its person gone for the day, or its place aboard needed by another job.
#include "services/courier/core/execution/courier_executive.hpp"

#include <gtest/gtest.h>

#include "services/courier/core/execution/test/executive_fixture.hpp"

namespace autonomy::courier {
namespace {

using test_support::delivery;
using test_support::ExecutiveTest;

class OpportunisticTest : public ExecutiveTest {
 protected:
  // The robot loads `object` at `from` and heads for `to`; `door` is then seen closed.
  void loaded_then_door_closes(const std::string& id, const std::string& object, const std::string& from,
                               const std::string& to, const std::string& door, std::optional<double> deadline = {}) {
    Job j = delivery(id, object, "red", "letter", from, to);
    j.deadline_s = deadline;
    exec_.add_job(j, now_);
    step();
    arrive();
    complete_handover();
    ASSERT_EQ(exec_.job(id)->object_carrier, "rhino");
    now_ += 5;
    exec_.on_door("rhino", door, 0.0, now_);
    step();
  }
  // The robot reaches its lookout and sees `door` there, at `angle`.
  void at_lookout_sees(const std::string& door, double angle) {
    arrive();
    now_ += 1;
    exec_.on_door("rhino", door, angle, now_);
    step();
  }
};

// Each delivery room of the floor in turn: the object stays aboard, the robot waits beside the
// door, and the delivery is made when the door is seen open.
TEST_F(OpportunisticTest, ADeliveryBehindAClosedDoorWaitsAboardAndIsMadeWhenTheDoorOpens) {
  const std::vector<std::pair<std::string, std::string>> rooms = {
      {"michael-desk", "A-120"}, {"a114-desk", "A-114"}, {"librarian-desk", "A-110"}};
  int n = 0;
  for (const auto& [desk, door] : rooms) {
    SCOPED_TRACE(door);
    const std::string id = "j" + std::to_string(++n);
    const std::string object = "letter-" + std::to_string(n);
    loaded_then_door_closes(id, object, "meeting-table", desk, door);
    EXPECT_EQ(exec_.job(id)->state, JobState::opportunistic);
    EXPECT_EQ(exec_.job(id)->reason.rfind(door + " closed at ", 0), 0u) << exec_.job(id)->reason;
    EXPECT_EQ(exec_.job(id)->object_carrier, "rhino");
    EXPECT_EQ(goal_place(), "lookout-" + door);
    at_lookout_sees(door, 0.0);  // still closed: waits there, no new goal
    const std::string goal_before = last_goal_.goal_id;
    now_ += 120;
    step();
    EXPECT_EQ(last_goal_.goal_id, goal_before);
    EXPECT_EQ(exec_.job(id)->state, JobState::opportunistic);
    exec_.on_door("rhino", door, 1.5, now_);
    step();
    EXPECT_EQ(exec_.job(id)->state, JobState::underway);
    EXPECT_EQ(goal_place(), desk);
    arrive();
    complete_handover();
    EXPECT_EQ(exec_.job(id)->state, JobState::completed);
    EXPECT_EQ(exec_.job(id)->object_place, desk);
    EXPECT_LT(index_of(door + " seen closed"), index_of("job " + id + " failed over to opportunistic"));
    EXPECT_LT(index_of("job " + id + " failed over to opportunistic"), index_of(door + " seen open"));
    EXPECT_LT(index_of(door + " seen open"), index_of("opportunity: job " + id + " taken up"));
    EXPECT_LT(index_of("opportunity: job " + id + " taken up"), index_of("job " + id + " delivered"));
  }
}

TEST_F(OpportunisticTest, APickupBehindAClosedDoorIsOpportunisticAndTakenUpWhenTheDoorIsSeenOpen) {
  meeting_room_seen_closed();
  EXPECT_EQ(exec_.job("j1")->state, JobState::opportunistic);
  EXPECT_EQ(exec_.job("j1")->object_place, "meeting-table");
  EXPECT_EQ(exec_.job("j1")->reason.rfind("A-111 closed at ", 0), 0u) << exec_.job("j1")->reason;
  at_lookout_sees("A-111", 0.0);
  now_ += 60;
  exec_.on_door("rhino", "A-111", 1.5, now_);
  step();
  EXPECT_EQ(exec_.job("j1")->state, JobState::underway);
  EXPECT_EQ(goal_place(), "meeting-table");
}

// Given up (deadline), the object is on its way back when the door is seen open: delivered after
// all, since the person can still get it.
TEST_F(OpportunisticTest, WithNothingElseToDoTheRobotWatchesTheDoorOfItsPickup) {
  meeting_room_seen_closed();
  ASSERT_EQ(exec_.job("j1")->state, JobState::opportunistic);
  EXPECT_EQ(goal_place(), "lookout-A-111");
}

TEST_F(OpportunisticTest, AReturnForAGivenUpDoorTurnsBackIntoTheDeliveryWhenTheDoorIsSeenOpen) {
  loaded_then_door_closes("j1", "letter-red", "meeting-table", "michael-desk", "A-120", now_ + 120);
  at_lookout_sees("A-120", 0.0);
  now_ = *exec_.job("j1")->deadline_s + 900;
  exec_.on_door("rhino", "A-120", 0.0, now_ - 1);
  step();
  ASSERT_EQ(exec_.job("j1")->phase, JobPhase::returning) << exec_.job("j1")->reason;
  EXPECT_EQ(goal_place(), "meeting-table");
  now_ += 3;
  exec_.on_door("rhino", "A-120", 1.5, now_);
  step();
  EXPECT_TRUE(exec_.job("j1")->return_to.empty());
  EXPECT_EQ(exec_.job("j1")->state, JobState::underway) << exec_.job("j1")->reason;
  EXPECT_EQ(goal_place(), "michael-desk");
  arrive();
  complete_handover();
  EXPECT_EQ(exec_.job("j1")->state, JobState::completed);
}

// A cancelled job's return is not turned back by a door.
TEST_F(OpportunisticTest, ACancelledJobsReturnIgnoresItsDoorOpening) {
  loaded_then_door_closes("j1", "letter-red", "meeting-table", "michael-desk", "A-120");
  ASSERT_FALSE(exec_.cancel("j1", "by test", now_));
  step();
  ASSERT_EQ(exec_.job("j1")->phase, JobPhase::returning);
  exec_.on_door("rhino", "A-120", 1.5, now_ + 1);
  now_ += 1;
  step();
  EXPECT_EQ(exec_.job("j1")->phase, JobPhase::returning);
  EXPECT_EQ(goal_place(), "meeting-table");
}

TEST_F(OpportunisticTest, AJobWhosePersonIsGoneForTheDayIsGivenUpAndItsObjectReturned) {
  loaded_then_door_closes("j1", "letter-red", "meeting-table", "michael-desk", "A-120");
  ASSERT_EQ(exec_.job("j1")->state, JobState::opportunistic);
  at_lookout_sees("A-120", 0.0);
  scheduler_.gone.insert("michael-desk");
  // The door is seen open: the opportunity check finds Michael gone for the day.
  now_ += 10;
  exec_.on_door("rhino", "A-120", 1.5, now_);
  step();
  EXPECT_EQ(exec_.job("j1")->phase, JobPhase::returning);
  EXPECT_NE(exec_.job("j1")->reason.find("cannot be done today: nobody at michael-desk again today"), std::string::npos)
      << exec_.job("j1")->reason;
  EXPECT_EQ(goal_place(), "meeting-table");
}

TEST_F(OpportunisticTest, AWaitingJobWhosePersonIsGoneIsGivenUpAtTheNextSchedule) {
  scheduler_.gone.insert("a114-desk");
  exec_.add_job(delivery("j1", "book-green", "green", "book", "librarian-desk", "a114-desk"), now_);
  step();
  EXPECT_EQ(exec_.job("j1")->state, JobState::failed);
  EXPECT_EQ(exec_.job("j1")->reason, "cannot be done today: nobody at a114-desk again today");
}

// Left out of the schedule with no door to blame (it clashes with a job accepted before it): not
// opportunistic, it stays queued, says why, and is planned when the schedule has room for it.
TEST_F(OpportunisticTest, AJobTheScheduleLeavesOutWithoutADoorStaysQueuedAndIsPlannedLater) {
  scheduler_.clashes["j2"] = "cannot be done together with job 'j1'";
  exec_.add_job(delivery("j1", "letter-red", "red", "letter", "meeting-table", "michael-desk"), now_);
  exec_.add_job(delivery("j2", "book-green", "green", "book", "librarian-desk", "a114-desk"), now_);
  step();
  EXPECT_EQ(exec_.job("j2")->state, JobState::queued);
  EXPECT_EQ(exec_.job("j2")->reason, "not in the schedule: cannot be done together with job 'j1'");
  scheduler_.clashes.clear();
  arrive();
  complete_handover();  // the letter aboard: rescheduled, now with j2
  EXPECT_TRUE(exec_.job("j2")->reason.empty()) << exec_.job("j2")->reason;
  EXPECT_EQ(exec_.job("j2")->robot, "rhino");
  EXPECT_TRUE(exec_.job("j2")->estimated_completion_s.has_value());
}

// Capacity 1: the letter waiting for A-120 takes the only place aboard; a new job needs it.
TEST(Opportunistic, AnObjectWaitingAboardGoesBackWhenItsPlaceIsNeededForAnotherJob) {
  const Floor floor = test_support::paper_floor();
  test_support::InOrderScheduler scheduler(floor);
  CourierExecutive exec(floor, scheduler);
  exec.add_robot("rhino", 1);
  exec.on_pose("rhino", 1.5, 8.0);
  double now = 9 * 3600.0;
  std::string goal, request;
  const auto run = [&] {
    const Orders o = exec.step(now);
    for (const auto& g : o.goals) goal = g.goal_id;
    for (const auto& h : o.handovers) request = h.request_id;
    return o;
  };
  exec.add_job(delivery("j1", "letter-red", "red", "letter", "meeting-table", "michael-desk"), now);
  run();
  now += 30;
  exec.on_goal("rhino", goal, GoalOutcome::reached, "", now);
  run();
  exec.on_handover(request, HandoverOutcome::completed, "", "", now);
  run();
  exec.on_door("rhino", "A-120", 0.0, now);
  run();
  ASSERT_EQ(exec.job("j1")->state, JobState::opportunistic);
  EXPECT_FALSE(scheduler.last_request.jobs.empty()) << "the waiting letter takes its place aboard";
  exec.add_job(delivery("j2", "book-green", "green", "book", "librarian-desk", "a114-desk"), now);
  run();
  const Job& j1 = *exec.job("j1");
  EXPECT_EQ(j1.phase, JobPhase::returning);
  EXPECT_NE(j1.reason.find("its place aboard rhino is needed for job j2 (A-120 closed at"), std::string::npos)
      << j1.reason;
  EXPECT_EQ(exec.job("j2")->state, JobState::queued);
}

TEST_F(OpportunisticTest, WaitingAtTheLookoutTheCourierIsIdleUntilTheDeadlineIsGivenUpOrTheSightingIsStale) {
  loaded_then_door_closes("j1", "letter-red", "meeting-table", "michael-desk", "A-120", now_ + 60);
  EXPECT_FALSE(exec_.idle_until_s(now_)) << "driving to the lookout";
  at_lookout_sees("A-120", 0.0);
  const auto idle = exec_.idle_until_s(now_);
  ASSERT_TRUE(idle);
  EXPECT_DOUBLE_EQ(*idle, std::min(*exec_.job("j1")->deadline_s + 900, now_ + 300));
}

TEST_F(OpportunisticTest, OneObjectIsInOneOpenJobAndWhereItLiesFollowsItsJobs) {
  exec_.add_job(delivery("job-1", "book-green", "green", "book", "librarian-desk", "a114-desk"), now_);
  ASSERT_NE(exec_.open_job_of_object("book-green"), nullptr);
  EXPECT_EQ(exec_.open_job_of_object("book-green")->id, "job-1");
  EXPECT_EQ(exec_.open_job_of_object("letter-red"), nullptr);
  EXPECT_EQ(exec_.object_whereabouts().at("book-green").place, "librarian-desk");
  step();
  arrive();
  complete_handover();
  EXPECT_EQ(exec_.object_whereabouts().at("book-green").carrier, "rhino");
  arrive();
  complete_handover();
  EXPECT_EQ(exec_.job("job-1")->state, JobState::completed);
  EXPECT_EQ(exec_.open_job_of_object("book-green"), nullptr);
  EXPECT_EQ(exec_.object_whereabouts().at("book-green").place, "a114-desk");
  // The next job moves it on from there; its belief is the latest.
  now_ += 60;
  exec_.add_job(delivery("job-2", "book-green", "green", "book", "a114-desk", "librarian-desk"), now_);
  EXPECT_EQ(exec_.object_whereabouts().at("book-green").job, "job-2");
}

}  // namespace
}  // namespace autonomy::courier

namespace autonomy::courier {
namespace {

// An object aboard whose job waits as an opportunity (its door seen open again, the opportunity
// declined) still takes its place aboard in every schedule: the scheduler is told to keep it
// aboard, not to deliver it, so it never plans more pickups than the robot has room for.
TEST_F(OpportunisticTest, AnObjectWaitingAboardForAnOpportunityKeepsItsPlaceAboardInTheSchedule) {
  loaded_then_door_closes("j1", "letter-1", "meeting-table", "michael-desk", "A-120");
  ASSERT_EQ(exec_.job("j1")->state, JobState::opportunistic);
  Job j2 = delivery("j2", "book-2", "green", "book", "librarian-desk", "a114-desk");
  j2.deadline_s = now_ + 150;  // on time alone (done at +120), late behind j1's delivery (+180)
  exec_.add_job(j2, now_);
  step();
  // A-120 seen open: taking j1 up first would make j2 late (the in-order scheduler puts it
  // first), so the opportunity is declined and j1 stays aboard, waiting.
  now_ += 1;
  exec_.on_door("rhino", "A-120", 1.5, now_);
  step();
  ASSERT_EQ(exec_.job("j1")->state, JobState::opportunistic);
  ASSERT_TRUE(exec_.doors().believed_open("A-120"));
  now_ += 1;
  exec_.add_job(delivery("j3", "letter-3", "blue", "letter", "meeting-table", "a114-desk"), now_);
  step();
  const auto& jobs = scheduler_.last_request.jobs;
  const auto j1 = std::find_if(jobs.begin(), jobs.end(), [](const PlanJob& j) { return j.id == "j1"; });
  ASSERT_NE(j1, jobs.end());
  EXPECT_TRUE(j1->keep_aboard);
  EXPECT_EQ(j1->aboard, "rhino");
  for (const PlanJob& j : jobs)
    if (j.id != "j1") EXPECT_FALSE(j.keep_aboard) << j.id;
}

}  // namespace
}  // namespace autonomy::courier
