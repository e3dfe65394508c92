// A courier fleet on the office floor (deploy/scenarios/office.pbtxt): 4 robots, 200 delivery jobs
// with deadlines known at 09:00 (a morning's mail; two loads: due in 15-120 min and in 30-240 min),
// travel times from the map through the courier's own bridge (EngineScheduleSource: cost-to-go
// fields over the behavior's grid), presence windows and handover times from the office knowledge.
// Measured in the same run on the same problems, every schedule scored by the one referee
// (evaluate_order):
//   ours    - the courier's allocation: the engine the service picks for this size (large-scale,
//             anytime, --budget-ms of wall clock), all couriers at once, deadlines in the
//             objective;
//   greedy  - a deadline-blind dispatcher in the manner of Open-RMF's task allocation: jobs first
//             come first served, each to the nearest idle robot, one job at a time (pickup, then
//             delivery);
//   paper   - FAXBOT's SCHEDULE-DELIVERIES spread over the fleet (the paper engine), for reference.
// Figures per allocation: on-time rate, mean lateness over all jobs and over the late ones, max
// lateness, when the last job is done, driving time, solve time (wall and CPU); then ours / greedy
// ratios. No doors are closed here: the door policy is the executive's (see the integration tests).
//
//   courier_fleet_bench [--instances 5] [--jobs 200] [--robots 4] [--seed 1] [--budget-ms 2000]
//
// Nothing passes or fails; exit 1 only if a schedule breaks the model (evaluate_order refuses it).
#include "services/courier/core/bridge/engine_schedule_source.hpp"
#include "services/courier/core/scheduler/schedule_evaluation.hpp"
#include "services/courier/core/scheduler/scheduler_engine.hpp"
#include "services/courier/core/scheduler/wall_clock_budget.hpp"
#include "services/courier/dds/office_file.hpp"

#include <CLI/CLI.hpp>

#include <time.h>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace {

using namespace autonomy::courier;
namespace sched = autonomy::courier::scheduling;

struct Figures {
  double on_time_rate = 0.0;
  double mean_lateness_s = 0.0;       // over all jobs
  double mean_late_lateness_s = 0.0;  // over the late jobs
  double max_lateness_s = 0.0;
  double last_done_s = 0.0;  // after now
  double travel_s = 0.0;
  double solve_ms = 0.0;
  double solve_cpu_ms = 0.0;  // this thread's CPU time: on a shared machine the steadier figure
};

// Integer draws only: the same jobs on every platform.
std::uint64_t draw(std::mt19937_64& rng, std::uint64_t n) {
  return rng() % n;
}

PlanRequest morning_mail(const CourierOffice& office, int jobs, int robots, std::uint64_t seed,
                         double now_s, int due_min, int due_max) {
  std::mt19937_64 rng(seed);
  PlanRequest request;
  request.now_s = now_s;
  std::vector<std::string> places;
  for (const auto& [name, place] : office.floor.places) places.push_back(name);
  // Robots spread along the hallway (y = 8), west to east.
  for (int r = 0; r < robots; ++r)
    request.robots.push_back(
        {"rhino" + std::to_string(r + 1), 1.5 + 37.0 * r / std::max(1, robots - 1), 8.0, 3});
  const char* kinds[] = {"letter", "parcel", "book"};
  const char* colours[] = {"red", "green", "blue", "yellow"};
  for (int j = 0; j < jobs; ++j) {
    PlanJob job;
    job.id = "job-" + std::to_string(j + 1);
    job.lookalike_class = std::string(kinds[draw(rng, 3)]) + "/" + colours[draw(rng, 4)];
    job.pickup = places[draw(rng, places.size())];
    do job.destination = places[draw(rng, places.size())];
    while (job.destination == job.pickup);
    // Due between due_min and due_max minutes from now, whole minutes.
    job.deadline_s =
        now_s + 60.0 * static_cast<double>(
                           due_min + static_cast<int>(draw(
                                         rng, static_cast<std::uint64_t>(due_max - due_min + 1))));
    request.jobs.push_back(std::move(job));
  }
  return request;
}

// Open-RMF-style dispatch: jobs in arrival order; each goes to the robot that is idle first (all
// are idle at the start), among those idle at that moment the nearest to the pickup; that robot
// drives to the pickup, loads, drives to the destination, unloads, and is idle again.
std::vector<std::vector<sched::StopRef>> greedy_dispatch(const sched::SchedulingProblem& p) {
  const std::size_t robots = p.couriers.size();
  std::vector<double> free_at(robots, p.now_s);
  std::vector<int> at(robots);
  for (std::size_t r = 0; r < robots; ++r) at[r] = p.couriers[r].location;
  std::vector<std::vector<sched::StopRef>> order(robots);
  const auto handover = [&](const sched::Place& place, double arrival) {
    const double d = sched::handover_duration(p, place);
    return sched::earliest_handover_start(p, place.person, arrival, d) + d;
  };
  for (std::size_t j = 0; j < p.jobs.size(); ++j) {
    const sched::Job& job = p.jobs[j];
    const double first_free = *std::min_element(free_at.begin(), free_at.end());
    std::size_t best = robots;
    for (std::size_t r = 0; r < robots; ++r) {
      if (free_at[r] > first_free) continue;  // busy when the job's turn comes
      const double t = p.travel.at(static_cast<std::size_t>(at[r]),
                                   static_cast<std::size_t>(job.pickup.location));
      if (best == robots || t < p.travel.at(static_cast<std::size_t>(at[best]),
                                            static_cast<std::size_t>(job.pickup.location)))
        best = r;
    }
    double t = free_at[best] + p.travel.at(static_cast<std::size_t>(at[best]),
                                           static_cast<std::size_t>(job.pickup.location));
    t = handover(job.pickup, t);
    t += p.travel.at(static_cast<std::size_t>(job.pickup.location),
                     static_cast<std::size_t>(job.delivery.location));
    t = handover(job.delivery, t);
    free_at[best] = t;
    at[best] = job.delivery.location;
    order[best].push_back({static_cast<int>(j), sched::StopKind::kPickup});
    order[best].push_back({static_cast<int>(j), sched::StopKind::kDelivery});
  }
  return order;
}

bool score(const sched::SchedulingProblem& p, const sched::JobSchedule& s, const char* who,
           Figures& f) {
  if (!s.ok()) {
    std::fprintf(stderr, "%s: %s (%s)\n", who, sched::to_string(s.status), s.reason.c_str());
    return false;
  }
  // Re-scored by the referee, so every allocation is measured by the same rules.
  const sched::JobSchedule checked = sched::evaluate_order(p, s.order());
  if (!checked.ok()) {
    std::fprintf(stderr, "%s: the referee refuses the schedule: %s\n", who, checked.reason.c_str());
    return false;
  }
  const double n = static_cast<double>(p.jobs.size());
  int late = 0;
  double lateness = 0.0;
  for (const auto& o : checked.outcomes) {
    late += o.late;
    lateness += o.lateness_s;
    f.max_lateness_s = std::max(f.max_lateness_s, o.lateness_s);
    f.last_done_s = std::max(f.last_done_s, o.completion_s - p.now_s);
  }
  // A job left out of the schedule would count as late here; the office has none.
  late += static_cast<int>(p.jobs.size() - checked.outcomes.size());
  f.on_time_rate = (n - late) / n;
  f.mean_lateness_s = lateness / n;
  f.mean_late_lateness_s = late ? lateness / late : 0.0;
  f.travel_s = checked.objective.travel_s;
  return true;
}

Figures mean_of(const std::vector<Figures>& v) {
  Figures m;
  for (const Figures& f : v) {
    m.on_time_rate += f.on_time_rate / v.size();
    m.mean_lateness_s += f.mean_lateness_s / v.size();
    m.mean_late_lateness_s += f.mean_late_lateness_s / v.size();
    m.max_lateness_s += f.max_lateness_s / v.size();
    m.last_done_s += f.last_done_s / v.size();
    m.travel_s += f.travel_s / v.size();
    m.solve_ms += f.solve_ms / v.size();
    m.solve_cpu_ms += f.solve_cpu_ms / v.size();
  }
  return m;
}

void print_row(const char* name, const Figures& f) {
  std::printf("  %-8s %7.1f %%  %9.1f  %9.1f  %9.1f  %9.1f  %8.1f  %9.1f  %9.1f\n", name,
              100.0 * f.on_time_rate, f.mean_lateness_s / 60.0, f.mean_late_lateness_s / 60.0,
              f.max_lateness_s / 60.0, f.last_done_s / 60.0, f.travel_s / 60.0, f.solve_ms,
              f.solve_cpu_ms);
}

double thread_cpu_ms() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) * 1e3 + static_cast<double>(ts.tv_nsec) * 1e-6;
}

double ratio(double a, double b) {
  return b > 0.0 ? a / b : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "Courier fleet allocation against a deadline-blind greedy dispatcher on the office floor"};
  int instances = 5, jobs = 200, robots = 4;
  std::uint64_t seed = 1;
  double budget_ms = 2000.0;
  std::string scenario = std::string(AUTONOMY_SOURCE_DIR) + "/deploy/scenarios/office.pbtxt";
  app.add_option("--instances", instances, "Seeded job sets")
      ->check(CLI::Range(1, 100))
      ->capture_default_str();
  app.add_option("--jobs", jobs, "Jobs per set")->check(CLI::Range(1, 1000))->capture_default_str();
  app.add_option("--robots", robots, "Courier robots")
      ->check(CLI::Range(1, 16))
      ->capture_default_str();
  app.add_option("--seed", seed, "First seed")->capture_default_str();
  app.add_option("--budget-ms", budget_ms, "Wall-clock budget of our schedule")
      ->check(CLI::Range(1.0, 600000.0))
      ->capture_default_str();
  app.add_option("--scenario", scenario, "The office")->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  auto loaded = load_courier_office(scenario);
  if (!loaded.ok()) {
    std::fprintf(stderr, "%s\n", loaded.error.c_str());
    return 1;
  }
  const CourierOffice office = std::move(*loaded.office);
  EngineSourceSettings settings;
  settings.speed_mps = 0.8 * office.attach_defaults.max_speed_mps;
  settings.robot_radius_m = office.attach_defaults.radius_m;
  settings.budget_ms = budget_ms;
  EngineScheduleSource source(office.knowledge, office.floor, office.map, settings);

  std::printf(
      "courier fleet: %d robots (capacity 3), %d jobs with deadlines known at 09:00, %d sets, "
      "office floor %s, "
      "our budget %.0f ms of wall clock\n",
      robots, jobs, instances, scenario.c_str(), budget_ms);
  bool ok = true;
  // The load: deadlines 15-120 min ahead (more work than 4 robots can do on time one job at a
  // time) and 30-240 min ahead (about what they can).
  for (const auto& [due_min, due_max] : {std::pair{15, 120}, std::pair{30, 240}}) {
    std::printf("\ndeadlines %d-%d min after 09:00\n", due_min, due_max);
    std::vector<Figures> ours, greedy, paper;
    std::string our_engine;
    for (int i = 0; i < instances; ++i) {
      const PlanRequest request = morning_mail(
          office, jobs, robots, seed + static_cast<std::uint64_t>(i), 9 * 3600.0, due_min, due_max);
      const sched::SchedulingProblem problem = source.problem_for(request);
      our_engine = source.engine_for(problem);
      Figures o, g, pp;
      {
        auto engine = sched::make_scheduler_engine(our_engine);
        const auto t0 = std::chrono::steady_clock::now();
        const double c0 = thread_cpu_ms();
        const sched::JobSchedule s = engine->solve(
            problem, sched::wall_clock_budget(
                         std::chrono::microseconds(static_cast<long long>(budget_ms * 1000.0)),
                         seed + static_cast<std::uint64_t>(i)));
        o.solve_cpu_ms = thread_cpu_ms() - c0;
        o.solve_ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                .count();
        ok &= score(problem, s, "ours", o);
      }
      {
        const auto t0 = std::chrono::steady_clock::now();
        const double c0 = thread_cpu_ms();
        const auto order = greedy_dispatch(problem);
        g.solve_cpu_ms = thread_cpu_ms() - c0;
        g.solve_ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                .count();
        ok &= score(problem, sched::evaluate_order(problem, order), "greedy", g);
      }
      {
        auto engine = sched::make_scheduler_engine("paper");
        const auto t0 = std::chrono::steady_clock::now();
        const double c0 = thread_cpu_ms();
        const sched::JobSchedule s = engine->solve(problem, {});
        pp.solve_cpu_ms = thread_cpu_ms() - c0;
        pp.solve_ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                .count();
        ok &= score(problem, s, "paper", pp);
      }
      std::printf("  set %d: on time ours %.1f %%, greedy %.1f %%, paper %.1f %%\n", i + 1,
                  100.0 * o.on_time_rate, 100.0 * g.on_time_rate, 100.0 * pp.on_time_rate);
      ours.push_back(o);
      greedy.push_back(g);
      paper.push_back(pp);
    }
    const Figures mo = mean_of(ours), mg = mean_of(greedy), mp = mean_of(paper);
    std::printf(
        "means over %d sets (ours = the %s engine; lateness, done and driving in minutes)\n",
        instances, our_engine.c_str());
    std::printf("  %-8s %9s  %9s  %9s  %9s  %9s  %8s  %9s  %9s\n", "", "on time", "lateness",
                "late-mean", "max-late", "last-done", "driving", "solve-ms", "solve-cpu");
    print_row("ours", mo);
    print_row("greedy", mg);
    print_row("paper", mp);
    std::printf(
        "ours / greedy: on-time rate x%.2f, mean lateness x%.3f, max lateness x%.3f, last done "
        "x%.2f, "
        "driving x%.2f\n",
        ratio(mo.on_time_rate, mg.on_time_rate), ratio(mo.mean_lateness_s, mg.mean_lateness_s),
        ratio(mo.max_lateness_s, mg.max_lateness_s), ratio(mo.last_done_s, mg.last_done_s),
        ratio(mo.travel_s, mg.travel_s));
    std::printf("ours / paper:  on-time rate x%.2f, mean lateness x%.3f\n",
                ratio(mo.on_time_rate, mp.on_time_rate),
                ratio(mo.mean_lateness_s, mp.mean_lateness_s));
  }
  return ok ? 0 : 1;
}
