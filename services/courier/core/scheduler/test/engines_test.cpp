// The engines against brute-force enumeration (random seeded offices up to 7 jobs), against each
// other and on hand-computed cases. The brute force has its own simulation, written from the
// model in scheduling_problem.hpp, so it does not share code with what it checks.
#include "services/courier/core/scheduler/random_office.hpp"
#include "services/courier/core/scheduler/reference_dp.hpp"
#include "services/courier/core/scheduler/schedule_evaluation.hpp"
#include "services/courier/core/scheduler/scheduler_engine.hpp"
#include "services/courier/core/scheduler/test/small_office.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <vector>

namespace autonomy::courier::scheduling {
namespace {

using test::D;
using test::job;
using test::P;
using test::small_office;

// ---- Brute force -------------------------------------------------------------------------------

struct BruteState {
  double t = 0;
  int loc = 0;
  bool visited = false;
  std::vector<int> aboard;
  Objective cost;
};

bool brute_step(const SchedulingProblem& p, int capacity, BruteState& s, int j, bool pickup) {
  const Job& jb = p.jobs[static_cast<std::size_t>(j)];
  const Place& place = pickup ? jb.pickup : jb.delivery;
  if (pickup) {
    if (static_cast<int>(s.aboard.size()) >= capacity) return false;
    for (int a : s.aboard)
      if (p.jobs[static_cast<std::size_t>(a)].object == jb.object) return false;
  }
  const double tt =
      p.travel.at(static_cast<std::size_t>(s.loc), static_cast<std::size_t>(place.location));
  if (tt == kNoRoute) return false;
  const double arrival = s.t + tt;
  const double dur = place.person >= 0
                         ? p.people[static_cast<std::size_t>(place.person)].handover_s
                         : p.locations[static_cast<std::size_t>(place.location)].station_handover_s;
  double start = arrival;
  if (place.person >= 0 && !p.people[static_cast<std::size_t>(place.person)].presence.empty()) {
    start = kNoRoute;
    for (const TimeWindow& w : p.people[static_cast<std::size_t>(place.person)].presence) {
      const double b = std::max(arrival, w.start_s);
      if (b + dur <= w.end_s) {
        start = b;
        break;
      }
    }
    if (start == kNoRoute) return false;
  }
  if (!(s.visited && s.loc == place.location)) ++s.cost.interruptions;
  s.cost.travel_s += tt;
  s.t = start + dur;
  s.loc = place.location;
  s.visited = true;
  if (pickup) {
    s.aboard.push_back(j);
  } else {
    s.aboard.erase(std::find(s.aboard.begin(), s.aboard.end(), j));
    s.cost.completion_s += s.t - p.now_s;
    if (jb.deadline_s && s.t > *jb.deadline_s + 1e-9) {
      ++s.cost.late_jobs;
      s.cost.lateness_s += s.t - *jb.deadline_s;
    }
  }
  return true;
}

// Every feasible order of `jobs` for one courier; the best cost, false if none.
void brute_route(const SchedulingProblem& p, int capacity, const std::vector<int>& jobs,
                 std::vector<int>& state /*0 waiting 1 aboard 2 done*/, const BruteState& s,
                 bool& found, Objective& best, std::uint64_t& leaves) {
  bool all_done = true;
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    if (state[i] == 2) continue;
    all_done = false;
    BruteState next = s;
    const bool pickup = state[i] == 0;
    if (!brute_step(p, capacity, next, jobs[i], pickup)) continue;
    ++state[i];
    brute_route(p, capacity, jobs, state, next, found, best, leaves);
    --state[i];
  }
  if (all_done) {
    ++leaves;
    if (!found || better(s.cost, best)) best = s.cost, found = true;
  }
}

bool brute_force(const SchedulingProblem& p, Objective& best, std::uint64_t& leaves) {
  const std::size_t couriers = p.couriers.size();
  std::vector<int> open;
  for (std::size_t j = 0; j < p.jobs.size(); ++j)
    if (p.jobs[j].status == JobStatus::kWaitingForPickup) open.push_back(static_cast<int>(j));
  std::size_t assignments = 1;
  for (std::size_t k = 0; k < open.size(); ++k) assignments *= couriers;
  bool any = false;
  for (std::size_t a = 0; a < assignments; ++a) {
    Objective total;
    bool feasible = true;
    std::size_t code = a;
    std::vector<std::vector<int>> mine(couriers);
    for (int j : open) mine[code % couriers].push_back(j), code /= couriers;
    for (std::size_t c = 0; c < couriers && feasible; ++c) {
      BruteState s;
      s.t = std::max(p.now_s, p.couriers[c].available_s);
      s.loc = p.couriers[c].location;
      std::vector<int> jobs = mine[c];
      std::vector<int> state(jobs.size(), 0);
      for (std::size_t j = 0; j < p.jobs.size(); ++j)
        if (p.jobs[j].status == JobStatus::kAboard &&
            p.jobs[j].aboard_courier == static_cast<int>(c)) {
          s.aboard.push_back(static_cast<int>(j));
          jobs.push_back(static_cast<int>(j));
          state.push_back(1);
        }
      bool found = false;
      Objective best_c;
      brute_route(p, p.couriers[c].capacity, jobs, state, s, found, best_c, leaves);
      feasible = found;
      total += best_c;
    }
    if (feasible && (!any || better(total, best))) best = total, any = true;
  }
  return any;
}

void expect_same(const Objective& a, const Objective& b, const std::string& what) {
  EXPECT_EQ(a.late_jobs, b.late_jobs) << what;
  EXPECT_NEAR(a.lateness_s, b.lateness_s, 1e-6) << what;
  EXPECT_NEAR(a.completion_s, b.completion_s, 1e-6) << what;
  EXPECT_NEAR(a.travel_s, b.travel_s, 1e-6) << what;
  EXPECT_EQ(a.interruptions, b.interruptions) << what;
}

// ---- Exact against brute force -----------------------------------------------------------------

TEST(ExactEngine, EqualsBruteForceOnRandomOfficesUpToSevenJobs) {
  auto exact = make_scheduler_engine("exact");
  int compared = 0;
  for (int jobs = 1; jobs <= 7; ++jobs)
    for (std::uint64_t seed = 1; seed <= 6; ++seed) {
      OfficeSpec spec;
      spec.jobs = jobs;
      spec.rooms = 8;
      spec.capacity = jobs == 7 ? 2 : 1 + static_cast<int>(seed % 3);
      spec.colours = 2;
      spec.kinds = 1;  // many look-alikes
      spec.deadline_percent = 60;
      spec.aboard_percent = seed % 2 ? 30 : 0;
      spec.seed = seed * 100 + static_cast<std::uint64_t>(jobs);
      const SchedulingProblem p = random_office(spec);
      const std::string what =
          "jobs " + std::to_string(jobs) + " seed " + std::to_string(spec.seed);
      Objective brute;
      std::uint64_t leaves = 0;
      const bool feasible = brute_force(p, brute, leaves);
      const JobSchedule s = exact->solve(p, {});
      ASSERT_EQ(s.ok(), feasible) << what << ": " << s.reason;
      if (!feasible) continue;
      EXPECT_TRUE(s.proved_optimal) << what;
      expect_same(s.objective, brute, what);
      // The schedule is what evaluate_order says of its own order.
      const JobSchedule again = evaluate_order(p, s.order());
      ASSERT_TRUE(again.ok()) << what << ": " << again.reason;
      expect_same(again.objective, s.objective, what);
      ++compared;
    }
  EXPECT_GE(compared, 40);
}

TEST(ExactEngine, EqualsBruteForceWithTwoCouriers) {
  auto exact = make_scheduler_engine("exact");
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    OfficeSpec spec;
    spec.jobs = 3 + static_cast<int>(seed % 3);
    spec.couriers = 2;
    spec.rooms = 8;
    spec.capacity = 2;
    spec.deadline_percent = 70;
    spec.aboard_percent = 20;
    spec.seed = seed;
    const SchedulingProblem p = random_office(spec);
    Objective brute;
    std::uint64_t leaves = 0;
    ASSERT_TRUE(brute_force(p, brute, leaves));
    const JobSchedule s = exact->solve(p, {});
    ASSERT_TRUE(s.ok()) << s.reason;
    EXPECT_TRUE(s.proved_optimal);
    expect_same(s.objective, brute, "seed " + std::to_string(seed));
  }
}

TEST(ExactEngine, EqualsTheTextbookDynamicProgram) {
  auto exact = make_scheduler_engine("exact");
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    OfficeSpec spec;
    spec.jobs = 9;
    spec.seed = seed;
    const SchedulingProblem p = random_office(spec);
    const ReferenceDpResult dp = reference_dp(p);
    const JobSchedule s = exact->solve(p, {});
    ASSERT_TRUE(dp.feasible);
    ASSERT_TRUE(s.ok()) << s.reason;
    expect_same(s.objective, dp.best, "seed " + std::to_string(seed));
    expect_same(evaluate_order(p, {dp.route}).objective, dp.best, "dp route");
  }
}

TEST(ExactEngine, StopsAtTheBudgetAndSaysNotProved) {
  OfficeSpec spec;
  spec.jobs = 14;
  spec.seed = 3;
  const SchedulingProblem p = random_office(spec);
  SearchBudget budget;
  budget.max_work = 2000;
  const JobSchedule s = make_scheduler_engine("exact")->solve(p, budget);
  ASSERT_TRUE(s.ok()) << s.reason;  // the incumbent, complete
  EXPECT_FALSE(s.proved_optimal);
  EXPECT_NE(s.reason.find("not proved"), std::string::npos);
}

// ---- Hand-computed cases -----------------------------------------------------------------------

TEST(Engines, TwoRedLettersAreNeverAboardTogether) {
  SchedulingProblem p = small_office(/*capacity=*/3);
  p.jobs.push_back(job("red1", 1, 2, "red"));
  p.jobs.push_back(job("red2", 1, 2, "red"));
  for (const auto& name : scheduler_engine_names()) {
    const JobSchedule s = make_scheduler_engine(name)->solve(p, {});
    ASSERT_TRUE(s.ok()) << name << ": " << s.reason;
    const auto order = s.order()[0];
    ASSERT_EQ(order.size(), 4u) << name;
    // One job completely, then the other.
    EXPECT_EQ(order[0].job, order[1].job) << name;
    EXPECT_EQ(order[1].kind, StopKind::kDelivery) << name;
  }
  // Exact: hall->A-111 (10) +5, ->A-120 (20) +5 = 40; back (20) +5, (20) +5 = 90.
  const JobSchedule s = make_scheduler_engine("exact")->solve(p, {});
  EXPECT_DOUBLE_EQ(s.objective.completion_s, 40.0 + 90.0);
  // Different colours: both loaded in one visit, delivered in one visit.
  p.jobs[1].object.colour = "green";
  const JobSchedule both = make_scheduler_engine("exact")->solve(p, {});
  EXPECT_DOUBLE_EQ(both.objective.completion_s, 45.0 + 50.0);
  EXPECT_EQ(both.objective.interruptions, 2);
}

TEST(Engines, TheFaxbotExampleInterleavesTheTwoJobs) {
  // Red letter A-111 -> A-120, green book A-110 -> A-114 (section 2 of the paper).
  SchedulingProblem p;
  p.now_s = 36000;
  const char* names[] = {"hall", "A-111 table", "A-120 desk", "A-110 desk", "A-114 desk"};
  const double x[] = {0, 2, 10, 0, 6};
  const double y[] = {0, 5, 5, -5, -5};
  for (int i = 0; i < 5; ++i) {
    Location l;
    l.name = names[i];
    if (i) l.room = std::string(names[i]).substr(0, 5);
    l.x_m = x[i], l.y_m = y[i];
    l.station_handover_s = 10;
    p.locations.push_back(l);
  }
  p.travel = TravelMatrix(5);
  for (std::size_t a = 0; a < 5; ++a)
    for (std::size_t b = 0; b < 5; ++b)
      if (a != b) p.travel.set(a, b, std::abs(y[a]) + std::abs(x[a] - x[b]) + std::abs(y[b]));
  Courier c;
  c.id = "rhino";
  c.capacity = 2;
  c.location = 0;
  c.available_s = 36000;
  p.couriers.push_back(c);
  p.jobs.push_back(job("red letter", 1, 2, "red", "letter"));
  p.jobs.push_back(job("green book", 3, 4, "green", "book"));
  const JobSchedule s = make_scheduler_engine("exact")->solve(p, {});
  ASSERT_TRUE(s.ok()) << s.reason;
  EXPECT_TRUE(s.proved_optimal);
  // Every job on time, assumptions: the four rooms.
  std::vector<std::string> rooms;
  for (const auto& a : s.assumptions) rooms.push_back(a.room);
  std::sort(rooms.begin(), rooms.end());
  EXPECT_EQ(rooms, (std::vector<std::string>{"A-110", "A-111", "A-114", "A-120"}));
}

TEST(Engines, DeadlineDecidesTheOrder) {
  SchedulingProblem p = small_office(/*capacity=*/1);
  p.jobs.push_back(job("near", 0, 1, "red"));   // hall -> A-111
  p.jobs.push_back(job("far", 0, 2, "green"));  // hall -> A-120
  // Without deadlines the near job goes first: near 5 + 10 + 5 = 20, far 20 + 10 + 5 + 25 + 5 = 65
  // (85), against far 35, near 35 + 25 + 5 + 10 + 5 = 80 (115).
  JobSchedule s = make_scheduler_engine("exact")->solve(p, {});
  ASSERT_TRUE(s.ok());
  EXPECT_EQ(s.order()[0][0].job, 0);
  EXPECT_DOUBLE_EQ(s.objective.completion_s, 85.0);
  // The far job due at 10:00:40: it goes first (finish 35, near 80).
  p.jobs[1].deadline_s = 36040.0;
  s = make_scheduler_engine("exact")->solve(p, {});
  ASSERT_TRUE(s.ok());
  EXPECT_EQ(s.order()[0][0].job, 1);
  EXPECT_EQ(s.objective.late_jobs, 0);
  EXPECT_DOUBLE_EQ(s.objective.completion_s, 35.0 + 80.0);
  // Impossible deadline (10:00:20): one late job either way; far first is 15 s late, near first
  // would make it 45 s late.
  p.jobs[1].deadline_s = 36020.0;
  s = make_scheduler_engine("exact")->solve(p, {});
  EXPECT_EQ(s.objective.late_jobs, 1);
  EXPECT_DOUBLE_EQ(s.objective.lateness_s, 15.0);
  EXPECT_EQ(s.order()[0][0].job, 1);
}

TEST(Engines, PresenceMakesTheCourierServeSomeoneElseFirst) {
  SchedulingProblem p = small_office(/*capacity=*/1);
  p.people.push_back({"Michael", 5.0, {{36200.0, 40000.0}}});
  p.jobs.push_back(job("for Michael", 0, 2, "red"));
  p.jobs[0].delivery.person = 0;
  p.jobs.push_back(job("other", 0, 1, "green"));
  const JobSchedule s = make_scheduler_engine("exact")->solve(p, {});
  ASSERT_TRUE(s.ok()) << s.reason;
  EXPECT_EQ(s.order()[0][0].job, 1);
  // other: 5 + 10 + 5 = 20; then back 10 + 5, to A-120 25 -> 36065, wait to 36200, done 36205.
  EXPECT_DOUBLE_EQ(s.outcomes[0].completion_s, 36205.0);
  EXPECT_DOUBLE_EQ(s.routes[0].stops[3].handover_start_s, 36200.0);
}

TEST(Engines, ForcedPrefixIsKeptByEveryEngine) {
  SchedulingProblem p = small_office(/*capacity=*/2);
  p.jobs.push_back(job("a", 0, 1, "red"));
  p.jobs.push_back(job("b", 0, 2, "green"));
  p.couriers[0].forced_prefix = {P(1), D(1)};
  for (const auto& name : scheduler_engine_names()) {
    const JobSchedule s = make_scheduler_engine(name)->solve(p, {});
    ASSERT_TRUE(s.ok()) << name << ": " << s.reason;
    const auto order = s.order()[0];
    ASSERT_GE(order.size(), 2u);
    EXPECT_EQ(order[0], P(1)) << name;
    EXPECT_EQ(order[1], D(1)) << name;
  }
  // b: 5, 25 +5 = 35; a: back to the hall 25, 5 -> 65, A-111 10 + 5 -> 80.
  const JobSchedule s = make_scheduler_engine("exact")->solve(p, {});
  EXPECT_DOUBLE_EQ(s.objective.completion_s, 35.0 + 80.0);
  EXPECT_TRUE(s.proved_optimal);
}

// The opportunity check forces a job's first open step (its pickup alone) to the front; with its
// deadline already missed, the paper's deadline repair used to move the forced pickup out of the
// prefix and insert past the end of the route (a heap overrun the day-in-office experiment hit).
TEST(Engines, AForcedPickupOfAJobAlreadyLateStaysFirst) {
  for (int others = 0; others <= 1; ++others) {
    SchedulingProblem p = small_office(/*capacity=*/2);
    p.jobs.push_back(job("late", 0, 2, "red"));
    p.jobs[0].deadline_s = p.now_s + 1.0;
    if (others) p.jobs.push_back(job("other", 0, 1, "green"));
    p.couriers[0].forced_prefix = {P(0)};
    for (const auto& name : scheduler_engine_names()) {
      const JobSchedule s = make_scheduler_engine(name)->solve(p, {});
      ASSERT_TRUE(s.ok()) << name << ": " << s.reason;
      const auto order = s.order()[0];
      ASSERT_GE(order.size(), 2u) << name;
      EXPECT_EQ(order[0], P(0)) << name;
      EXPECT_EQ(s.objective.late_jobs, 1) << name;
      // The late delivery goes right after its forced pickup (the least lateness left).
      EXPECT_EQ(order[1], D(0)) << name;
    }
  }
}

TEST(Engines, UnreachableJobsAreReportedAndTheRestScheduled) {
  SchedulingProblem p = small_office(/*capacity=*/2);
  p.jobs.push_back(job("to A-120", 0, 2, "red"));
  p.jobs.push_back(job("to A-111", 0, 1, "green"));
  p.travel.cut_off(2);
  for (const auto& name : scheduler_engine_names()) {
    const JobSchedule s = make_scheduler_engine(name)->solve(p, {});
    ASSERT_TRUE(s.ok()) << name << ": " << s.reason;
    ASSERT_EQ(s.unschedulable.size(), 1u) << name;
    EXPECT_EQ(s.unschedulable[0].job, 0);
    ASSERT_EQ(s.outcomes.size(), 1u);
    EXPECT_EQ(s.outcomes[0].job, 1);
  }
}

TEST(Engines, InvalidProblemIsRefusedWithTheReason) {
  SchedulingProblem p = small_office();
  p.jobs.push_back(job("j", 0, 9));
  for (const auto& name : scheduler_engine_names()) {
    const JobSchedule s = make_scheduler_engine(name)->solve(p, {});
    EXPECT_EQ(s.status, ScheduleStatus::kInvalidProblem);
    EXPECT_NE(s.reason.find("jobs[0].delivery.location"), std::string::npos);
  }
  EXPECT_EQ(make_scheduler_engine("simplex"), nullptr);
}

TEST(OpportunityCheck, DetourThatKeepsDeadlinesAndOneThatDoesNot) {
  SchedulingProblem p = small_office(/*capacity=*/2);
  p.jobs.push_back(job("opportunity", 1, 2, "red"));
  p.jobs[0].status = JobStatus::kAboard;
  p.jobs[0].aboard_courier = 0;
  p.jobs.push_back(job("urgent", 0, 1, "green"));
  p.jobs[1].deadline_s = 36100.0;
  auto exact = make_scheduler_engine("exact");
  OpportunityCheck check = check_opportunity(p, 0, {D(0)}, *exact, {});
  EXPECT_TRUE(check.keeps_deadlines);  // 25+5 = 30; hall 25+5 = 60, A-111 10+5 = 75 <= 100
  p.jobs[1].deadline_s = 36050.0;  // without the detour: 5, 10+5 = 20 on time; with it: 75, late
  check = check_opportunity(p, 0, {D(0)}, *exact, {});
  EXPECT_FALSE(check.keeps_deadlines);
  EXPECT_EQ(check.with_detour.order()[0][0], D(0));
}

// ---- Large and paper against exact -------------------------------------------------------------

TEST(LargeEngine, GapToExactUpToTwelveJobs) {
  auto exact = make_scheduler_engine("exact");
  auto large = make_scheduler_engine("large");
  auto paper = make_scheduler_engine("paper");
  for (int jobs : {4, 8, 10, 12}) {
    double large_gap = 0, paper_gap = 0;
    int n = 0;
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
      OfficeSpec spec;
      spec.jobs = jobs;
      spec.seed = seed + 1000;
      const SchedulingProblem p = random_office(spec);
      const JobSchedule e = exact->solve(p, {});
      ASSERT_TRUE(e.ok() && e.proved_optimal) << e.reason;
      SearchBudget budget;
      budget.max_work = 200000;
      const JobSchedule l = large->solve(p, budget);
      const JobSchedule h = paper->solve(p, {});
      ASSERT_TRUE(l.ok()) << l.reason;
      ASSERT_TRUE(h.ok()) << h.reason;
      EXPECT_GE(compare(l.objective, e.objective), 0);
      EXPECT_GE(compare(h.objective, e.objective), 0);
      if (l.objective.late_jobs == e.objective.late_jobs)
        large_gap += l.objective.completion_s / e.objective.completion_s - 1.0;
      if (h.objective.late_jobs == e.objective.late_jobs)
        paper_gap += h.objective.completion_s / e.objective.completion_s - 1.0;
      ++n;
    }
    std::printf(
        "[ gap      ] %2d jobs: large +%.2f %%, paper +%.2f %% completion time (mean of %d)\n",
        jobs, 100.0 * large_gap / n, 100.0 * paper_gap / n, n);
  }
}

TEST(LargeEngine, ManyJobsAndCouriersGiveAFeasibleSchedule) {
  OfficeSpec spec;
  spec.jobs = 60;
  spec.couriers = 3;
  spec.rooms = 30;
  spec.aboard_percent = 5;
  spec.seed = 7;
  const SchedulingProblem p = random_office(spec);
  SearchBudget budget;
  budget.max_work = 300000;
  const JobSchedule s = make_scheduler_engine("large")->solve(p, budget);
  ASSERT_TRUE(s.ok()) << s.reason;
  EXPECT_EQ(s.outcomes.size(), 60u);
  const JobSchedule paper = make_scheduler_engine("paper")->solve(p, {});
  ASSERT_TRUE(paper.ok()) << paper.reason;
  EXPECT_LE(compare(s.objective, paper.objective), 0);
  // Same seed and work: the same schedule.
  const JobSchedule again = make_scheduler_engine("large")->solve(p, budget);
  EXPECT_EQ(compare(again.objective, s.objective), 0);
}

TEST(LargeEngine, ReschedulesFromThePreviousOrderAfterADoorCloses) {
  OfficeSpec spec;
  spec.jobs = 20;
  spec.seed = 11;
  SchedulingProblem p = random_office(spec);
  SearchBudget budget;
  budget.max_work = 100000;
  const JobSchedule before = make_scheduler_engine("large")->solve(p, budget);
  ASSERT_TRUE(before.ok());
  p.previous_order = before.order();
  p.travel.cut_off(3);
  const JobSchedule after = make_scheduler_engine("large")->solve(p, budget);
  ASSERT_TRUE(after.ok()) << after.reason;
  std::size_t affected = 0;
  for (const Job& j : p.jobs)
    affected += (j.pickup.location == 3 || j.delivery.location == 3) ? 1 : 0;
  EXPECT_EQ(after.unschedulable.size(), affected);
  EXPECT_EQ(after.outcomes.size(), p.jobs.size() - affected);
}

}  // namespace
}  // namespace autonomy::courier::scheduling
