#include "services/courier/core/scheduler/allocation_rule.hpp"

#include "services/courier/core/scheduler/route_simulation.hpp"

#include <cmath>
#include <cstdio>

namespace autonomy::courier::scheduling {

namespace {

using detail::RouteSimulator;
using detail::RouteState;

struct RouteCost {
  bool feasible = false;
  Objective cost;
  double completion_of_job = 0.0;  // of the job asked about, when it is in the route
};

// One courier's route on its own (the other couriers do not influence it).
RouteCost simulate(const RouteSimulator& sim, int courier, const std::vector<StopRef>& stops,
                   int job_of_interest) {
  RouteCost out;
  RouteState s = sim.start(courier);
  for (const StopRef& stop : stops) {
    if (sim.refusal(s, stop)) return out;
    ScheduledStop done;
    if (!sim.advance(s, stop, &done)) return out;
    if (stop.job == job_of_interest && stop.kind == StopKind::kDelivery)
      out.completion_of_job = done.finish_s;
  }
  out.feasible = true;
  out.cost = s.cost;
  return out;
}

Objective objective_minus(const Objective& a, const Objective& b) {
  return {a.late_jobs - b.late_jobs, a.lateness_s - b.lateness_s, a.completion_s - b.completion_s,
          a.travel_s - b.travel_s, a.interruptions - b.interruptions};
}

// The job's stops inserted into `route` at the best positions for that route's own cost.
std::optional<RouteCost> best_insertion(const RouteSimulator& sim, int courier,
                                        const std::vector<StopRef>& route, int job) {
  std::optional<RouteCost> best;
  int tries = 0;
  const std::size_t n = route.size();
  auto consider = [&](std::size_t p, std::size_t q) {
    std::vector<StopRef> stops;
    stops.reserve(n + 2);
    for (std::size_t i = 0; i <= n; ++i) {
      if (i == p) stops.push_back({job, StopKind::kPickup});
      if (i == q) stops.push_back({job, StopKind::kDelivery});
      if (i < n) stops.push_back(route[i]);
    }
    ++tries;
    const RouteCost c = simulate(sim, courier, stops, job);
    if (c.feasible && (!best || better(c.cost, best->cost))) best = c;
  };
  const std::size_t prefix =
      sim.problem().couriers[static_cast<std::size_t>(courier)].forced_prefix.size();
  for (std::size_t p = prefix; p <= n && tries < kMaxInsertionTries; ++p)
    for (std::size_t q = p; q <= n && tries < kMaxInsertionTries; ++q) consider(p, q);
  if (!best && tries >= kMaxInsertionTries) consider(n, n);
  return best;
}

std::string worse_term(const Objective& d) {
  if (d.late_jobs > 0)
    return std::to_string(d.late_jobs) +
           (d.late_jobs == 1 ? " other job late" : " other jobs late");
  if (d.lateness_s > 1e-6) return duration_text(d.lateness_s) + " more lateness for the others";
  if (d.completion_s > 1e-6)
    return "the others done " + duration_text(d.completion_s) + " later in total";
  if (d.travel_s > 1e-6) return duration_text(d.travel_s) + " more driving";
  return "no gain for the fleet";
}

}  // namespace

std::string duration_text(double seconds) {
  const long s = std::lround(std::max(0.0, seconds));
  char text[32];
  if (s < 90)
    std::snprintf(text, sizeof text, "%ld s", s);
  else if (s < 3600)
    std::snprintf(text, sizeof text, "%ld min", (s + 30) / 60);
  else
    std::snprintf(text, sizeof text, "%ld h %02ld min", s / 3600, (s % 3600 + 30) / 60);
  return text;
}

std::vector<AllocationReason> explain_allocation(const SchedulingProblem& problem,
                                                 const JobSchedule& schedule) {
  std::vector<AllocationReason> out;
  if (problem.couriers.size() < 2 || !schedule.ok()) return out;
  const RouteSimulator sim(problem);
  const auto order = schedule.order();
  std::vector<RouteCost> as_scheduled;
  for (std::size_t c = 0; c < order.size(); ++c)
    as_scheduled.push_back(simulate(sim, static_cast<int>(c), order[c], -1));
  const auto& name = [&](int c) -> const std::string& {
    return problem.couriers[static_cast<std::size_t>(c)].id;
  };

  for (const JobOutcome& o : schedule.outcomes) {
    AllocationReason r;
    r.job = o.job;
    r.courier = o.courier;
    r.completion_s = o.completion_s;
    const Job& job = problem.jobs[static_cast<std::size_t>(o.job)];
    const std::size_t mine = static_cast<std::size_t>(o.courier);
    if (job.status == JobStatus::kAboard || mine >= order.size() || !as_scheduled[mine].feasible) {
      r.text = "aboard " + name(o.courier);
      out.push_back(std::move(r));
      continue;
    }
    // Its courier's route without it.
    std::vector<StopRef> without;
    for (const StopRef& s : order[mine])
      if (s.job != o.job) without.push_back(s);
    const RouteCost mine_without = simulate(sim, o.courier, without, -1);
    std::optional<Objective> best_difference;
    for (std::size_t c = 0; c < order.size(); ++c) {
      if (c == mine || !as_scheduled[c].feasible || !mine_without.feasible) continue;
      const auto inserted = best_insertion(sim, static_cast<int>(c), order[c], o.job);
      if (!inserted) continue;
      // The fleet's objective with the move, minus the schedule's: only the two routes change.
      const Objective d =
          objective_minus(mine_without.cost + inserted->cost, as_scheduled[mine].cost + as_scheduled[c].cost);
      if (!best_difference || better(d, *best_difference)) {
        best_difference = d;
        r.alternative = static_cast<int>(c);
        r.alternative_completion_s = inserted->completion_of_job;
        r.fleet_difference = d;
      }
    }
    if (r.alternative < 0) {
      r.text = "assigned to " + name(o.courier) + ": the only courier that can do it";
    } else if (better(r.fleet_difference, Objective{})) {
      // The engine's schedule is not the best (an anytime engine out of budget): say so.
      r.text =
          "assigned to " + name(o.courier) + ": " + name(r.alternative) +
          " would serve the fleet better; the engine found no better schedule within its budget";
    } else if (*r.alternative_completion_s > o.completion_s + 0.5) {
      r.text = "assigned to " + name(o.courier) + ": " +
               duration_text(*r.alternative_completion_s - o.completion_s) + " earlier than " +
               name(r.alternative);
    } else {
      // As quick or quicker for this job elsewhere: the rest of the fleet pays for it. The job's
      // own share of the difference is taken out of the completion term.
      Objective others = r.fleet_difference;
      others.completion_s -= *r.alternative_completion_s - o.completion_s;
      const double gain = o.completion_s - *r.alternative_completion_s;
      r.text =
          "assigned to " + name(o.courier) + ": " + name(r.alternative) +
          (gain > 0.5 ? " would be " + duration_text(gain) + " earlier" : " would be as quick") +
          " but " + worse_term(others);
    }
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace autonomy::courier::scheduling
