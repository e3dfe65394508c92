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

TEST(ExactEngineBounds, EqualsTheDpWithObjectsAboardAndLookAlikes) {
  OfficeSpec spec = six_jobs(20, false);
  spec.capacity = 2;
  spec.kinds = 1;
  spec.colours = 2;
  spec.aboard_percent = 30;
  expect_exact_equals_dp(spec, 401, 12);
}

}  // namespace
}  // namespace autonomy::courier::scheduling
