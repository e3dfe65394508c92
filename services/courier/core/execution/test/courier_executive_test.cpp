// The executive against a scripted scheduler (jobs in the order asked, 60 s per stop): the
// paper's two deliveries with door A-120 staying open, closing and reopening (Fig. 5) or closing
// for good (Fig. 7), cancels with the object aboard, refused handovers and restarts.
#include "services/courier/core/execution/courier_executive.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "services/courier/core/execution/test/executive_fixture.hpp"

namespace autonomy::courier {
namespace {

using test_support::paper_floor;
using test_support::delivery;
using test_support::ExecutiveTest;
using test_support::InOrderScheduler;

TEST_F(ExecutiveTest, TwoDeliveriesWithAllDoorsOpen) {
  exec_.add_job(delivery("j1", "letter-red", "red", "letter", "meeting-table", "michael-desk"), now_);
  exec_.add_job(delivery("j2", "book-green", "green", "book", "librarian-desk", "a114-desk"), now_);
  Orders o = step();
  ASSERT_EQ(o.goals.size(), 1u);
  EXPECT_EQ(goal_place(), "meeting-table");
  EXPECT_DOUBLE_EQ(o.goals[0].x, 4.0);
  ASSERT_EQ(o.schedules.size(), 1u);
  EXPECT_EQ(o.schedules[0].assumptions,
            (std::vector<std::string>{"A-111 open at 09:01:00", "A-120 open at 09:02:00", "A-110 open at 09:03:00",
                                      "A-114 open at 09:04:00"}));
  EXPECT_EQ(exec_.job("j1")->phase, JobPhase::to_pickup);
  arrive();
  EXPECT_EQ(last_handover_.object_id, "letter-red");
  EXPECT_TRUE(last_handover_.load);
  EXPECT_EQ(exec_.job("j1")->phase, JobPhase::loading);
  complete_handover();
  EXPECT_EQ(exec_.job("j1")->object_carrier, "rhino");
  EXPECT_EQ(goal_place(), "michael-desk");
  arrive();
  complete_handover();
  EXPECT_EQ(exec_.job("j1")->state, JobState::completed);
  EXPECT_EQ(exec_.job("j1")->object_place, "michael-desk");
  EXPECT_EQ(goal_place(), "librarian-desk");
  arrive();
  complete_handover();
  arrive();
  complete_handover();
  EXPECT_EQ(exec_.job("j2")->state, JobState::completed);
  EXPECT_LT(index_of("job j1 delivered"), index_of("book-green loaded"));
}

TEST_F(ExecutiveTest, Fig5ClosedDoorMakesTheJobOpportunisticAndAnOpenDoorInterruptsTheOtherDelivery) {
  exec_.add_job(delivery("j1", "letter-red", "red", "letter", "meeting-table", "michael-desk"), now_);
  exec_.add_job(delivery("j2", "book-green", "green", "book", "librarian-desk", "a114-desk"), now_);
  step();
  arrive();
  complete_handover();  // red letter aboard, heading for A-120
  ASSERT_EQ(goal_place(), "michael-desk");
  now_ += 5;
  exec_.on_door("rhino", "A-120", 0.05, now_);
  Orders o = step();  // the same tick: failure signalled, rescheduled, off to the librarian
  EXPECT_EQ(exec_.job("j1")->state, JobState::opportunistic);
  EXPECT_EQ(exec_.job("j1")->reason, "A-120 closed at 09:00:45");
  EXPECT_EQ(exec_.job("j1")->object_carrier, "rhino");  // still aboard
  ASSERT_EQ(o.goals.size(), 1u);
  EXPECT_EQ(goal_place(), "librarian-desk");
  arrive();
  complete_handover();  // green book aboard, heading for A-114
  ASSERT_EQ(goal_place(), "a114-desk");
  now_ += 5;
  exec_.on_door("rhino", "A-120", 1.4, now_);
  o = step();
  EXPECT_EQ(exec_.job("j1")->state, JobState::underway);
  EXPECT_EQ(goal_place(), "michael-desk");  // the green book's delivery is interrupted
  arrive();
  complete_handover();
  EXPECT_EQ(exec_.job("j1")->state, JobState::completed);
  EXPECT_EQ(goal_place(), "a114-desk");  // resumed
  arrive();
  complete_handover();
  EXPECT_EQ(exec_.job("j2")->state, JobState::completed);
  // The paper's steps in order.
  const size_t loaded_red = index_of("letter-red loaded at meeting-table");
  const size_t seen_closed = index_of("A-120 seen closed");
  const size_t failed_over = index_of("job j1 failed over to opportunistic");
  const size_t loaded_green = index_of("book-green loaded at librarian-desk");
  const size_t seen_open = index_of("A-120 seen open");
  const size_t taken_up = index_of("opportunity: job j1 taken up");
  const size_t red_done = index_of("job j1 delivered");
  const size_t green_done = index_of("job j2 delivered");
  EXPECT_LT(loaded_red, seen_closed);
  EXPECT_LT(seen_closed, failed_over);
  EXPECT_LT(failed_over, loaded_green);
  EXPECT_LT(loaded_green, seen_open);
  EXPECT_LT(seen_open, taken_up);
  EXPECT_LT(taken_up, red_done);
  EXPECT_LT(red_done, green_done);
}

// The door stays closed: the letter stays aboard while the green book is delivered and after
// (the job can still be done); it goes back only when the policy gives its deadline up.
TEST_F(ExecutiveTest, Fig7DoorStaysClosedAndTheLetterIsReturnedWhenItsDeadlineIsGivenUp) {
  Job red = delivery("j1", "letter-red", "red", "letter", "meeting-table", "michael-desk");
  red.deadline_s = now_ + 600;  // 09:10
  exec_.add_job(red, now_);
  exec_.add_job(delivery("j2", "book-green", "green", "book", "librarian-desk", "a114-desk"), now_);
  step();
  arrive();
  complete_handover();
  exec_.on_door("rhino", "A-120", 0.0, now_);
  step();
  arrive();
  complete_handover();
  arrive();
  now_ += 10;
  exec_.on_handover(last_handover_.request_id, HandoverOutcome::completed, "", "", now_);
  step();  // green book delivered; the letter waits aboard for A-120, the robot beside its door
  EXPECT_EQ(exec_.job("j2")->state, JobState::completed);
  EXPECT_EQ(exec_.job("j1")->state, JobState::opportunistic);
  EXPECT_EQ(exec_.job("j1")->object_carrier, "rhino");
  EXPECT_EQ(goal_place(), "lookout-A-120");
  arrive();
  // Seen closed now and then until 15 min after its deadline: then given up.
  const double give_up_at = *red.deadline_s + 900;
  while (now_ < give_up_at - 60) {
    now_ += 60;
    exec_.on_door("rhino", "A-120", 0.0, now_);
    step();
    ASSERT_EQ(exec_.job("j1")->state, JobState::opportunistic) << clock_text(now_);
  }
  EXPECT_DOUBLE_EQ(*exec_.idle_until_s(now_), give_up_at);
  now_ = give_up_at;
  step();
  EXPECT_EQ(exec_.job("j1")->phase, JobPhase::returning);
  EXPECT_EQ(goal_place(), "meeting-table");
  arrive();
  EXPECT_FALSE(last_handover_.load);
  EXPECT_EQ(last_handover_.place, "meeting-table");
  complete_handover();
  const Job& j1 = *exec_.job("j1");
  EXPECT_EQ(j1.state, JobState::failed);
  EXPECT_EQ(j1.reason,
            "gave up waiting for A-120: deadline 09:10:00 passed 15 min ago (A-120 closed at 09:24:30); "
            "letter-red returned to meeting-table");
  EXPECT_EQ(j1.object_place, "meeting-table");
}

TEST_F(ExecutiveTest, CancelWithTheObjectAboardReturnsItBeforeTheJobEnds) {
  exec_.add_job(delivery("j1", "letter-red", "red", "letter", "meeting-table", "michael-desk"), now_);
  step();
  arrive();
  complete_handover();
  EXPECT_EQ(exec_.cancel("j1", "sender changed their mind", now_), std::nullopt);
  Orders o = step();
  EXPECT_EQ(exec_.job("j1")->state, JobState::underway);
  EXPECT_EQ(exec_.job("j1")->phase, JobPhase::returning);
  EXPECT_EQ(goal_place(), "meeting-table");
  EXPECT_TRUE(o.reports.empty());
  arrive();
  complete_handover();
  EXPECT_EQ(exec_.job("j1")->state, JobState::cancelled);
  EXPECT_EQ(exec_.job("j1")->reason, "cancelled: sender changed their mind; letter-red returned to meeting-table");
  EXPECT_EQ(*exec_.cancel("j1", "", now_), "job j1 is already cancelled");
  EXPECT_EQ(*exec_.cancel("nope", "", now_), "no job 'nope'");
}

TEST_F(ExecutiveTest, CancelBeforePickupEndsAtOnceAndReportsIt) {
  exec_.add_job(delivery("j1", "letter-red", "red", "letter", "meeting-table", "michael-desk"), now_);
  step();
  EXPECT_EQ(exec_.cancel("j1", "", now_), std::nullopt);
  Orders o = step();
  EXPECT_EQ(exec_.job("j1")->state, JobState::cancelled);
  ASSERT_EQ(o.reports.size(), 1u);
  EXPECT_FALSE(o.reports[0].success);
  EXPECT_TRUE(o.goals.empty());
}

TEST_F(ExecutiveTest, RefusedHandoverWaitsAndRetriesAndAnUnansweredOneIsRepeatedWithTheSameId) {
  exec_.add_job(delivery("j1", "letter-red", "red", "letter", "meeting-table", "michael-desk"), now_);
  step();
  arrive();
  const std::string first_id = last_handover_.request_id;
  now_ += 6;  // no answer within the request timeout: the same request again
  Orders o = step();
  ASSERT_EQ(o.handovers.size(), 1u);
  EXPECT_EQ(o.handovers[0].request_id, first_id);
  exec_.on_handover(first_id, HandoverOutcome::rejected, "nobody_present", "nobody at meeting-table", now_);
  o = step();
  EXPECT_TRUE(o.handovers.empty());
  EXPECT_EQ(exec_.job("j1")->reason, "waiting: nobody at meeting-table");
  now_ += 21;
  o = step();
  ASSERT_EQ(o.handovers.size(), 1u);
  EXPECT_NE(o.handovers[0].request_id, first_id);  // a new attempt
}

TEST_F(ExecutiveTest, RevisedDestinationIsUsedAndUnknownPlacesAreRefused) {
  exec_.add_job(delivery("j1", "letter-red", "red", "letter", "meeting-table", "michael-desk"), now_);
  step();
  arrive();
  complete_handover();
  EXPECT_EQ(*exec_.revise("j1", std::string("A-999"), std::nullopt, now_), "no place 'A-999'");
  EXPECT_EQ(exec_.revise("j1", std::string("a114-desk"), std::optional<double>(10 * 3600.0), now_), std::nullopt);
  step();
  EXPECT_EQ(goal_place(), "a114-desk");
  EXPECT_EQ(*exec_.job("j1")->deadline_s, 36000.0);
}

TEST_F(ExecutiveTest, BlockedGoalNamingAClosedDoorIsTakenAsASighting) {
  exec_.add_job(delivery("j1", "letter-red", "red", "letter", "meeting-table", "michael-desk"), now_);
  step();
  arrive();
  complete_handover();
  exec_.on_goal("rhino", last_goal_.goal_id, GoalOutcome::blocked,
                "no route to goal (37.50, 2.60): door A-120 closed", now_);
  step();
  EXPECT_FALSE(exec_.doors().believed_open("A-120"));
  // Nothing else to do: the letter stays aboard, the job waits for the door and the robot waits
  // in sight of it.
  EXPECT_EQ(exec_.job("j1")->state, JobState::opportunistic);
  EXPECT_EQ(exec_.job("j1")->object_carrier, "rhino");
  EXPECT_EQ(goal_place(), "lookout-A-120");
}

// Without door monitoring (strategy (a) of the day-in-office experiment): a door seen closed
// changes nothing, and a goal blocked by it is sent again after a wait, for as long as it takes.
TEST(Executive, WithoutDoorMonitoringABlockedGoalWaitsAtTheDoorAndIsSentAgain) {
  const Floor floor = paper_floor();
  InOrderScheduler scheduler(floor);
  ExecutiveSettings settings;
  settings.monitor_doors = false;
  CourierExecutive exec(floor, scheduler, settings);
  exec.add_robot("rhino", 3);
  exec.on_pose("rhino", 1.5, 8.0);
  double now = 9 * 3600.0;
  exec.add_job(delivery("j1", "letter-red", "red", "letter", "meeting-table", "michael-desk"), now);
  NavGoalOrder goal = exec.step(now).goals.at(0);
  exec.on_goal("rhino", goal.goal_id, GoalOutcome::reached, "", now += 30);
  HandoverOrder load = exec.step(now).handovers.at(0);
  exec.on_handover(load.request_id, HandoverOutcome::accepted, "", "", now += 5);
  exec.on_handover(load.request_id, HandoverOutcome::completed, "", "", now += 5);
  goal = exec.step(now).goals.at(0);
  EXPECT_NE(goal.goal_id.find("michael-desk"), std::string::npos);
  exec.on_door("rhino", "A-120", 0.0, now);
  EXPECT_TRUE(exec.doors().believed_open("A-120"));  // not watched
  for (int attempt = 0; attempt < 5; ++attempt) {
    exec.on_goal("rhino", goal.goal_id, GoalOutcome::blocked, "no route to goal: door A-120 closed", now += 2);
    EXPECT_TRUE(exec.step(now).goals.empty());  // waits
    const Orders again = exec.step(now += 10);
    ASSERT_EQ(again.goals.size(), 1u) << "attempt " << attempt;
    goal = again.goals[0];
    EXPECT_NE(goal.goal_id.find("michael-desk"), std::string::npos);
    EXPECT_EQ(exec.job("j1")->state, JobState::underway);  // never opportunistic, never given up
  }
  exec.on_goal("rhino", goal.goal_id, GoalOutcome::reached, "", now += 20);
  const HandoverOrder unload = exec.step(now).handovers.at(0);
  EXPECT_FALSE(unload.load);
  exec.on_handover(unload.request_id, HandoverOutcome::accepted, "", "", now += 5);
  exec.on_handover(unload.request_id, HandoverOutcome::completed, "", "", now += 5);
  exec.step(now);
  EXPECT_EQ(exec.job("j1")->state, JobState::completed);
}

TEST(Executive, NothingIsPlannedBeforeARobotsPoseIsKnown) {
  const Floor floor = paper_floor();
  InOrderScheduler scheduler(floor);
  CourierExecutive exec(floor, scheduler);
  exec.add_robot("rhino", 3);
  exec.add_job(delivery("j1", "letter-red", "red", "letter", "meeting-table", "michael-desk"), 0.0);
  Orders o = exec.step(1.0);
  EXPECT_TRUE(o.goals.empty());
  EXPECT_EQ(scheduler.calls, 0);
  EXPECT_EQ(exec.job("j1")->state, JobState::queued);
  exec.on_pose("rhino", 1.5, 8.0);
  o = exec.step(2.0);
  ASSERT_EQ(o.goals.size(), 1u);
  EXPECT_EQ(scheduler.calls, 1);
}

TEST_F(ExecutiveTest, RestoredJobAboardGoesOnToItsDestination) {
  Job j = delivery("j1", "letter-red", "red", "letter", "meeting-table", "michael-desk");
  j.state = JobState::underway;
  j.phase = JobPhase::to_destination;
  j.object_place.clear();
  j.object_carrier = "rhino";
  exec_.restore_job(j);
  step();
  EXPECT_EQ(goal_place(), "michael-desk");
}

TEST_F(ExecutiveTest, RestoredPendingHandoverIsSentAgainWithItsId) {
  Job j = delivery("j1", "letter-red", "red", "letter", "meeting-table", "michael-desk");
  exec_.restore_job(j);
  exec_.restore_pending_handover({"rhino", "rhino/j1/load/1", true, "meeting-table", "letter-red", "j1"});
  Orders o = step();
  ASSERT_EQ(o.handovers.size(), 1u);
  EXPECT_EQ(o.handovers[0].request_id, "rhino/j1/load/1");
  exec_.on_handover("rhino/j1/load/1", HandoverOutcome::completed, "", "", now_);
  step();
  EXPECT_EQ(exec_.job("j1")->object_carrier, "rhino");
  EXPECT_EQ(goal_place(), "michael-desk");
}



TEST_F(ExecutiveTest, CancelWhileLoadingThenTheLoadFailsEndsTheJobOnce) {
  exec_.add_job(delivery("j1", "letter-red", "red", "letter", "meeting-table", "michael-desk"), now_);
  step();
  arrive();  // load request sent
  ASSERT_EQ(exec_.job("j1")->phase, JobPhase::loading);
  EXPECT_EQ(exec_.cancel("j1", "", now_), std::nullopt);
  step();
  exec_.on_handover(last_handover_.request_id, HandoverOutcome::failed, "robot_moved_away", "", now_);
  int reports = 0;
  for (int i = 0; i < 50; ++i) { now_ += 10; reports += step().reports.size(); }
  EXPECT_TRUE(exec_.job("j1")->finished()) << to_string(exec_.job("j1")->state) << " / " << exec_.job("j1")->reason;
  EXPECT_EQ(reports, 1);
}

TEST_F(ExecutiveTest, RevisingTheDestinationToWhereTheObjectLiesIsRefused) {
  exec_.add_job(delivery("j1", "letter-red", "red", "letter", "meeting-table", "michael-desk"), now_);
  step();
  EXPECT_EQ(exec_.revise("j1", std::string("meeting-table"), std::nullopt, now_),
            std::optional<std::string>("job j1's object already lies at meeting-table"));
  EXPECT_EQ(exec_.job("j1")->destination, "michael-desk");
}

TEST_F(ExecutiveTest, ADeclinedOpportunityIsTakenUpWhenNothingElseWaits) {
  exec_.add_job(delivery("j1", "letter-red", "red", "letter", "meeting-table", "michael-desk"), now_);
  Job g = delivery("j2", "book-green", "green", "book", "librarian-desk", "a114-desk");
  g.deadline_s = now_ + 200;  // tight: the detour would make it late
  exec_.add_job(g, now_);
  step();
  arrive();
  complete_handover();  // red aboard
  now_ += 5;
  exec_.on_door("rhino", "A-120", 0.05, now_);
  step();
  arrive();
  complete_handover();  // green aboard
  now_ += 5;
  exec_.on_door("rhino", "A-120", 1.4, now_);
  step();
  EXPECT_EQ(exec_.job("j1")->state, JobState::opportunistic);  // declined
  arrive();
  complete_handover();  // green delivered
  EXPECT_EQ(exec_.job("j2")->state, JobState::completed);
  // A-120 is believed open now: the letter should be delivered, not returned.
  EXPECT_NE(exec_.job("j1")->phase, JobPhase::returning) << exec_.job("j1")->reason;
  EXPECT_EQ(goal_place(), "michael-desk");
}

TEST_F(ExecutiveTest, ARefusedReturnIsTriedAFewTimesThenReported) {
  exec_.add_job(delivery("j1", "letter-red", "red", "letter", "meeting-table", "michael-desk"), now_);
  step();
  arrive();
  complete_handover();
  exec_.cancel("j1", "", now_);
  step();
  arrive();  // return unload sent
  int requests = 0;
  for (int i = 0; i < 20; ++i) {
    exec_.on_handover(last_handover_.request_id, HandoverOutcome::rejected, "object_not_carried_by_robot", "", now_);
    now_ += 0.1;
    requests += step().handovers.size();
  }
  EXPECT_LT(requests, 3) << "unload requests in 2 s";
  EXPECT_TRUE(exec_.job("j1")->finished()) << exec_.job("j1")->reason;
}

class FailingOnce : public ScheduleSource {
 public:
  explicit FailingOnce(ScheduleSource& inner) : inner_(inner) {}
  Plan plan(const PlanRequest& r) override {
    if (calls_++ == 0) {
      Plan p;
      p.failed = true;
      p.failure = "the budget ran out";
      return p;
    }
    return inner_.plan(r);
  }
  ScheduleSource& inner_;
  int calls_ = 0;
};

TEST(Executive, AFailedScheduleIsTriedAgainWithoutBlamingTheJobs) {
  const Floor floor = paper_floor();
  InOrderScheduler inner(floor);
  FailingOnce scheduler(inner);
  CourierExecutive exec(floor, scheduler);
  exec.add_robot("rhino", 3);
  exec.on_pose("rhino", 1.5, 8.0);
  exec.add_job(delivery("j1", "letter-red", "red", "letter", "meeting-table", "michael-desk"), 0.0);
  int goals = 0;
  for (int i = 1; i < 50; ++i) goals += exec.step(i * 10.0).goals.size();
  EXPECT_GT(goals, 0) << to_string(exec.job("j1")->state) << ": " << exec.job("j1")->reason;
}

TEST_F(ExecutiveTest, ABlockedGoalNamingTwoDoorsIsTakenAsTwoSightings) {
  exec_.add_job(delivery("j1", "letter-red", "red", "letter", "meeting-table", "michael-desk"), now_);
  step();
  arrive();
  complete_handover();
  exec_.on_goal("rhino", last_goal_.goal_id, GoalOutcome::blocked,
                "no route to goal (37.50, 2.60): doors A-111, A-120 closed", now_);
  step();
  EXPECT_FALSE(exec_.doors().believed_open("A-120"));
}

TEST_F(ExecutiveTest, AnAcceptedHandoverThatNeverCompletesIsAskedAgain) {
  exec_.add_job(delivery("j1", "letter-red", "red", "letter", "meeting-table", "michael-desk"), now_);
  step();
  arrive();
  exec_.on_handover(last_handover_.request_id, HandoverOutcome::accepted, "", "", now_);
  int resent = 0;
  for (int i = 0; i < 100; ++i) { now_ += 10; resent += step().handovers.size(); }
  EXPECT_GT(resent, 0) << "1000 s after an accepted load, nothing asked";
}

TEST_F(ExecutiveTest, ARefusedGoalIsRetriedAFewTimesThenTheJobFails) {
  exec_.add_job(delivery("j1", "letter-red", "red", "letter", "meeting-table", "michael-desk"), now_);
  step();
  int goals = 0;
  for (int i = 0; i < 40; ++i) {
    exec_.on_goal("rhino", last_goal_.goal_id, GoalOutcome::rejected, "goal outside the map", now_);
    now_ += 0.25;
    goals += step().goals.size();
  }
  EXPECT_EQ(goals, 2);  // the first goal came before the loop: three in all, one second apart
  EXPECT_EQ(exec_.job("j1")->state, JobState::failed);
  EXPECT_EQ(exec_.job("j1")->reason, "goal to meeting-table refused 3 times: goal outside the map");
}


TEST_F(ExecutiveTest, ALoadCompletingAfterItsJobFailedOverIsReportedAndReturned) {
  exec_.add_job(delivery("j1", "letter-red", "red", "letter", "meeting-table", "michael-desk"), now_);
  step();
  arrive();  // load under way
  exec_.on_door("rhino", "A-120", 0.0, now_);  // the destination closes meanwhile
  EXPECT_EQ(exec_.cancel("j1", "no longer needed", now_), std::nullopt);
  step();
  complete_handover();  // the load completes after all
  const Job& j1 = *exec_.job("j1");
  EXPECT_EQ(j1.object_carrier, "rhino");
  EXPECT_EQ(j1.phase, JobPhase::returning);
  EXPECT_FALSE(j1.reason.empty());
  arrive();
  complete_handover();
  EXPECT_EQ(exec_.job("j1")->state, JobState::cancelled);
  EXPECT_EQ(exec_.job("j1")->object_place, "meeting-table");
}

TEST_F(ExecutiveTest, CancelDuringTheFinalUnloadIsRefused) {
  exec_.add_job(delivery("j1", "letter-red", "red", "letter", "meeting-table", "michael-desk"), now_);
  step();
  arrive();
  complete_handover();
  arrive();  // unload at michael-desk under way
  EXPECT_EQ(exec_.cancel("j1", "", now_),
            std::optional<std::string>("job j1 is being handed over at michael-desk now: too late to cancel"));
}

TEST(Executive, AHandoverAcceptedTwiceIsTimedFromTheFirstAcceptance) {
  Floor floor = paper_floor();
  floor.places["meeting-table"].person = "mary";
  InOrderScheduler scheduler(floor);
  CourierExecutive exec(floor, scheduler);
  exec.add_robot("rhino", 3);
  exec.on_pose("rhino", 1.5, 8.0);
  double now = 9 * 3600.0;
  exec.add_job(delivery("j1", "letter-red", "red", "letter", "meeting-table", "michael-desk"), now);
  const Orders first = exec.step(now);
  ASSERT_EQ(first.goals.size(), 1u);
  exec.on_goal("rhino", first.goals[0].goal_id, GoalOutcome::reached, "", now += 30);
  const Orders at_table = exec.step(now);
  ASSERT_EQ(at_table.handovers.size(), 1u);
  const std::string request = at_table.handovers[0].request_id;
  exec.on_handover(request, HandoverOutcome::accepted, "", "", now += 5);
  exec.on_handover(request, HandoverOutcome::accepted, "", "", now += 60);  // the request asked again
  exec.on_handover(request, HandoverOutcome::completed, "", "", now += 15);
  ASSERT_EQ(exec.experience().handovers().count("mary"), 1u);
  EXPECT_DOUBLE_EQ(exec.experience().handovers().at("mary").mean, 75.0);
  EXPECT_EQ(exec.experience().handovers().at("mary").n, 1);
}

TEST_F(ExecutiveTest, SightingsOfDoorsNotOnTheFloorAreIgnored) {
  exec_.on_door("rhino", "no-such-door", 0.0, now_);
  EXPECT_TRUE(exec_.doors().doors().empty());
}

TEST_F(ExecutiveTest, IdsCarryTheRunTag) {
  exec_.add_job(delivery("j1", "letter-red", "red", "letter", "meeting-table", "michael-desk"), now_);
  step();
  EXPECT_EQ(last_goal_.goal_id, "rhino/meeting-table/r1.1");
  arrive();
  EXPECT_EQ(last_handover_.request_id, "rhino/j1/load/r1.1");
}

TEST_F(ExecutiveTest, NobodyPresentWaitsUntilThePersonIsBack) {
  librarian_is_out_until_ten();
  EXPECT_EQ(exec_.job("j1")->reason, "waiting: nobody at librarian-desk at 09:01 (somebody is back at 10:00)");
  int requests = 0;
  for (now_ = 9 * 3600.0 + 100; now_ < 10 * 3600.0; now_ += 60) requests += step().handovers.size();
  EXPECT_EQ(requests, 0);  // no failed attempts piling up meanwhile
  now_ = 10 * 3600.0 + 1;
  EXPECT_EQ(step().handovers.size(), 1u);
  EXPECT_FALSE(exec_.job("j1")->finished());
}

TEST_F(ExecutiveTest, WhileAPersonIsOutTheRobotDoesOtherWorkFirst) {
  librarian_is_out_until_ten();
  // A new job the schedule puts first: the robot goes for it instead of waiting for 10:00.
  scheduler_.newest_first = true;
  now_ += 60;
  exec_.add_job(delivery("j2", "letter-red", "red", "letter", "meeting-table", "michael-desk"), now_);
  step();
  EXPECT_EQ(goal_place(), "meeting-table");
  EXPECT_EQ(exec_.job("j2")->state, JobState::underway);
}

TEST_F(ExecutiveTest, ADoorSeenClosedLongAgoIsAssumedOpenAgainAndItsJobTried) {
  // The pickup's room is seen closed on the way: the job waits for an opportunity.
  meeting_room_seen_closed();
  ASSERT_EQ(exec_.job("j1")->state, JobState::opportunistic);
  const double seen = now_;
  now_ = seen + 299;
  step();
  EXPECT_FALSE(exec_.doors().believed_open("A-111"));
  // Five minutes without seeing it: open, as a door never seen; the job is tried again.
  now_ = seen + 301;
  step();
  EXPECT_TRUE(exec_.doors().believed_open("A-111"));
  EXPECT_TRUE(happened("A-111 assumed open again: not seen for 300 s (09:05:01)")) << events_.back();
  EXPECT_NE(exec_.job("j1")->state, JobState::opportunistic);
  EXPECT_EQ(goal_place(), "meeting-table");
  // Assumed, not seen: the door's learned habit still counts.
  EXPECT_EQ(scheduler_.last_request.doors_seen_open.count("A-111"), 0u);
  EXPECT_EQ(scheduler_.last_request.closed_doors.count("A-111"), 0u);
}

// A goal lost on its way (its behavior's reader not matched again yet) is sent again every 11 s
// (10 s without an answer, then the 1 s retry), not counted as a refusal: the job is not given
// up, and once the behavior answers it goes on.
TEST_F(ExecutiveTest, AGoalTheBehaviorNeverAnswersIsSentAgainUntilItIsAnswered) {
  exec_.add_job(delivery("j1", "letter-red", "red", "letter", "meeting-table", "michael-desk"), now_);
  step();
  int goals = 0;
  for (int i = 0; i < 60; ++i) {
    now_ += 1.0;
    goals += step().goals.size();
  }
  EXPECT_EQ(goals, 5);  // at 11, 22, 33, 44 and 55 s
  EXPECT_EQ(exec_.job("j1")->state, JobState::underway);
  EXPECT_TRUE(happened("goal " + last_goal_.goal_id.substr(0, last_goal_.goal_id.rfind('.') + 1) + "5 unanswered: "
                       "no answer from the behavior of rhino within 10 s; sent again"))
      << events_.back();
  arrive();
  EXPECT_EQ(last_handover_.place, "meeting-table");
  EXPECT_TRUE(last_handover_.load);
}

// Quiet ticks (idl/clock.idl): how long the world may run without the courier.
TEST_F(ExecutiveTest, IdleWithoutJobsUntilSomethingHappensAndAtWorkWithOne) {
  step();
  ASSERT_TRUE(exec_.idle_until_s(now_).has_value());
  EXPECT_TRUE(std::isinf(*exec_.idle_until_s(now_)));
  exec_.add_job(delivery("j1", "letter-red", "red", "letter", "meeting-table", "michael-desk"), now_);
  EXPECT_FALSE(exec_.idle_until_s(now_)) << "a job to plan";
  step();
  EXPECT_FALSE(exec_.idle_until_s(now_)) << "driving to the pickup";
  arrive();
  EXPECT_FALSE(exec_.idle_until_s(now_)) << "handing over";
  complete_handover();
  arrive();
  complete_handover();
  ASSERT_EQ(exec_.job("j1")->state, JobState::completed);
  EXPECT_TRUE(exec_.idle_until_s(now_).has_value()) << "delivered, nothing else to do";
}

TEST_F(ExecutiveTest, IdleWhileWaitingForAPersonUntilThePersonIsBack) {
  librarian_is_out_until_ten();
  const auto idle = exec_.idle_until_s(now_);
  ASSERT_TRUE(idle.has_value());
  EXPECT_GT(*idle, now_);
  EXPECT_LE(*idle, 10 * 3600.0 + 1);
  // Nothing happens before then (the hold), and at that time the request goes out again.
  now_ = *idle - 1;
  EXPECT_TRUE(step().handovers.empty());
  now_ = *idle + 1;
  EXPECT_EQ(step().handovers.size(), 1u);
}

TEST_F(ExecutiveTest, IdleBehindAClosedDoorUntilItsSightingGoesStale) {
  meeting_room_seen_closed();
  ASSERT_EQ(exec_.job("j1")->state, JobState::opportunistic);
  EXPECT_FALSE(exec_.idle_until_s(now_)) << "on its way to watch the door";
  now_ += 30;
  exec_.on_goal("rhino", last_goal_.goal_id, GoalOutcome::reached, "", now_);
  exec_.on_door("rhino", "A-111", 0.0, now_);
  step();
  const auto idle = exec_.idle_until_s(now_);
  ASSERT_TRUE(idle.has_value());
  EXPECT_DOUBLE_EQ(*idle, now_ + 300);  // then A-111 is assumed open and the job tried again
  // Seen closed again meanwhile: later.
  exec_.on_door("rhino", "A-111", 0.0, now_ + 100);
  EXPECT_DOUBLE_EQ(*exec_.idle_until_s(now_ + 100), now_ + 400);
}

}  // namespace
}  // namespace autonomy::courier
