#include "services/courier/core/scheduler/route_simulation.hpp"

#include <algorithm>
#include <map>

namespace autonomy::courier::scheduling::detail {

bool RouteState::carries(int job) const {
  for (int i = 0; i < load; ++i)
    if (aboard[static_cast<std::size_t>(i)] == job) return true;
  return false;
}

void RouteState::drop(int job) {
  for (int i = 0; i < load; ++i)
    if (aboard[static_cast<std::size_t>(i)] == job) {
      aboard[static_cast<std::size_t>(i)] = aboard[static_cast<std::size_t>(load - 1)];
      --load;
      return;
    }
}

RouteSimulator::RouteSimulator(const SchedulingProblem& problem) : p_(&problem) {
  std::map<std::pair<std::string, std::string>, int> classes;
  jobs_.resize(problem.jobs.size());
  min_del_dur_ = kNoRoute;
  for (std::size_t j = 0; j < problem.jobs.size(); ++j) {
    const Job& job = problem.jobs[j];
    JobData& d = jobs_[j];
    d.aboard = job.status == JobStatus::kAboard;
    d.fixed_courier = d.aboard ? job.aboard_courier : -1;
    if (!d.aboard) {
      d.pick_loc = job.pickup.location;
      d.pick_person = job.pickup.person;
      d.pick_dur = handover_duration(problem, job.pickup);
    }
    d.del_loc = job.delivery.location;
    d.del_person = job.delivery.person;
    d.del_dur = handover_duration(problem, job.delivery);
    min_del_dur_ = std::min(min_del_dur_, d.del_dur);
    d.deadline = job.deadline_s ? *job.deadline_s : kNoRoute;
    auto windows = [&](int person) -> const std::vector<TimeWindow>* {
      if (person < 0) return nullptr;
      const auto& w = problem.people[static_cast<std::size_t>(person)].presence;
      return w.empty() ? nullptr : &w;
    };
    if (!d.aboard) d.pick_windows = windows(d.pick_person);
    d.del_windows = windows(d.del_person);
    d.cls = classes
                .emplace(std::make_pair(job.object.kind, job.object.colour),
                         static_cast<int>(classes.size()))
                .first->second;
  }
  if (jobs_.empty()) min_del_dur_ = 0.0;
}

RouteState RouteSimulator::start(int courier) const {
  const Courier& c = p_->couriers[static_cast<std::size_t>(courier)];
  RouteState s;
  s.t = std::max(p_->now_s, c.available_s);
  s.loc = c.location;
  for (std::size_t j = 0; j < jobs_.size(); ++j)
    if (jobs_[j].fixed_courier == courier && s.load < kMaxCapacity)
      s.aboard[static_cast<std::size_t>(s.load++)] = static_cast<int>(j);
  return s;
}

bool RouteSimulator::may_pick_up(const RouteState& s, int job) const {
  const int cls = jobs_[static_cast<std::size_t>(job)].cls;
  for (int i = 0; i < s.load; ++i)
    if (jobs_[static_cast<std::size_t>(s.aboard[static_cast<std::size_t>(i)])].cls == cls)
      return false;
  return true;
}

const char* RouteSimulator::refusal(const RouteState& s, StopRef stop) const {
  const JobData& d = job(stop.job);
  if (stop.kind == StopKind::kDelivery)
    return s.carries(stop.job) ? nullptr : "delivery of an object that is not aboard";
  if (d.aboard) return "pickup of an object that is already aboard";
  if (s.carries(stop.job)) return "second pickup of the same object";
  if (!may_pick_up(s, stop.job)) return "pickup while a look-alike object is aboard";
  return nullptr;
}

bool RouteSimulator::timed_step(double& t, int& at, bool& visited, Objective& cost, StopRef stop,
                                ScheduledStop* out) const {
  const JobData& d = job(stop.job);
  const bool pickup = stop.kind == StopKind::kPickup;
  const int loc = pickup ? d.pick_loc : d.del_loc;
  const int person = pickup ? d.pick_person : d.del_person;
  const double dur = pickup ? d.pick_dur : d.del_dur;
  const auto* windows = pickup ? d.pick_windows : d.del_windows;
  const bool same_visit = visited && loc == at;
  const double tt = travel(at, loc);
  if (!(tt < kNoRoute)) return false;
  const double arrival = t + tt;
  const double begin = start_within(windows, arrival, dur);
  if (!(begin < kNoRoute)) return false;
  const double finish = begin + dur;
  cost.travel_s += tt;
  if (!same_visit) ++cost.interruptions;
  if (!pickup) {
    cost.completion_s += finish - p_->now_s;
    if (finish > d.deadline + 1e-9) {
      ++cost.late_jobs;
      cost.lateness_s += finish - d.deadline;
    }
  }
  t = finish;
  at = loc;
  visited = true;
  if (out) *out = {stop.job, stop.kind, loc, person, arrival, begin, finish, same_visit};
  return true;
}

bool RouteSimulator::advance(RouteState& s, StopRef stop, ScheduledStop* out) const {
  if (!timed_step(s.t, s.loc, s.visited, s.cost, stop, out)) return false;
  if (stop.kind == StopKind::kPickup)
    s.aboard[static_cast<std::size_t>(s.load++)] = stop.job;
  else
    s.drop(stop.job);
  return true;
}

double RouteSimulator::earliest_completion(const RouteState& s, int j) const {
  const JobData& d = job(j);
  double t = s.t;
  int loc = s.loc;
  if (!s.carries(j)) {
    t += travel(loc, d.pick_loc);
    t = start_within(d.pick_windows, t, d.pick_dur) + d.pick_dur;
    loc = d.pick_loc;
  }
  t += travel(loc, d.del_loc);
  return start_within(d.del_windows, t, d.del_dur) + d.del_dur;
}

void collect_assumptions(const SchedulingProblem& problem, const CourierRoute& route,
                         std::vector<RoomAssumption>& out) {
  std::string current_room;
  for (std::size_t i = 0; i < route.stops.size(); ++i) {
    const ScheduledStop& st = route.stops[i];
    const std::string& room = problem.locations[static_cast<std::size_t>(st.location)].room;
    if (room.empty()) {
      current_room.clear();
      continue;
    }
    if (room == current_room) continue;  // still inside: consecutive stops in one room
    current_room = room;
    out.push_back({route.courier, room, st.location, st.arrival_s, static_cast<int>(i)});
  }
}

}  // namespace autonomy::courier::scheduling::detail
