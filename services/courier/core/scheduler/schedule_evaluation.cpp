#include "services/courier/core/scheduler/schedule_evaluation.hpp"

#include "services/courier/core/scheduler/route_simulation.hpp"

#include <string>

namespace autonomy::courier::scheduling {

namespace {

bool reachable(const SchedulingProblem& p, int from, int to) {
  return p.travel.at(static_cast<std::size_t>(from), static_cast<std::size_t>(to)) < kNoRoute;
}

// The person is present again (at or after now) long enough for one handover.
bool present_again(const SchedulingProblem& p, const Place& place) {
  return earliest_handover_start(p, place.person, p.now_s, handover_duration(p, place)) < kNoRoute;
}

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
  std::vector<UnschedulableJob> out;
  for (std::size_t j = 0; j < p.jobs.size(); ++j) {
    const Job& job = p.jobs[j];
    const int ji = static_cast<int>(j);
    const std::string& del_name = p.locations[static_cast<std::size_t>(job.delivery.location)].name;
    if (job.status == JobStatus::kAboard) {
      const Courier& c = p.couriers[static_cast<std::size_t>(job.aboard_courier)];
      if (!reachable(p, c.location, job.delivery.location)) {
        out.push_back({ji, UnschedulableReason::kUnreachable,
                       "delivery " + del_name + " cannot be reached from courier '" + c.id +
                           "' at " + p.locations[static_cast<std::size_t>(c.location)].name});
        continue;
      }
    } else {
      const std::string& pick_name =
          p.locations[static_cast<std::size_t>(job.pickup.location)].name;
      bool any = false;
      for (const Courier& c : p.couriers)
        if (reachable(p, c.location, job.pickup.location) &&
            reachable(p, job.pickup.location, job.delivery.location))
          any = true;
      if (!any) {
        std::string detail;
        bool pickup_reached = false;
        for (const Courier& c : p.couriers)
          pickup_reached = pickup_reached || reachable(p, c.location, job.pickup.location);
        detail = pickup_reached
                     ? "delivery " + del_name + " cannot be reached from pickup " + pick_name
                     : "pickup " + pick_name + " cannot be reached by any courier";
        out.push_back({ji, UnschedulableReason::kUnreachable, detail});
        continue;
      }
      if (!present_again(p, job.pickup)) {
        out.push_back({ji, UnschedulableReason::kNobodyPresent,
                       describe_place(p, job.pickup) + " is not present again for the pickup"});
        continue;
      }
    }
    if (!present_again(p, job.delivery))
      out.push_back({ji, UnschedulableReason::kNobodyPresent,
                     describe_place(p, job.delivery) + " is not present again for the delivery"});
  }
  return out;
}

JobSchedule evaluate_order(const SchedulingProblem& p,
                           const std::vector<std::vector<StopRef>>& order) {
  JobSchedule out;
  out.engine = "evaluate";
  if (std::string e = problem_error(p); !e.empty()) {
    out.status = ScheduleStatus::kInvalidProblem;
    out.reason = std::move(e);
    return out;
  }
  out.unschedulable = find_unschedulable(p);
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
