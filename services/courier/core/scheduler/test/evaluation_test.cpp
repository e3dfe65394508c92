// evaluate_order and find_unschedulable on hand-computed cases (small_office.hpp: hall -10 s-
// A-111 -20 s- A-120, hall -25 s- A-120, 5 s handovers, now 10:00 = 36000 s).
#include "services/courier/core/scheduler/schedule_evaluation.hpp"
#include "services/courier/core/scheduler/test/small_office.hpp"

#include <gtest/gtest.h>

namespace autonomy::courier::scheduling {
namespace {

using test::D;
using test::job;
using test::P;
using test::small_office;

TEST(EvaluateOrder, OneJobTimesAndObjective) {
  SchedulingProblem p = small_office();
  p.jobs.push_back(job("j1", 1, 2));
  p.jobs[0].deadline_s = 36030.0;
  const JobSchedule s = evaluate_order(p, {{P(0), D(0)}});
  ASSERT_TRUE(s.ok()) << s.reason;
  ASSERT_EQ(s.routes.size(), 1u);
  ASSERT_EQ(s.routes[0].stops.size(), 2u);
  const auto& pick = s.routes[0].stops[0];
  const auto& drop = s.routes[0].stops[1];
  EXPECT_DOUBLE_EQ(pick.arrival_s, 36010.0);
  EXPECT_DOUBLE_EQ(pick.finish_s, 36015.0);
  EXPECT_DOUBLE_EQ(drop.arrival_s, 36035.0);
  EXPECT_DOUBLE_EQ(drop.finish_s, 36040.0);
  EXPECT_EQ(s.objective.late_jobs, 1);
  EXPECT_DOUBLE_EQ(s.objective.lateness_s, 10.0);
  EXPECT_DOUBLE_EQ(s.objective.completion_s, 40.0);
  EXPECT_DOUBLE_EQ(s.objective.travel_s, 30.0);
  EXPECT_EQ(s.objective.interruptions, 2);
  ASSERT_EQ(s.outcomes.size(), 1u);
  EXPECT_TRUE(s.outcomes[0].late);
  EXPECT_DOUBLE_EQ(s.outcomes[0].completion_s, 36040.0);
  // Assumptions: A-111 open at 10:00:10, A-120 open at 10:00:35.
  ASSERT_EQ(s.assumptions.size(), 2u);
  EXPECT_EQ(s.assumptions[0].room, "A-111");
  EXPECT_DOUBLE_EQ(s.assumptions[0].arrival_s, 36010.0);
  EXPECT_EQ(s.assumptions[1].room, "A-120");
  EXPECT_DOUBLE_EQ(s.assumptions[1].arrival_s, 36035.0);
}

TEST(EvaluateOrder, ConsecutiveStopsAtOneLocationAreOneVisit) {
  SchedulingProblem p = small_office();
  p.jobs.push_back(job("j1", 1, 2, "red"));
  p.jobs.push_back(job("j2", 1, 2, "green"));
  const JobSchedule s = evaluate_order(p, {{P(0), P(1), D(0), D(1)}});
  ASSERT_TRUE(s.ok()) << s.reason;
  const auto& st = s.routes[0].stops;
  EXPECT_FALSE(st[0].same_visit_as_previous);
  EXPECT_TRUE(st[1].same_visit_as_previous);
  EXPECT_DOUBLE_EQ(st[1].arrival_s, 36015.0);  // the previous handover's end, no travel
  EXPECT_DOUBLE_EQ(st[1].finish_s, 36020.0);
  EXPECT_DOUBLE_EQ(st[2].finish_s, 36045.0);
  EXPECT_DOUBLE_EQ(st[3].finish_s, 36050.0);
  EXPECT_EQ(s.objective.interruptions, 2);
  EXPECT_DOUBLE_EQ(s.objective.completion_s, 45.0 + 50.0);
  EXPECT_EQ(s.assumptions.size(), 2u);  // one entry per room
}

TEST(EvaluateOrder, CapacityAndLookAlikeAreRefusedWithTheStop) {
  SchedulingProblem p = small_office(/*capacity=*/1);
  p.jobs.push_back(job("j1", 1, 2, "red"));
  p.jobs.push_back(job("j2", 1, 2, "green"));
  JobSchedule s = evaluate_order(p, {{P(0), P(1), D(0), D(1)}});
  EXPECT_EQ(s.status, ScheduleStatus::kInfeasible);
  EXPECT_NE(s.reason.find("stop 1 (pickup of job 'j2')"), std::string::npos) << s.reason;
  EXPECT_NE(s.reason.find("capacity 1"), std::string::npos) << s.reason;

  p.couriers[0].capacity = 2;
  p.jobs[1].object.colour = "red";  // two red letters
  s = evaluate_order(p, {{P(0), P(1), D(0), D(1)}});
  EXPECT_EQ(s.status, ScheduleStatus::kInfeasible);
  EXPECT_NE(s.reason.find("look-alike"), std::string::npos) << s.reason;
  EXPECT_TRUE(evaluate_order(p, {{P(0), D(0), P(1), D(1)}}).ok());
}

TEST(EvaluateOrder, PrecedenceMissingAndDuplicateStops) {
  SchedulingProblem p = small_office();
  p.jobs.push_back(job("j1", 1, 2));
  EXPECT_NE(evaluate_order(p, {{D(0), P(0)}}).reason.find("not aboard"), std::string::npos);
  EXPECT_NE(evaluate_order(p, {{P(0)}}).reason.find("still aboard"), std::string::npos);
  EXPECT_NE(evaluate_order(p, {{}}).reason.find("not delivered"), std::string::npos);
  EXPECT_NE(evaluate_order(p, {{P(0), D(0), D(0)}}).reason.find("twice"), std::string::npos);
  EXPECT_EQ(evaluate_order(p, {}).status, ScheduleStatus::kInfeasible);
}

TEST(EvaluateOrder, WaitsForPresenceAndRefusesOutsideIt) {
  SchedulingProblem p = small_office();
  p.people.push_back({"Michael", 30.0, {{36100.0, 36200.0}}});
  p.jobs.push_back(job("j1", 1, 2));
  p.jobs[0].delivery.person = 0;
  JobSchedule s = evaluate_order(p, {{P(0), D(0)}});
  ASSERT_TRUE(s.ok()) << s.reason;
  EXPECT_DOUBLE_EQ(s.routes[0].stops[1].arrival_s, 36035.0);
  EXPECT_DOUBLE_EQ(s.routes[0].stops[1].handover_start_s, 36100.0);
  EXPECT_DOUBLE_EQ(s.routes[0].stops[1].finish_s, 36130.0);
  // Another job first: the window closes before a 30 s handover fits, nobody to hand over to.
  p.people[0].presence = {{36000.0, 36070.0}};
  p.jobs.push_back(job("j2", 0, 1, "green"));
  s = evaluate_order(p, {{P(1), D(1), P(0), D(0)}});
  EXPECT_EQ(s.status, ScheduleStatus::kInfeasible);
  EXPECT_NE(s.reason.find("no presence window fits at Michael at A-120 desk"), std::string::npos)
      << s.reason;
  EXPECT_TRUE(evaluate_order(p, {{P(0), D(0), P(1), D(1)}}).ok());
  // Michael left for the day: the job is unschedulable.
  p.people[0].presence = {{30000.0, 35000.0}};
  const auto left = find_unschedulable(p);
  ASSERT_EQ(left.size(), 1u);
  EXPECT_EQ(left[0].reason, UnschedulableReason::kNobodyPresent);
}

TEST(EvaluateOrder, ForcedPrefixMustComeFirst) {
  SchedulingProblem p = small_office();
  p.jobs.push_back(job("j1", 1, 2));
  p.jobs.push_back(job("j2", 0, 1, "green"));
  p.jobs[0].status = JobStatus::kAboard;
  p.jobs[0].aboard_courier = 0;
  p.couriers[0].forced_prefix = {D(0)};
  EXPECT_TRUE(evaluate_order(p, {{D(0), P(1), D(1)}}).ok());
  const JobSchedule s = evaluate_order(p, {{P(1), D(1), D(0)}});
  EXPECT_EQ(s.status, ScheduleStatus::kInfeasible);
  EXPECT_NE(s.reason.find("forced prefix"), std::string::npos) << s.reason;
  // An aboard job has no pickup.
  EXPECT_NE(evaluate_order(p, {{D(0), P(0), P(1), D(1)}}).reason.find("stop 1"), std::string::npos);
}

TEST(FindUnschedulable, ClosedDoorCutsOffTheDeliveryButTheObjectStaysAboard) {
  SchedulingProblem p = small_office(/*capacity=*/2);
  p.jobs.push_back(job("red", 1, 2, "red"));
  p.jobs.push_back(job("red2", 0, 1, "red"));
  p.jobs[0].status = JobStatus::kAboard;
  p.jobs[0].aboard_courier = 0;
  p.travel.cut_off(2);  // A-120 closed
  const auto left = find_unschedulable(p);
  ASSERT_EQ(left.size(), 2u);
  EXPECT_EQ(left[0].job, 0);
  EXPECT_EQ(left[0].reason, UnschedulableReason::kUnreachable);
  EXPECT_NE(left[0].detail.find("A-120 desk"), std::string::npos);
  // The red letter stays aboard, so the second red letter cannot be loaded: left out too.
  EXPECT_EQ(left[1].job, 1);
  EXPECT_EQ(left[1].reason, UnschedulableReason::kClash);
  EXPECT_NE(left[1].detail.find("stay aboard"), std::string::npos) << left[1].detail;
  EXPECT_TRUE(evaluate_order(p, {{}}).ok());
  p.jobs[1].object.colour = "green";
  const JobSchedule ok = evaluate_order(p, {{P(1), D(1)}});
  ASSERT_TRUE(ok.ok()) << ok.reason;
  ASSERT_EQ(ok.unschedulable.size(), 1u);
}

TEST(ProblemError, NamesTheField) {
  SchedulingProblem p = small_office();
  p.jobs.push_back(job("j1", 1, 7));
  EXPECT_NE(problem_error(p).find("jobs[0].delivery.location: 7 is not a location"),
            std::string::npos)
      << problem_error(p);
  p.jobs[0].delivery.location = 2;
  p.couriers[0].capacity = 0;
  EXPECT_NE(problem_error(p).find("couriers[0].capacity"), std::string::npos);
  p.couriers[0].capacity = 1;
  p.travel.set(1, 1, 3.0);
  EXPECT_NE(problem_error(p).find("diagonal"), std::string::npos);
  p.travel.set(1, 1, 0.0);
  EXPECT_EQ(problem_error(p), "");
}

}  // namespace
}  // namespace autonomy::courier::scheduling
