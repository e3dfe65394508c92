// The exact engine against the textbook dynamic program (reference_dp.hpp) on seeded random
// offices, in the classes that exercise each of its cuts: loose offices (few deadlines, everybody
// always present: many orders tie closely, the delay dominance compares labels at different
// times), presence windows that close during the route (the delay dominance must refuse), tight
// deadlines (late jobs and lateness in the bound) and objects aboard with look-alikes (the aboard
// set rebuilt from the masks). Sizes stay where the DP takes milliseconds.
#include "services/courier/core/scheduler/random_office.hpp"
#include "services/courier/core/scheduler/reference_dp.hpp"
#include "services/courier/core/scheduler/schedule_evaluation.hpp"
#include "services/courier/core/scheduler/scheduler_engine.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace autonomy::courier::scheduling {
namespace {

// Solves `spec` for seeds first..first+count-1 with both and expects the same optimum, proved,
// and a schedule whose order evaluates to what the engine says it costs.
void expect_exact_equals_dp(OfficeSpec spec, std::uint64_t first, int count) {
  auto exact = make_scheduler_engine("exact");
  for (int i = 0; i < count; ++i) {
    spec.seed = first + static_cast<std::uint64_t>(i);
    const std::string what = std::to_string(spec.jobs) + " jobs, seed " + std::to_string(spec.seed);
    const SchedulingProblem p = random_office(spec);
    const ReferenceDpResult dp = reference_dp(p);
    const JobSchedule s = exact->solve(p, {});
    ASSERT_EQ(s.ok(), dp.feasible) << what << ": " << s.reason;
    if (!dp.feasible) continue;
    EXPECT_TRUE(s.proved_optimal) << what;
    EXPECT_EQ(compare(s.objective, dp.best), 0)
        << what << ": exact " << s.objective.late_jobs << " late, " << s.objective.lateness_s
        << " s late, " << s.objective.completion_s << " s completion, " << s.objective.travel_s
        << " s travel; DP " << dp.best.late_jobs << ", " << dp.best.lateness_s << ", "
        << dp.best.completion_s << ", " << dp.best.travel_s;
    const JobSchedule again = evaluate_order(p, s.order());
    ASSERT_TRUE(again.ok()) << what << ": " << again.reason;
    EXPECT_EQ(compare(again.objective, s.objective), 0) << what;
  }
}

// Six jobs: the DP takes milliseconds even under the sanitizers.
OfficeSpec six_jobs(int deadline_percent, bool presence) {
  OfficeSpec spec;
  spec.jobs = 6;
  spec.deadline_percent = deadline_percent;
  spec.presence = presence;
  return spec;
}

TEST(ExactEngineBounds, EqualsTheDpOnLooseOffices) {
  expect_exact_equals_dp(six_jobs(10, false), 1, 10);
  OfficeSpec crowded = six_jobs(0, false);
  crowded.rooms = 8;  // more stops per place: the shared travel charge splits legs
  expect_exact_equals_dp(crowded, 101, 10);
}

TEST(ExactEngineBounds, EqualsTheDpWhenPresenceEndsDuringTheRoute) {
  // 11:50: the morning presence ends ten minutes in, so a later label can miss a window an
  // earlier one makes; a delay must not be priced as a shift then.
  OfficeSpec spec = six_jobs(30, true);
  spec.now_s = 11.0 * 3600.0 + 50.0 * 60.0;
  expect_exact_equals_dp(spec, 201, 10);
}

TEST(ExactEngineBounds, EqualsTheDpWithTightDeadlines) {
  expect_exact_equals_dp(six_jobs(100, true), 301, 10);
  // No window stops the delay dominance: the deadlines alone price it.
  expect_exact_equals_dp(six_jobs(100, false), 311, 10);
}

TEST(ExactEngineBounds, EqualsTheDpWhenSomePeopleComeOrLeaveSoon) {
  // Most people always present, some arriving or leaving within 1-15 minutes. An earlier label
  // may cut a later, cheaper one of its state by its head start only while no stop left can
  // wait for a window (the head start is then kept by every job left); where a stop left waits
  // for someone to arrive, both labels wait and the head start is lost.
  // Seeds 101-180 hold three offices (122, 157, 180) where the head start priced without that
  // condition cuts the optimum.
  OfficeSpec spec = six_jobs(30, false);
  spec.jobs = 7;
  spec.late_arrival_percent = 40;
  spec.late_max_s = 900;
  expect_exact_equals_dp(spec, 101, 80);
  spec.late_arrival_percent = 0;
  spec.tight_presence_percent = 40;
  expect_exact_equals_dp(spec, 513, 12);
  // Loose and larger: many labels of one state at different times, priced by their head start.
  OfficeSpec loose = six_jobs(20, false);
  loose.jobs = 8;
  expect_exact_equals_dp(loose, 521, 6);
}

TEST(ExactEngineBounds, EqualsTheDpWithObjectsAboardAndLookAlikes) {
  OfficeSpec spec = six_jobs(20, false);
  spec.capacity = 2;
  spec.kinds = 1;
  spec.colours = 2;
  spec.aboard_percent = 30;
  expect_exact_equals_dp(spec, 401, 12);
}

// The optimum with several couriers by brute force: every assignment of the waiting jobs to the
// couriers, each courier's share (with the objects already aboard it) solved by the reference DP,
// the costs summed. Couriers with no share cost nothing beyond their start.
bool best_by_assignment(const SchedulingProblem& p, Objective& best) {
  std::vector<int> waiting;
  for (std::size_t j = 0; j < p.jobs.size(); ++j)
    if (p.jobs[j].status == JobStatus::kWaitingForPickup) waiting.push_back(static_cast<int>(j));
  const std::size_t couriers = p.couriers.size();
  std::size_t assignments = 1;
  for (std::size_t k = 0; k < waiting.size(); ++k) assignments *= couriers;
  bool found = false;
  for (std::size_t a = 0; a < assignments; ++a) {
    Objective total;
    bool feasible = true;
    for (std::size_t c = 0; c < couriers && feasible; ++c) {
      SchedulingProblem share = p;
      share.jobs.clear();
      std::size_t code = a;
      for (std::size_t j = 0, k = 0; j < p.jobs.size(); ++j) {
        const Job& job = p.jobs[j];
        if (job.status == JobStatus::kAboard) {
          if (job.aboard_courier == static_cast<int>(c)) share.jobs.push_back(job);
          continue;
        }
        if (code % couriers == c) share.jobs.push_back(job);
        code /= couriers, ++k;
      }
      const ReferenceDpResult dp = reference_dp(share, static_cast<int>(c));
      feasible = dp.feasible;
      total += dp.best;
    }
    if (feasible && (!found || better(total, best))) best = total, found = true;
  }
  return found;
}

// Couriers that become available after now (busy finishing something, or after a forced
// prefix): leaving one idle can be optimal. The exact engine took a courier with no jobs for an
// infeasible assignment unless its incumbent (the large engine's) happened to leave it idle too,
// so it missed such optima (property test instance 2103: 761 s of completion instead of 742 s).
// Instances 855, 1023, 1335 and 2205 are ones it missed; the others are a plain range.
SchedulingProblem busy_courier_office(int i) {
  OfficeSpec spec;
  spec.jobs = 5;
  spec.couriers = 2 + i % 2;
  spec.rooms = 8;
  spec.capacity = 1 + (i / 3) % 3;
  spec.kinds = 2;
  spec.colours = 2;
  spec.deadline_percent = 30;
  spec.aboard_percent = 20;
  spec.presence = i % 2;
  spec.seed = 600 + static_cast<std::uint64_t>(i);
  SchedulingProblem p = random_office(spec);
  p.couriers[0].available_s = p.now_s + 60.0 + 20.0 * (i % 10);  // busy 1 to 4 minutes more
  return p;
}

TEST(ExactEngineCouriers, EqualsTheBestAssignmentWhenACourierBecomesAvailableLater) {
  auto exact = make_scheduler_engine("exact");
  std::vector<int> instances{855, 1023, 1335, 2205};
  for (int i = 0; i < 16; ++i) instances.push_back(i);
  int idle = 0;
  for (int i : instances) {
    const SchedulingProblem p = busy_courier_office(i);
    const std::string what = "instance " + std::to_string(i);
    Objective best;
    ASSERT_TRUE(best_by_assignment(p, best)) << what;
    const JobSchedule s = exact->solve(p, {});
    ASSERT_TRUE(s.ok()) << what << ": " << s.reason;
    EXPECT_TRUE(s.proved_optimal) << what;
    EXPECT_EQ(compare(s.objective, best), 0)
        << what << ": exact " << s.objective.completion_s << " s completion, "
        << s.objective.travel_s << " s travel; best assignment " << best.completion_s << ", "
        << best.travel_s;
    idle += s.routes.at(0).stops.empty() ? 1 : 0;
  }
  EXPECT_GE(idle, 4);  // the optimum leaves the busy courier idle at least where it was missed
}

}  // namespace
}  // namespace autonomy::courier::scheduling
