// Courier scheduling engines on random seeded offices (services/courier/core/scheduler), every
// figure beside a baseline measured in the same run:
//   1. exact at 12 jobs (one courier) against the textbook dynamic program over (stops done,
//      position) (reference_dp.hpp): ms per schedule, same optimum checked;
//   1b. exact on loose offices (few deadlines, everybody always present: many orders are
//      feasible and close in cost, the hard case for its bound) at 12, 14 and 16 jobs, on the
//      bench's seeds and on seeds 1001-1020 (never tuned on), the DP beside it at 12 jobs;
//   2. large (anytime, wall-clock budget) and the paper's SCHEDULE-DELIVERIES against the exact
//      optimum at 8-12 jobs: gap in total completion time, late jobs and lateness;
//   3. large at 50 jobs (1 courier) and 200 jobs x 4 couriers within a budget, against the paper
//      heuristic on the same instances;
//   4. rescheduling after a door event (one location becomes unreachable) for 20 jobs, warm
//      started from the schedule being executed, against solving from scratch with 10x the budget;
//   5. the travel-time matrix from a map (one cost-to-go field per place), for the door event.
//
//   courier_bench [--instances 10] [--seed 1] [--quick] [--loose-only] [--loose-jobs 12 14 16]
//                 [--no-dp]
//
// Times are wall clock (steady_clock) medians; the machine is shared, so read the ratios.
// Nothing here passes or fails on time; exit 1 only if exact and the DP disagree on an optimum.
#include "common/grid/random_map.hpp"
#include "services/courier/core/scheduler/random_office.hpp"
#include "services/courier/core/scheduler/reference_dp.hpp"
#include "services/courier/core/scheduler/scheduler_engine.hpp"
#include "services/courier/core/scheduler/travel_times.hpp"
#include "services/courier/core/scheduler/wall_clock_budget.hpp"

#include <CLI/CLI.hpp>

#include <time.h>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace {

using namespace autonomy::courier::scheduling;
using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

// CPU time of this thread: on a shared machine it leaves out the time other processes hold the
// core, so it is the steadier figure.
double thread_cpu_ms() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) * 1e3 + static_cast<double>(ts.tv_nsec) * 1e-6;
}

// Nearest-rank percentile, q in [0, 1].
double percentile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const double rank = q * static_cast<double>(v.size() - 1) + 0.5;
  return v[std::min(v.size() - 1, static_cast<std::size_t>(rank))];
}

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const auto n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double mean(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x;
  return v.empty() ? 0.0 : s / static_cast<double>(v.size());
}

SearchBudget budget_ms(double ms, std::uint64_t seed = 1) {
  return wall_clock_budget(std::chrono::microseconds(static_cast<long long>(ms * 1000.0)), seed);
}

struct Run {
  JobSchedule schedule;
  double ms = 0;
  double cpu_ms = 0;
};

Run timed(SchedulerEngine& engine, const SchedulingProblem& p, const SearchBudget& budget) {
  const double c0 = thread_cpu_ms();
  const auto t0 = Clock::now();
  JobSchedule s = engine.solve(p, budget);
  const double ms = ms_since(t0);
  return {std::move(s), ms, thread_cpu_ms() - c0};
}

// Relative gap in total completion time (the term the engines differ on when nobody is late).
double gap(const Objective& got, const Objective& best) {
  return best.completion_s > 0 ? got.completion_s / best.completion_s - 1.0 : 0.0;
}

// Loose: one job in ten has a deadline, nobody is ever away. The bound's deadline terms say
// nothing and every label's cost is close to the others'.
OfficeSpec loose_office(int jobs, std::uint64_t seed) {
  OfficeSpec spec;
  spec.jobs = jobs;
  spec.rooms = std::max(16, jobs / 2);
  spec.capacity = 3;
  spec.deadline_percent = 10;
  spec.presence = false;
  spec.seed = seed;
  return spec;
}

OfficeSpec office(int jobs, int couriers, std::uint64_t seed) {
  OfficeSpec spec;
  spec.jobs = jobs;
  spec.couriers = couriers;
  spec.rooms = std::max(16, std::min(60, jobs / 2));
  spec.capacity = 3;
  spec.seed = seed;
  return spec;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Courier scheduling engines: exact vs textbook DP, large and paper vs exact"};
  int instances = 10;
  std::uint64_t seed = 1;
  bool quick = false;
  bool loose_only = false;
  app.add_option("--instances", instances, "random instances per row")->check(CLI::PositiveNumber);
  app.add_option("--seed", seed, "first instance seed");
  app.add_flag("--quick", quick, "3 instances per row, smaller budgets");
  app.add_flag("--loose-only", loose_only, "only section 1b (exact on loose offices)");
  std::vector<int> loose_jobs{12, 14, 16};
  app.add_option("--loose-jobs", loose_jobs, "job counts of section 1b")
      ->check(CLI::Range(1, 30));
  bool no_dp = false;
  app.add_flag("--no-dp", no_dp, "section 1b without the textbook DP (minutes at 12 jobs)");
  CLI11_PARSE(app, argc, argv);
  if (quick) instances = 3;
  auto exact = make_scheduler_engine("exact");
  auto large = make_scheduler_engine("large");
  auto paper = make_scheduler_engine("paper");
  int disagreements = 0;

  std::printf(
      "# courier_bench: %d instances per row, seeds %llu.., random offices (random_office.hpp)\n\n",
      instances, static_cast<unsigned long long>(seed));

  if (!loose_only) {
    // 1. Exact against the textbook DP.
    std::printf(
        "## 1. Exact engine against the textbook DP over (stops done, position), 1 courier\n\n");
    std::printf(
        "| jobs | exact ms median (CPU) | exact ms p90 (CPU) | exact ms max (CPU) | textbook DP "
        "CPU "
        "ms median | DP / exact (median CPU) | proved | same optimum |\n");
    std::printf("|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (int jobs : {8, 10, 12}) {
      std::vector<double> exact_ms, exact_cpu, dp_cpu;
      int proved = 0, same = 0;
      for (int i = 0; i < instances; ++i) {
        const SchedulingProblem p =
            random_office(office(jobs, 1, seed + static_cast<std::uint64_t>(i)));
        const Run e = timed(*exact, p, budget_ms(10000));
        const double c0 = thread_cpu_ms();
        const ReferenceDpResult dp = reference_dp(p);
        dp_cpu.push_back(thread_cpu_ms() - c0);
        exact_ms.push_back(e.ms);
        exact_cpu.push_back(e.cpu_ms);
        proved += e.schedule.proved_optimal ? 1 : 0;
        if (dp.feasible && e.schedule.ok() && compare(dp.best, e.schedule.objective) == 0)
          ++same;
        else
          ++disagreements;
      }
      std::printf(
          "| %d | %.2f (%.2f) | %.2f (%.2f) | %.2f (%.2f) | %.1f | %.1fx | %d/%d | %d/%d |\n", jobs,
          median(exact_ms), median(exact_cpu), percentile(exact_ms, 0.9),
          percentile(exact_cpu, 0.9), percentile(exact_ms, 1.0), percentile(exact_cpu, 1.0),
          median(dp_cpu), median(dp_cpu) / std::max(1e-9, median(exact_cpu)), proved, instances,
          same, instances);
    }
  }

  // 1b. Exact on loose offices, on the bench's seeds and on seeds it was never tuned on.
  std::printf(
      "\n## 1b. Exact engine on loose offices (10 %% of jobs with a deadline, everybody always "
      "present), 1 courier, 10 s budget\n\n");
  std::printf(
      "| jobs | seeds | exact ms median (CPU) | exact ms p90 (CPU) | exact ms max (CPU) | proved | "
      "textbook DP CPU ms median | same optimum as the DP |\n");
  std::printf("|---:|---|---:|---:|---:|---:|---:|---:|\n");
  struct Seeds {
    std::uint64_t first;
    int count;
  };
  for (int jobs : loose_jobs)
    for (const Seeds& seeds : {Seeds{seed, instances}, Seeds{1001, quick ? 3 : 20}}) {
      std::vector<double> exact_ms, exact_cpu, dp_cpu;
      int proved = 0, same = 0;
      const bool with_dp = !no_dp && jobs <= 12;  // 14 jobs: minutes and gigabytes
      for (int i = 0; i < seeds.count; ++i) {
        const SchedulingProblem p =
            random_office(loose_office(jobs, seeds.first + static_cast<std::uint64_t>(i)));
        const Run e = timed(*exact, p, budget_ms(10000));
        exact_ms.push_back(e.ms);
        exact_cpu.push_back(e.cpu_ms);
        proved += e.schedule.proved_optimal ? 1 : 0;
        if (!with_dp) continue;
        const double c0 = thread_cpu_ms();
        const ReferenceDpResult dp = reference_dp(p);
        dp_cpu.push_back(thread_cpu_ms() - c0);
        if (dp.feasible && e.schedule.ok() && compare(dp.best, e.schedule.objective) == 0)
          ++same;
        else if (e.schedule.proved_optimal || !e.schedule.ok())
          ++disagreements;  // a search that gave up (not proved) may miss it: the proved column
      }
      char dp_median[32] = "-", agree[32] = "-";
      if (with_dp) {
        std::snprintf(dp_median, sizeof dp_median, "%.0f", median(dp_cpu));
        std::snprintf(agree, sizeof agree, "%d/%d", same, seeds.count);
      }
      std::printf(
          "| %d | %llu-%llu | %.2f (%.2f) | %.2f (%.2f) | %.2f (%.2f) | %d/%d | %s | %s |\n", jobs,
          static_cast<unsigned long long>(seeds.first),
          static_cast<unsigned long long>(seeds.first + static_cast<std::uint64_t>(seeds.count) -
                                          1),
          median(exact_ms), median(exact_cpu), percentile(exact_ms, 0.9),
          percentile(exact_cpu, 0.9), percentile(exact_ms, 1.0), percentile(exact_cpu, 1.0), proved,
          seeds.count, dp_median, agree);
    }
  if (loose_only) {
    if (disagreements)
      std::printf("\nexact and the textbook DP disagree on %d instances\n", disagreements);
    return disagreements ? 1 : 0;
  }

  // 2. Large and paper against the exact optimum.
  const double small_budget = 5.0;
  std::printf("\n## 2. Gap to the exact optimum (1 courier; large with a %.0f ms budget)\n\n",
              small_budget);
  std::printf(
      "| jobs | large gap mean | large gap max | large late / exact late | paper gap mean | paper "
      "late / exact late | paper lateness s / exact | large ms | paper ms |\n");
  std::printf("|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (int jobs : {8, 10, 12}) {
    std::vector<double> lg, pg, lms, pms;
    int late_e = 0, late_l = 0, late_p = 0;
    double lateness_e = 0, lateness_p = 0;
    for (int i = 0; i < instances; ++i) {
      const SchedulingProblem p =
          random_office(office(jobs, 1, seed + 100 + static_cast<std::uint64_t>(i)));
      const Run e = timed(*exact, p, budget_ms(10000));
      const Run l = timed(*large, p, budget_ms(small_budget, seed + static_cast<std::uint64_t>(i)));
      const Run h = timed(*paper, p, {});
      if (!e.schedule.proved_optimal || !l.schedule.ok() || !h.schedule.ok()) continue;
      lg.push_back(gap(l.schedule.objective, e.schedule.objective));
      pg.push_back(gap(h.schedule.objective, e.schedule.objective));
      lms.push_back(l.ms);
      pms.push_back(h.ms);
      late_e += e.schedule.objective.late_jobs;
      late_l += l.schedule.objective.late_jobs;
      late_p += h.schedule.objective.late_jobs;
      lateness_e += e.schedule.objective.lateness_s;
      lateness_p += h.schedule.objective.lateness_s;
    }
    std::printf(
        "| %d | %.2f %% | %.2f %% | %d / %d | %.1f %% | %d / %d | %.0f / %.0f | %.2f | %.3f |\n",
        jobs, 100 * mean(lg), 100 * (lg.empty() ? 0 : *std::max_element(lg.begin(), lg.end())),
        late_l, late_e, 100 * mean(pg), late_p, late_e, lateness_p, lateness_e, median(lms),
        median(pms));
  }

  // 3. Large scale.
  std::printf(
      "\n## 3. Large instances: large engine within a budget against the paper heuristic\n\n");
  std::printf(
      "| jobs x couriers | budget ms | large ms (median) | large late | paper late | large "
      "completion / paper | large lateness s | paper lateness s | paper ms | late, completion with "
      "10x the budget / with the budget |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  struct Row {
    int jobs, couriers;
    double budget;
  };
  for (const Row& row : {Row{50, 1, 10.0}, Row{200, 4, 100.0}}) {
    std::vector<double> lms, pms, ratio, longer;
    double late_l = 0, late_p = 0, lat_l = 0, lat_p = 0, late_long = 0;
    for (int i = 0; i < instances; ++i) {
      const SchedulingProblem p =
          random_office(office(row.jobs, row.couriers, seed + 200 + static_cast<std::uint64_t>(i)));
      const Run l = timed(*large, p, budget_ms(row.budget, seed + static_cast<std::uint64_t>(i)));
      const Run h = timed(*paper, p, {});
      if (!l.schedule.ok() || !h.schedule.ok()) continue;
      lms.push_back(l.ms);
      pms.push_back(h.ms);
      ratio.push_back(l.schedule.objective.completion_s / h.schedule.objective.completion_s);
      late_l += l.schedule.objective.late_jobs;
      late_p += h.schedule.objective.late_jobs;
      lat_l += l.schedule.objective.lateness_s;
      lat_p += h.schedule.objective.lateness_s;
      const Run ten =
          timed(*large, p, budget_ms(10 * row.budget, seed + static_cast<std::uint64_t>(i)));
      if (ten.schedule.ok()) {
        late_long += ten.schedule.objective.late_jobs;
        longer.push_back(ten.schedule.objective.completion_s / l.schedule.objective.completion_s);
      }
    }
    const double n = std::max<std::size_t>(1, lms.size());
    std::printf(
        "| %d x %d | %.0f | %.1f | %.1f | %.1f | %.2f | %.0f | %.0f | %.2f | %.1f, %.3f |\n",
        row.jobs, row.couriers, row.budget, median(lms), late_l / n, late_p / n, mean(ratio),
        lat_l / n, lat_p / n, median(pms), late_long / n, mean(longer));
  }

  // 4. Reschedule after a door event: warm (from the schedule being executed) with small budgets,
  // against from scratch with a 30 ms budget, on the same problems.
  std::printf(
      "\n## 4. Reschedule after a door event, 20 jobs, 1 courier (the room of a stop a third of "
      "the way along the route becomes unreachable)\n\n");
  std::printf(
      "| warm start budget ms | reschedule ms (median) | reschedule ms (max) | completion warm / "
      "from scratch (30 ms) | late warm / from scratch | jobs left out (mean) |\n");
  std::printf("|---:|---:|---:|---:|---:|---:|\n");
  {
    std::vector<SchedulingProblem> problems;
    std::vector<JobSchedule> scratch;
    for (int i = 0; i < instances; ++i) {
      SchedulingProblem p =
          random_office(office(20, 1, seed + 300 + static_cast<std::uint64_t>(i)));
      const JobSchedule before = large->solve(p, budget_ms(20.0));
      if (!before.ok()) continue;
      const auto& stops = before.routes[0].stops;
      int closed = -1;
      for (std::size_t k = stops.size() / 3; k < stops.size() && closed < 0; ++k)
        if (!p.locations[static_cast<std::size_t>(stops[k].location)].room.empty() &&
            stops[k].location != p.couriers[0].location)
          closed = stops[k].location;
      if (closed < 0) continue;
      p.previous_order = before.order();
      p.travel.cut_off(static_cast<std::size_t>(closed));
      SchedulingProblem fresh = p;
      fresh.previous_order.clear();
      scratch.push_back(large->solve(fresh, budget_ms(30.0)));
      problems.push_back(std::move(p));
    }
    for (double warm_budget : {0.5, 1.0, 3.0}) {
      std::vector<double> ms, ratio, left;
      int late_w = 0, late_s = 0;
      for (std::size_t i = 0; i < problems.size(); ++i) {
        const Run warm = timed(*large, problems[i], budget_ms(warm_budget));
        if (!warm.schedule.ok() || !scratch[i].ok()) continue;
        ms.push_back(warm.ms);
        ratio.push_back(warm.schedule.objective.completion_s / scratch[i].objective.completion_s);
        late_w += warm.schedule.objective.late_jobs;
        late_s += scratch[i].objective.late_jobs;
        left.push_back(static_cast<double>(warm.schedule.unschedulable.size()));
      }
      std::printf("| %.1f | %.2f | %.2f | %.3f | %d / %d | %.1f |\n", warm_budget, median(ms),
                  percentile(ms, 1.0), mean(ratio), late_w, late_s, mean(left));
    }
  }

  // 5. Travel times from a map.
  std::printf("\n## 5. Travel-time matrix from a map (one exact cost-to-go field per place)\n\n");
  std::printf(
      "| map cells | places | matrix ms (median of 5) | per field ms |\n|---:|---:|---:|---:|\n");
  for (int side : {200, 800}) {
    const auto raster = autonomy::grid::random_rectangles(side, side / 2, 0.10, 7, 0.05);
    std::vector<MapPosition> places;
    for (int k = 0; places.size() < 17 && k < 10000; ++k) {
      const int col = (k * 37) % side, row = (k * 53) % (side / 2);
      if (!raster.blocked({col, row})) places.push_back({(col + 0.5) * 0.05, (row + 0.5) * 0.05});
    }
    std::vector<double> ms;
    for (int r = 0; r < 5; ++r) {
      const auto t0 = Clock::now();
      const auto t = travel_times_from_map(raster, places, 0.7);
      ms.push_back(ms_since(t0));
      if (!t.ok()) std::printf("error: %s\n", t.error.c_str());
    }
    std::printf("| %d x %d | %zu | %.2f | %.3f |\n", side, side / 2, places.size(), median(ms),
                median(ms) / static_cast<double>(places.size()));
  }
  if (disagreements)
    std::printf("\nexact and the textbook DP disagree on %d instances\n", disagreements);
  return disagreements ? 1 : 0;
}
