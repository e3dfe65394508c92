#include "services/courier/core/bridge/engine_schedule_source.hpp"

#include "services/behavior/core/door_knowledge.hpp"
#include "services/courier/core/bridge/learned_problem.hpp"
#include "services/courier/core/scheduler/allocation_rule.hpp"
#include "services/courier/core/scheduler/scheduler_engine.hpp"
#include "services/courier/core/scheduler/wall_clock_budget.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace autonomy::courier {

namespace sched = scheduling;

struct EngineScheduleSource::Fields {
  std::vector<behavior::CostToGoField> to_place;  // in place_names_ order
};

EngineScheduleSource::EngineScheduleSource(const OfficeKnowledge& knowledge, const Floor& floor,
                                           const behavior::WorldMap& map, EngineSourceSettings settings)
    : knowledge_(knowledge), floor_(floor), map_(map), settings_(std::move(settings)) {
  if (!(settings_.speed_mps > 0.0)) throw std::invalid_argument("travel speed must be positive");
  for (const auto& [name, place] : floor_.places) place_names_.push_back(name);
  const Fields& open = fields_for({});
  for (size_t i = 0; i < place_names_.size(); ++i)
    if (!open.to_place[i].has_route_anywhere())
      throw std::invalid_argument("place " + place_names_[i] + " lies in an obstacle (grown by the robot radius)");
}

EngineScheduleSource::~EngineScheduleSource() = default;

const EngineScheduleSource::Fields& EngineScheduleSource::fields_for(const std::set<std::string>& closed_doors) {
  auto& slot = cache_[closed_doors];
  if (slot) return *slot;
  // Doors believed closed become walls across their doorways, as the behavior plans them.
  behavior::DoorKnowledge doors;
  std::vector<behavior::DoorSighting> closed;
  for (const auto& id : closed_doors) closed.push_back({id, 0.0});
  (void)doors.update(closed, 0.0, map_);
  const behavior::OccupancyGrid grid(doors.apply(map_), settings_.resolution_m, settings_.robot_radius_m);
  auto fields = std::make_unique<Fields>();
  for (const auto& name : place_names_) {
    const FloorPlace& p = floor_.places.at(name);
    fields->to_place.emplace_back(grid, geometry::Vec2(p.x, p.y));
  }
  slot = std::move(fields);
  return *slot;
}

double EngineScheduleSource::travel_s(const std::string& from, const std::string& to,
                                      const std::set<std::string>& closed_doors) {
  const auto a = std::find(place_names_.begin(), place_names_.end(), from);
  const auto b = std::find(place_names_.begin(), place_names_.end(), to);
  if (a == place_names_.end() || b == place_names_.end()) return std::numeric_limits<double>::infinity();
  const FloorPlace& p = floor_.places.at(from);
  const Fields& f = fields_for(closed_doors);
  return f.to_place[static_cast<size_t>(b - place_names_.begin())].cost_at(geometry::Vec2(p.x, p.y)) /
         settings_.speed_mps;
}

namespace {

// Metres from `position` along the field, from the nearest reachable cell when the robot's centre
// lies in the inflation margin (it may stop close to a desk).
double cost_from(const behavior::CostToGoField& field, double x, double y) {
  const geometry::Vec2 p(x, y);
  const double direct = field.cost_at(p);
  if (std::isfinite(direct)) return direct;
  if (const auto cell = field.nearest_reachable(p, 1.0)) return field.cost(*cell);
  return std::numeric_limits<double>::infinity();
}

}  // namespace

sched::SchedulingProblem EngineScheduleSource::problem_for(const PlanRequest& request) {
  const Fields& fields = fields_for(request.closed_doors);
  const size_t places = place_names_.size();
  sched::SchedulingProblem problem;
  problem.now_s = request.now_s;

  for (const auto& name : place_names_) {
    const FloorPlace& p = floor_.places.at(name);
    sched::Location loc{name, p.room, p.x, p.y, 0.0};
    if (const LoadingStation* station = knowledge_.station_at(name)) loc.station_handover_s = station->handover_s;
    problem.locations.push_back(std::move(loc));
  }
  for (const auto& r : request.robots) problem.locations.push_back({"@" + r.id, "", r.x, r.y, 0.0});
  // Objects kept aboard (PlanJob::keep_aboard) are "delivered" to a place no route leads to: the
  // engines leave the delivery out as unreachable and count the object aboard.
  const bool keeps = std::any_of(request.jobs.begin(), request.jobs.end(),
                                 [](const PlanJob& j) { return j.keep_aboard && !j.aboard.empty(); });
  const int kept_aboard = keeps ? static_cast<int>(problem.locations.size()) : -1;
  if (keeps) problem.locations.push_back({"@kept aboard", "", std::nullopt, std::nullopt, 0.0});
  const size_t n = problem.locations.size();
  problem.travel = sched::TravelMatrix(n);
  for (size_t to = 0; to < places; ++to) {
    const auto& field = fields.to_place[to];
    for (size_t from = 0; from < n; ++from) {
      if (from == to) {
        problem.travel.set(from, to, 0.0);
        continue;
      }
      if (static_cast<int>(from) == kept_aboard) continue;  // no route
      const auto& loc = problem.locations[from];
      problem.travel.set(from, to, cost_from(field, *loc.x_m, *loc.y_m) / settings_.speed_mps);
    }
  }
  for (size_t from = places; from < n; ++from) problem.travel.set(from, from, 0.0);

  for (const Person& person : knowledge_.people) {
    sched::Person out{person.name, person.handover_s, {}};
    for (const auto& w : person.presence) out.presence.push_back({w.start_s, w.end_s});
    problem.people.push_back(std::move(out));
  }
  const auto place_of = [&](const std::string& name) {
    sched::Place place;
    const auto it = std::find(place_names_.begin(), place_names_.end(), name);
    place.location = it == place_names_.end() ? -1 : static_cast<int>(it - place_names_.begin());
    if (knowledge_.station_at(name)) return place;  // no person needed
    if (const Person* person = knowledge_.person_at(name))
      place.person = static_cast<int>(person - knowledge_.people.data());
    return place;
  };

  std::map<std::string, int> courier_index;
  for (size_t i = 0; i < request.robots.size(); ++i) {
    const auto& r = request.robots[i];
    courier_index[r.id] = static_cast<int>(i);
    sched::Courier c;
    c.id = r.id;
    c.capacity = r.capacity;
    c.location = static_cast<int>(places + i);
    c.available_s = std::max(request.now_s, r.available_s);
    problem.couriers.push_back(std::move(c));
  }
  for (const PlanJob& j : request.jobs) {
    sched::Job job;
    job.id = j.id;
    const auto slash = j.lookalike_class.find('/');
    job.object = {j.lookalike_class.substr(0, slash),
                  slash == std::string::npos ? "" : j.lookalike_class.substr(slash + 1)};
    job.pickup = place_of(j.pickup);
    job.delivery = place_of(j.destination);
    if (j.keep_aboard && !j.aboard.empty()) job.delivery = sched::Place{kept_aboard, -1};
    job.deadline_s = j.deadline_s;
    if (!j.aboard.empty() && courier_index.count(j.aboard)) {
      job.status = sched::JobStatus::kAboard;
      job.aboard_courier = courier_index[j.aboard];
    }
    problem.jobs.push_back(std::move(job));
  }
  for (const auto& id : request.first) {
    for (size_t i = 0; i < problem.jobs.size(); ++i) {
      const sched::Job& job = problem.jobs[i];
      if (job.id != id) continue;
      int courier = 0;
      if (job.status == sched::JobStatus::kAboard) {
        courier = job.aboard_courier;
      } else if (const auto assigned = courier_index.find(request.jobs[i].robot); assigned != courier_index.end()) {
        courier = assigned->second;
      }
      const sched::StopKind kind =
          job.status == sched::JobStatus::kAboard ? sched::StopKind::kDelivery : sched::StopKind::kPickup;
      if (courier >= 0 && courier < static_cast<int>(problem.couriers.size()))
        problem.couriers[static_cast<size_t>(courier)].forced_prefix.push_back({static_cast<int>(i), kind});
    }
  }

  // The routes being driven are where an improving engine starts (rescheduling after a door
  // event is a repair, not a new search); stops of jobs no longer open are dropped by the engine.
  problem.previous_order.resize(problem.couriers.size());
  for (size_t c = 0; c < problem.couriers.size(); ++c) {
    const auto last = last_routes_.find(problem.couriers[c].id);
    if (last == last_routes_.end()) continue;
    for (const auto& [job_id, pickup] : last->second) {
      for (size_t j = 0; j < problem.jobs.size(); ++j) {
        const sched::Job& job = problem.jobs[j];
        if (job.id != job_id || (pickup && job.status == sched::JobStatus::kAboard)) continue;
        problem.previous_order[c].push_back(
            {static_cast<int>(j), pickup ? sched::StopKind::kPickup : sched::StopKind::kDelivery});
      }
    }
  }

  learned_notes_.clear();
  if (experience_) learned_notes_ = apply_experience(*experience_, floor_, request.doors_seen_open,
                                                     !request.closed_doors.empty(), places, problem);
  return problem;
}

std::string EngineScheduleSource::engine_for(const sched::SchedulingProblem& problem) const {
  if (settings_.engine != "exact") return settings_.engine;
  const int open_jobs = static_cast<int>(problem.jobs.size());
  if (open_jobs > settings_.exact_max_jobs) return "large";
  // The exact engine enumerates every assignment of the waiting jobs to the couriers.
  double assignments = 1.0;
  for (const auto& job : problem.jobs)
    if (job.status == sched::JobStatus::kWaitingForPickup) assignments *= static_cast<double>(problem.couriers.size());
  return assignments <= 16384.0 ? "exact" : "large";
}

Plan EngineScheduleSource::plan(const PlanRequest& request) {
  const sched::SchedulingProblem problem = problem_for(request);
  const std::string engine_name = engine_for(problem);
  auto engine = sched::make_scheduler_engine(engine_name);
  const auto budget =
      sched::wall_clock_budget(std::chrono::microseconds(static_cast<long long>(settings_.budget_ms * 1000.0)));
  const sched::JobSchedule schedule = engine->solve(problem, budget);

  Plan plan;
  plan.engine = engine_name;
  plan.proved_optimal = schedule.proved_optimal;
  for (const auto& u : schedule.unschedulable) {
    const sched::Job& job = problem.jobs[static_cast<size_t>(u.job)];
    std::string detail = u.detail;
    // Hours cut by what was learned say so ("learned: A-120 usually closed 10:00-11:30").
    bool learned = false;
    for (const int person : {job.pickup.person, job.delivery.person}) {
      if (person < 0 || person >= static_cast<int>(problem.people.size())) continue;
      const auto note = learned_notes_.find(problem.people[static_cast<size_t>(person)].name);
      if (note == learned_notes_.end()) continue;
      learned = true;
      if (detail.find(note->second) == std::string::npos) detail += " (" + note->second + ")";
    }
    plan.unschedulable[job.id] = detail;
    // Gone for the day by the office's hours, not by a habit learned: the job can no longer be done.
    if (u.reason == sched::UnschedulableReason::kNobodyPresent && !learned) plan.gone_for_good.insert(job.id);
  }
  if (!schedule.ok()) {
    // No schedule at all (infeasible, invalid, or out of time before the first one): the executive
    // keeps its routes and asks again; the jobs themselves are not to blame.
    plan.failed = true;
    plan.failure = std::string(sched::to_string(schedule.status)) + (schedule.reason.empty() ? "" : ": " + schedule.reason);
    return plan;
  }
  plan.late_jobs = schedule.objective.late_jobs;
  plan.total_lateness_s = schedule.objective.lateness_s;
  last_routes_.clear();
  for (const auto& route : schedule.routes) {
    const std::string& robot = problem.couriers[static_cast<size_t>(route.courier)].id;
    auto& stops = plan.routes[robot];
    for (const auto& s : route.stops)
      last_routes_[robot].emplace_back(problem.jobs[static_cast<size_t>(s.job)].id, s.kind == sched::StopKind::kPickup);
    for (const auto& s : route.stops) {
      const std::string& place = problem.locations[static_cast<size_t>(s.location)].name;
      stops.push_back({problem.jobs[static_cast<size_t>(s.job)].id, s.kind == sched::StopKind::kPickup, place,
                       problem.locations[static_cast<size_t>(s.location)].room, s.arrival_s, s.finish_s});
    }
  }
  for (const auto& o : schedule.outcomes) plan.completion_s[problem.jobs[static_cast<size_t>(o.job)].id] = o.completion_s;
  for (const auto& why : sched::explain_allocation(problem, schedule))
    plan.allocation[problem.jobs[static_cast<size_t>(why.job)].id] = why.text;
  return plan;
}

}  // namespace autonomy::courier
