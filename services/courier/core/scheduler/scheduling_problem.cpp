#include "services/courier/core/scheduler/scheduling_problem.hpp"

#include <cmath>
#include <set>
#include <string>

namespace autonomy::courier::scheduling {

TravelMatrix::TravelMatrix(std::size_t locations, double fill)
    : n_(locations), s_(locations * locations, fill) {
  for (std::size_t i = 0; i < n_; ++i) s_[i * n_ + i] = 0.0;
}

void TravelMatrix::cut_off(std::size_t location) {
  for (std::size_t i = 0; i < n_; ++i) {
    if (i == location) continue;
    s_[i * n_ + location] = kNoRoute;
    s_[location * n_ + i] = kNoRoute;
  }
}

const char* to_string(StopKind k) {
  return k == StopKind::kPickup ? "pickup" : "delivery";
}

namespace {

std::string at(const std::string& path, std::size_t i) {
  return path + "[" + std::to_string(i) + "]";
}

bool finite_non_negative(double v) {
  return std::isfinite(v) && v >= 0.0;
}

std::string place_error(const SchedulingProblem& p, const Place& place, const std::string& path) {
  if (place.location < 0 || static_cast<std::size_t>(place.location) >= p.locations.size())
    return path + ".location: " + std::to_string(place.location) +
           " is not a location (there are " + std::to_string(p.locations.size()) + ")";
  if (place.person < -1 || place.person >= static_cast<int>(p.people.size()))
    return path + ".person: " + std::to_string(place.person) + " is not a person (there are " +
           std::to_string(p.people.size()) + ")";
  return {};
}

}  // namespace

std::string problem_error(const SchedulingProblem& p) {
  if (!std::isfinite(p.now_s)) return "now_s: not a finite time";
  const std::size_t n = p.locations.size();
  if (p.travel.size() != n)
    return "travel: " + std::to_string(p.travel.size()) + " x " + std::to_string(p.travel.size()) +
           " matrix for " + std::to_string(n) + " locations";
  std::set<std::string> names;
  for (std::size_t i = 0; i < n; ++i) {
    const Location& l = p.locations[i];
    if (l.name.empty()) return at("locations", i) + ".name: empty";
    if (!names.insert(l.name).second) return at("locations", i) + ".name: '" + l.name + "' twice";
    if (!finite_non_negative(l.station_handover_s))
      return at("locations", i) + ".station_handover_s: must be finite and >= 0";
    if (l.x_m.has_value() != l.y_m.has_value() || (l.x_m && !std::isfinite(*l.x_m)) ||
        (l.y_m && !std::isfinite(*l.y_m)))
      return at("locations", i) + ": give both x_m and y_m, finite, or neither";
  }
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = 0; b < n; ++b) {
      const double t = p.travel.at(a, b);
      if (std::isnan(t) || t < 0.0 || (a == b && t != 0.0))
        return "travel[" + std::to_string(a) + "][" + std::to_string(b) +
               "]: " + std::to_string(t) +
               (a == b ? " (the diagonal must be 0)" : " (must be >= 0 or +inf)");
    }
  for (std::size_t i = 0; i < p.people.size(); ++i) {
    const Person& person = p.people[i];
    if (person.name.empty()) return at("people", i) + ".name: empty";
    if (!finite_non_negative(person.handover_s))
      return at("people", i) + ".handover_s: must be finite and >= 0";
    double previous_end = -kNoRoute;
    for (std::size_t w = 0; w < person.presence.size(); ++w) {
      const TimeWindow& tw = person.presence[w];
      const std::string path = at(at("people", i) + ".presence", w);
      if (!std::isfinite(tw.start_s) || !std::isfinite(tw.end_s) || tw.end_s < tw.start_s)
        return path + ": needs finite start <= end";
      if (tw.start_s < previous_end) return path + ": windows must be sorted and disjoint";
      previous_end = tw.end_s;
    }
  }
  if (p.couriers.empty()) return "couriers: none";
  std::set<std::string> courier_ids;
  for (std::size_t c = 0; c < p.couriers.size(); ++c) {
    const Courier& courier = p.couriers[c];
    const std::string path = at("couriers", c);
    if (courier.id.empty()) return path + ".id: empty";
    if (!courier_ids.insert(courier.id).second) return path + ".id: '" + courier.id + "' twice";
    if (courier.capacity < 1 || courier.capacity > 16)
      return path + ".capacity: " + std::to_string(courier.capacity) + " is outside 1..16";
    if (courier.location < 0 || static_cast<std::size_t>(courier.location) >= n)
      return path + ".location: " + std::to_string(courier.location) + " is not a location";
    if (!std::isfinite(courier.available_s)) return path + ".available_s: not a finite time";
  }
  std::set<std::string> job_ids;
  std::vector<int> aboard_count(p.couriers.size(), 0);
  for (std::size_t j = 0; j < p.jobs.size(); ++j) {
    const Job& job = p.jobs[j];
    const std::string path = at("jobs", j);
    if (job.id.empty()) return path + ".id: empty";
    if (!job_ids.insert(job.id).second) return path + ".id: '" + job.id + "' twice";
    if (job.status == JobStatus::kWaitingForPickup) {
      if (auto e = place_error(p, job.pickup, path + ".pickup"); !e.empty()) return e;
    } else {
      if (job.aboard_courier < 0 ||
          static_cast<std::size_t>(job.aboard_courier) >= p.couriers.size())
        return path + ".aboard_courier: " + std::to_string(job.aboard_courier) +
               " is not a courier";
      if (++aboard_count[static_cast<std::size_t>(job.aboard_courier)] >
          p.couriers[static_cast<std::size_t>(job.aboard_courier)].capacity)
        return path + ": more objects aboard courier '" +
               p.couriers[static_cast<std::size_t>(job.aboard_courier)].id + "' than its capacity";
    }
    if (auto e = place_error(p, job.delivery, path + ".delivery"); !e.empty()) return e;
    if (job.deadline_s && !std::isfinite(*job.deadline_s)) return path + ".deadline_s: not finite";
  }
  std::set<std::pair<int, int>> seen_forced;
  for (std::size_t c = 0; c < p.couriers.size(); ++c) {
    const auto& prefix = p.couriers[c].forced_prefix;
    for (std::size_t k = 0; k < prefix.size(); ++k) {
      const std::string path = at(at("couriers", c) + ".forced_prefix", k);
      const StopRef s = prefix[k];
      if (s.job < 0 || static_cast<std::size_t>(s.job) >= p.jobs.size())
        return path + ": job " + std::to_string(s.job) + " is not a job";
      const Job& job = p.jobs[static_cast<std::size_t>(s.job)];
      if (s.kind == StopKind::kPickup && job.status == JobStatus::kAboard)
        return path + ": job '" + job.id + "' is already aboard, it has no pickup";
      if (job.status == JobStatus::kAboard && job.aboard_courier != static_cast<int>(c))
        return path + ": job '" + job.id + "' is aboard another courier";
      if (!seen_forced.insert({s.job, static_cast<int>(s.kind)}).second)
        return path + ": the " + std::string(to_string(s.kind)) + " of job '" + job.id +
               "' is forced twice";
    }
  }
  return {};
}

double earliest_handover_start(const SchedulingProblem& p, int person, double arrival_s,
                               double duration_s) {
  if (person < 0) return arrival_s;
  const auto& windows = p.people[static_cast<std::size_t>(person)].presence;
  if (windows.empty()) return arrival_s;
  for (const TimeWindow& w : windows) {
    const double start = arrival_s > w.start_s ? arrival_s : w.start_s;
    if (start + duration_s <= w.end_s) return start;
  }
  return kNoRoute;
}

double handover_duration(const SchedulingProblem& p, const Place& place) {
  if (place.person >= 0) return p.people[static_cast<std::size_t>(place.person)].handover_s;
  return p.locations[static_cast<std::size_t>(place.location)].station_handover_s;
}

std::string describe_place(const SchedulingProblem& p, const Place& place) {
  const std::string& where = p.locations[static_cast<std::size_t>(place.location)].name;
  if (place.person < 0) return where;
  return p.people[static_cast<std::size_t>(place.person)].name + " at " + where;
}

}  // namespace autonomy::courier::scheduling
