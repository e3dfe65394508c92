#include "services/courier/core/scheduler/schedule_evaluation.hpp"

#include "services/courier/core/scheduler/job_selection.hpp"
#include "services/courier/core/scheduler/route_simulation.hpp"

#include <string>
#include <utility>

namespace autonomy::courier::scheduling {

namespace {

std::string stop_label(const SchedulingProblem& p, std::size_t courier, std::size_t index,
                       StopRef stop) {
  std::string job = stop.job >= 0 && static_cast<std::size_t>(stop.job) < p.jobs.size()
                        ? "'" + p.jobs[static_cast<std::size_t>(stop.job)].id + "'"
                        : std::to_string(stop.job);
  return "courier '" + p.couriers[courier].id + "' stop " + std::to_string(index) + " (" +
         to_string(stop.kind) + " of job " + job + ")";
}

}  // namespace

std::vector<UnschedulableJob> find_unschedulable(const SchedulingProblem& p) {
  return detail::select_jobs(p).unschedulable;
}

JobSchedule evaluate_order(const SchedulingProblem& p,
                           const std::vector<std::vector<StopRef>>& order) {
  if (!problem_error(p).empty()) return evaluate_order(p, order, {});
  return evaluate_order(p, order, find_unschedulable(p));
}

JobSchedule evaluate_order(const SchedulingProblem& p,
                           const std::vector<std::vector<StopRef>>& order,
                           std::vector<UnschedulableJob> unschedulable) {
  JobSchedule out;
  out.engine = "evaluate";
  if (std::string e = problem_error(p); !e.empty()) {
    out.status = ScheduleStatus::kInvalidProblem;
    out.reason = std::move(e);
    return out;
  }
  out.unschedulable = std::move(unschedulable);
  out.status = ScheduleStatus::kInfeasible;
  if (order.size() != p.couriers.size()) {
    out.reason = "the order has " + std::to_string(order.size()) + " routes for " +
                 std::to_string(p.couriers.size()) + " couriers";
    return out;
  }
  std::vector<char> left_out(p.jobs.size(), 0);
  for (const auto& u : out.unschedulable) left_out[static_cast<std::size_t>(u.job)] = 1;
  // Per job: pickup and delivery seen.
  std::vector<char> picked(p.jobs.size(), 0), delivered(p.jobs.size(), 0);
  const detail::RouteSimulator sim(p);
  std::vector<double> completion(p.jobs.size(), 0.0);
  std::vector<int> courier_of(p.jobs.size(), -1);
  for (std::size_t c = 0; c < order.size(); ++c) {
    const auto& route = order[c];
    const auto& prefix = p.couriers[c].forced_prefix;
    if (route.size() < prefix.size()) {
      out.reason =
          "courier '" + p.couriers[c].id + "': the route is shorter than its forced prefix";
      return out;
    }
    for (std::size_t k = 0; k < prefix.size(); ++k)
      if (!(route[k] == prefix[k])) {
        out.reason = stop_label(p, c, k, route[k]) + ": the forced prefix says " +
                     to_string(prefix[k].kind) + " of job '" +
                     p.jobs[static_cast<std::size_t>(prefix[k].job)].id + "'";
        return out;
      }
    detail::RouteState s = sim.start(static_cast<int>(c));
    CourierRoute cr;
    cr.courier = static_cast<int>(c);
    for (std::size_t k = 0; k < route.size(); ++k) {
      const StopRef stop = route[k];
      if (stop.job < 0 || static_cast<std::size_t>(stop.job) >= p.jobs.size()) {
        out.reason = stop_label(p, c, k, stop) + ": no such job";
        return out;
      }
      const auto j = static_cast<std::size_t>(stop.job);
      if (left_out[j]) {
        out.reason = stop_label(p, c, k, stop) + ": the job is unschedulable";
        return out;
      }
      auto& seen = stop.kind == StopKind::kPickup ? picked[j] : delivered[j];
      if (seen) {
        out.reason = stop_label(p, c, k, stop) + ": appears twice";
        return out;
      }
      seen = 1;
      if (const char* why = sim.refusal(s, stop)) {
        out.reason = stop_label(p, c, k, stop) + ": " + why;
        return out;
      }
      if (stop.kind == StopKind::kPickup && s.load >= p.couriers[c].capacity) {
        out.reason = stop_label(p, c, k, stop) + ": capacity " +
                     std::to_string(p.couriers[c].capacity) + " exceeded";
        return out;
      }
      ScheduledStop done;
      if (!sim.advance(s, stop, &done)) {
        const Place& place = stop.kind == StopKind::kPickup ? p.jobs[j].pickup : p.jobs[j].delivery;
        const bool no_route = !(sim.travel(s.loc, place.location) < kNoRoute);
        out.reason = stop_label(p, c, k, stop) +
                     (no_route ? ": no route to " : ": no presence window fits at ") +
                     describe_place(p, place);
        return out;
      }
      if (stop.kind == StopKind::kDelivery) {
        completion[j] = done.finish_s;
        courier_of[j] = static_cast<int>(c);
      }
      cr.stops.push_back(done);
    }
    for (int i = 0; i < s.load; ++i) {
      const auto j = static_cast<std::size_t>(s.aboard[static_cast<std::size_t>(i)]);
      if (left_out[j]) continue;  // cannot be delivered: stays aboard
      out.reason = "courier '" + p.couriers[c].id + "': the route ends with job '" + p.jobs[j].id +
                   "' still aboard";
      return out;
    }
    out.objective += s.cost;
    out.routes.push_back(std::move(cr));
  }
  for (std::size_t j = 0; j < p.jobs.size(); ++j) {
    if (left_out[j]) continue;
    if (!delivered[j]) {
      out.reason = "job '" + p.jobs[j].id + "' is not delivered by any courier";
      return out;
    }
    JobOutcome o;
    o.job = static_cast<int>(j);
    o.courier = courier_of[j];
    o.completion_s = completion[j];
    const double deadline = sim.job(static_cast<int>(j)).deadline;
    o.late = completion[j] > deadline + 1e-9;
    o.lateness_s = o.late ? completion[j] - deadline : 0.0;
    out.outcomes.push_back(o);
  }
  for (const CourierRoute& r : out.routes) detail::collect_assumptions(p, r, out.assumptions);
  out.status = ScheduleStatus::kOk;
  out.reason.clear();
  return out;
}

}  // namespace autonomy::courier::scheduling
