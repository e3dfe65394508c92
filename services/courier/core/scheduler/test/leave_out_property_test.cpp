// Property test of feasibility and of the rule for leaving jobs out (docs/courier-scheduling.md,
// "Jobs left out"): thousands of seeded random offices with short presence windows, look-alikes,
// capacity, objects aboard, several couriers, closed rooms and some forced prefixes. The large and
// the exact engine must agree on whether there is a schedule and on which jobs are left out, and
// every schedule must be what evaluate_order says of its own order. On the smallest instances an
// independent brute force (its own search over stop orders, the model's presence function only)
// applies the rule itself and must leave out the same jobs.
#include "services/courier/core/scheduler/random_office.hpp"
#include "services/courier/core/scheduler/schedule_evaluation.hpp"
#include "services/courier/core/scheduler/scheduler_engine.hpp"
#include "services/courier/core/scheduler/test/small_office.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

namespace autonomy::courier::scheduling {
namespace {

using test::D;
using test::job;
using test::P;
using test::small_office;

// ---- Hand-computed cases (small_office: hall -10 s- A-111 table -20 s- A-120 desk, hall -25 s-
// A-120 desk; 5 s handovers; now 10:00) -----------------------------------------------------------

// Anna at the A-120 desk (5 s handover) until `leaves`; Bob at the A-111 table until `bob_leaves`.
SchedulingProblem office_with_people(double anna_leaves, double bob_leaves) {
  SchedulingProblem p = small_office(/*capacity=*/2);
  p.people.push_back({"Anna", 5.0, {{30000.0, anna_leaves}}});
  p.people.push_back({"Bob", 5.0, {{30000.0, bob_leaves}}});
  return p;
}

TEST(LeaveOut, APersonGoneBeforeAnyCourierArrivesLeavesOnlyThatJobOut) {
  // To Anna: pickup at the hall 10:00:05, at her desk 10:00:30; she leaves at 10:00:20.
  SchedulingProblem p = office_with_people(36020.0, 40000.0);
  p.jobs.push_back(job("to-anna", 0, 2, "red"));
  p.jobs[0].delivery.person = 0;
  p.jobs.push_back(job("to-bob", 0, 1, "green"));
  p.jobs[1].delivery.person = 1;
  for (const auto& name : scheduler_engine_names()) {
    const JobSchedule s = make_scheduler_engine(name)->solve(p, {});
    ASSERT_TRUE(s.ok()) << name << ": " << s.reason;
    ASSERT_EQ(s.unschedulable.size(), 1u) << name;
    EXPECT_EQ(s.unschedulable[0].job, 0);
    EXPECT_EQ(s.unschedulable[0].reason, UnschedulableReason::kNobodyPresent);
    EXPECT_EQ(s.unschedulable[0].detail,
              "delivery at A-120 desk: Anna leaves at 10:00:20, the earliest arrival is 10:00:30");
    ASSERT_EQ(s.outcomes.size(), 1u) << name;
    EXPECT_EQ(s.outcomes[0].job, 1);
  }
  // Arriving before she leaves but too late for the handover.
  p.people[0].presence[0].end_s = 36033.0;
  EXPECT_EQ(find_unschedulable(p).at(0).detail,
            "delivery at A-120 desk: Anna leaves at 10:00:33, the earliest arrival is 10:00:30, "
            "too late for the 5 s handover");
  // The earliest arrival counts from when the courier is available: both fit when Anna stays
  // until 10:01, but not once the courier is busy until 10:00:40.
  p.people[0].presence[0].end_s = 36060.0;
  EXPECT_TRUE(find_unschedulable(p).empty());
  p.couriers[0].available_s = 36040.0;  // busy until 10:00:40: pickup 10:00:45, at Anna's 10:01:10
  ASSERT_EQ(find_unschedulable(p).size(), 1u);
  EXPECT_NE(find_unschedulable(p)[0].detail.find("the earliest arrival is 10:01:10"),
            std::string::npos);
}

TEST(LeaveOut, JobsDoableAloneButNotTogetherKeepTheOneAcceptedFirst) {
  // Each alone: to Bob by 10:00:30, to Anna by 10:00:40. Together: whichever is
  // second arrives too late (Bob then Anna: Anna's desk at 10:00:45; Anna then Bob: 10:01:00).
  for (int first : {0, 1}) {
    SchedulingProblem p = office_with_people(36040.0, 36030.0);
    Job to_anna = job("to-anna", 0, 2, "red");
    to_anna.delivery.person = 0;
    Job to_bob = job("to-bob", 0, 1, "green");
    to_bob.delivery.person = 1;
    p.jobs = first == 0 ? std::vector<Job>{to_anna, to_bob} : std::vector<Job>{to_bob, to_anna};
    const std::string dropped = first == 0 ? "to-bob" : "to-anna";
    const std::string kept = first == 0 ? "to-anna" : "to-bob";
    for (const auto& name : scheduler_engine_names()) {
      const JobSchedule s = make_scheduler_engine(name)->solve(p, {});
      ASSERT_TRUE(s.ok()) << name << ": " << s.reason;
      ASSERT_EQ(s.unschedulable.size(), 1u) << name;
      EXPECT_EQ(p.jobs[static_cast<std::size_t>(s.unschedulable[0].job)].id, dropped) << name;
      EXPECT_EQ(s.unschedulable[0].reason, UnschedulableReason::kClash);
      EXPECT_EQ(s.unschedulable[0].detail, "cannot be done together with job '" + kept + "'");
      ASSERT_EQ(s.outcomes.size(), 1u);
      EXPECT_TRUE(evaluate_order(p, s.order()).ok()) << name;
    }
  }
}

TEST(LeaveOut, OnlyAForcedPrefixThatCannotBeDoneMakesTheProblemInfeasible) {
  SchedulingProblem p = office_with_people(36020.0, 40000.0);
  p.jobs.push_back(job("to-anna", 0, 2, "red"));
  p.jobs[0].delivery.person = 0;
  p.jobs.push_back(job("to-bob", 0, 1, "green"));
  p.couriers[0].forced_prefix = {P(0), D(0)};  // "deliver to Anna now": she is gone by then
  for (const auto& name : scheduler_engine_names()) {
    const JobSchedule s = make_scheduler_engine(name)->solve(p, {});
    EXPECT_EQ(s.status, ScheduleStatus::kInfeasible) << name << ": " << s.reason;
  }
}

TEST(LeaveOut, ADetourThatMakesAnotherJobImpossibleDoesNotKeepDeadlines) {
  // To Anna fits first thing (at her desk 10:00:30, she leaves at 10:00:40); after the detour to
  // the A-111 table it is missed, left out rather than late.
  SchedulingProblem p = office_with_people(36040.0, 40000.0);
  p.jobs.push_back(job("to-anna", 0, 2, "red"));
  p.jobs[0].delivery.person = 0;
  p.jobs.push_back(job("to-table", 0, 1, "green"));
  auto engine = make_scheduler_engine("exact");
  const OpportunityCheck check = check_opportunity(p, 0, {P(1), D(1)}, *engine, {});
  ASSERT_TRUE(check.without_detour.ok());
  EXPECT_TRUE(check.without_detour.unschedulable.empty());
  ASSERT_TRUE(check.with_detour.ok()) << check.with_detour.reason;
  ASSERT_EQ(check.with_detour.unschedulable.size(), 1u);
  EXPECT_FALSE(check.keeps_deadlines);
}

// ---- Instances ---------------------------------------------------------------------------------

SchedulingProblem instance(int i) {
  OfficeSpec spec;
  spec.jobs = 3 + i % 6;  // 3..8
  spec.couriers = 1 + (i / 6) % 3;
  if (spec.jobs >= 7) spec.couriers = std::min(spec.couriers, 2);
  spec.rooms = 8;
  spec.capacity = 1 + (i / 18) % 3;
  spec.kinds = 2;
  spec.colours = 2;
  spec.deadline_percent = 50;
  spec.aboard_percent = 25;
  spec.tight_presence_percent = 40;
  spec.tight_max_s = 300 + 100 * (i % 7);
  spec.closed_rooms = i % 3;
  spec.seed = 7000 + static_cast<std::uint64_t>(i);
  SchedulingProblem p = random_office(spec);
  // Every seventh: the first courier must do job 0 first (its delivery, or both stops).
  if (i % 7 == 3) {
    const Job& j0 = p.jobs[0];
    if (j0.status == JobStatus::kWaitingForPickup)
      p.couriers[0].forced_prefix = {{0, StopKind::kPickup}, {0, StopKind::kDelivery}};
    else if (j0.aboard_courier == 0)
      p.couriers[0].forced_prefix = {{0, StopKind::kDelivery}};
  }
  return p;
}

std::vector<int> left_out_jobs(const JobSchedule& s) {
  std::vector<int> out;
  for (const UnschedulableJob& u : s.unschedulable) out.push_back(u.job);
  return out;
}

// ---- Independent brute force -------------------------------------------------------------------

struct Walker {
  double t = 0.0;
  int loc = 0;
  std::vector<int> aboard;
};

// One stop, from the model's text: rules at a pickup, finite travel, a presence window that holds
// the whole handover (the courier may wait).
bool walk(const SchedulingProblem& p, int courier, Walker& w, int j, bool pickup) {
  const Job& job = p.jobs[static_cast<std::size_t>(j)];
  if (pickup) {
    if (static_cast<int>(w.aboard.size()) >= p.couriers[static_cast<std::size_t>(courier)].capacity)
      return false;
    for (int a : w.aboard)
      if (p.jobs[static_cast<std::size_t>(a)].object == job.object) return false;
  } else if (std::find(w.aboard.begin(), w.aboard.end(), j) == w.aboard.end()) {
    return false;
  }
  const Place& place = pickup ? job.pickup : job.delivery;
  const double drive =
      p.travel.at(static_cast<std::size_t>(w.loc), static_cast<std::size_t>(place.location));
  if (drive == kNoRoute) return false;
  const double duration = handover_duration(p, place);
  const double start = earliest_handover_start(p, place.person, w.t + drive, duration);
  if (start == kNoRoute) return false;
  w.t = start + duration;
  w.loc = place.location;
  if (pickup)
    w.aboard.push_back(j);
  else
    w.aboard.erase(std::find(w.aboard.begin(), w.aboard.end(), j));
  return true;
}

Walker start_of(const SchedulingProblem& p, int c) {
  const Courier& courier = p.couriers[static_cast<std::size_t>(c)];
  Walker w;
  w.t = std::max(p.now_s, courier.available_s);
  w.loc = courier.location;
  for (std::size_t j = 0; j < p.jobs.size(); ++j)
    if (p.jobs[j].status == JobStatus::kAboard && p.jobs[j].aboard_courier == c)
      w.aboard.push_back(static_cast<int>(j));
  return w;
}

// Can the couriers from `c` on do every job in `todo` (1 = still to do; aboard jobs of a courier
// not in `todo` stay aboard)? Courier by courier: its route picks up and delivers todo jobs until
// it stops with nothing of `todo` aboard.
bool brute_feasible(const SchedulingProblem& p, std::vector<char>& todo, int c, Walker w) {
  const auto n = p.jobs.size();
  bool carries_todo = false;
  for (int a : w.aboard) carries_todo = carries_todo || todo[static_cast<std::size_t>(a)];
  if (!carries_todo) {
    bool none_waiting = true;
    for (std::size_t j = 0; j < n; ++j) none_waiting = none_waiting && !todo[j];
    if (none_waiting) return true;
    if (c + 1 < static_cast<int>(p.couriers.size()) && brute_feasible(p, todo, c + 1, start_of(p, c + 1)))
      return true;
  }
  for (std::size_t j = 0; j < n; ++j) {
    if (!todo[j]) continue;
    const bool aboard = std::find(w.aboard.begin(), w.aboard.end(), static_cast<int>(j)) != w.aboard.end();
    if (!aboard && p.jobs[j].status == JobStatus::kAboard) continue;  // on another courier
    Walker next = w;
    if (!walk(p, c, next, static_cast<int>(j), !aboard)) continue;
    if (aboard) todo[j] = 0;
    const bool ok = brute_feasible(p, todo, c, next);
    if (aboard) todo[j] = 1;
    if (ok) return true;
  }
  return false;
}

// The rule, applied by brute force (problems without forced prefixes): left out alone first
// (no courier can do the job on its own from where it starts), then the others admitted in
// order, jobs aboard first, each kept when it can be done together with those kept before.
std::vector<int> brute_left_out(const SchedulingProblem& p) {
  const auto n = p.jobs.size();
  std::vector<char> out(n, 0);
  for (std::size_t j = 0; j < n; ++j) {
    bool alone = false;
    for (int c = 0; c < static_cast<int>(p.couriers.size()) && !alone; ++c) {
      if (p.jobs[j].status == JobStatus::kAboard && p.jobs[j].aboard_courier != c) continue;
      Walker w = start_of(p, c);
      w.aboard.clear();
      if (p.jobs[j].status == JobStatus::kAboard) w.aboard.push_back(static_cast<int>(j));
      alone = (p.jobs[j].status == JobStatus::kAboard ||
               walk(p, c, w, static_cast<int>(j), true)) &&
              walk(p, c, w, static_cast<int>(j), false);
    }
    out[j] = !alone;
  }
  std::vector<int> order;
  for (int pass = 0; pass < 2; ++pass)
    for (std::size_t j = 0; j < n; ++j)
      if (!out[j] && (p.jobs[j].status == JobStatus::kAboard) == (pass == 0))
        order.push_back(static_cast<int>(j));
  std::vector<char> kept(n, 0);
  for (int j : order) {
    kept[static_cast<std::size_t>(j)] = 1;
    std::vector<char> todo = kept;
    if (!brute_feasible(p, todo, 0, start_of(p, 0))) kept[static_cast<std::size_t>(j)] = 0, out[static_cast<std::size_t>(j)] = 1;
  }
  std::vector<int> left;
  for (std::size_t j = 0; j < n; ++j)
    if (out[j]) left.push_back(static_cast<int>(j));
  return left;
}

// ---- The property ------------------------------------------------------------------------------

TEST(LeaveOutProperty, LargeAndExactAgreeOnFeasibilityAndOnTheJobsLeftOut) {
  auto large = make_scheduler_engine("large");
  auto exact = make_scheduler_engine("exact");
  constexpr int kInstances = 2400;
  int full = 0, partial = 0, infeasible = 0, large_wrong = 0, brute_checked = 0, large_better = 0;
  for (int i = 0; i < kInstances; ++i) {
    const SchedulingProblem p = instance(i);
    const std::string what = "instance " + std::to_string(i);
    SearchBudget budget;
    budget.max_work = 4000;  // its first schedule is what is compared, not its search
    const JobSchedule e = exact->solve(p, {});
    const JobSchedule l = large->solve(p, budget);
    ASSERT_NE(e.status, ScheduleStatus::kNoSolution) << what << ": " << e.reason;
    if (l.ok() != e.ok()) ++large_wrong;
    EXPECT_EQ(l.ok(), e.ok()) << what << ": large " << l.reason << "; exact " << e.reason;
    EXPECT_EQ(left_out_jobs(l), left_out_jobs(e)) << what;
    if (!e.ok()) {
      ++infeasible;
      // Only a forced prefix that cannot be done makes a whole problem infeasible.
      EXPECT_FALSE(p.couriers[0].forced_prefix.empty()) << what << ": " << e.reason;
      continue;
    }
    ++(e.unschedulable.empty() ? full : partial);
    for (const JobSchedule* s : {&e, &l}) {
      if (!s->ok()) continue;
      const JobSchedule again = evaluate_order(p, s->order());
      ASSERT_TRUE(again.ok()) << what << " " << s->engine << ": " << again.reason;
      EXPECT_EQ(compare(again.objective, s->objective), 0) << what << " " << s->engine;
    }
    // Not asserted: the exact engine is not always optimal when a courier becomes available after
    // now (e.g. after a forced prefix), a defect of its own; counted so that it shows.
    if (l.ok() && better(l.objective, e.objective)) ++large_better;
    if (p.jobs.size() <= 6 && p.couriers[0].forced_prefix.empty()) {
      EXPECT_EQ(left_out_jobs(e), brute_left_out(p)) << what;
      ++brute_checked;
    }
  }
  std::printf("%d instances: %d scheduled in full, %d partial, %d infeasible; large engine wrong "
              "on %d; %d checked against the brute-force rule; large better than exact on %d\n",
              kInstances, full, partial, infeasible, large_wrong, brute_checked, large_better);
  EXPECT_GT(partial, kInstances / 10);
  EXPECT_GT(brute_checked, kInstances / 3);
}

}  // namespace
}  // namespace autonomy::courier::scheduling
