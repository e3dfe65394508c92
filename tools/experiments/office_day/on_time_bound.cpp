#include "tools/experiments/office_day/on_time_bound.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <stdexcept>

namespace autonomy::office_day {

void DoorHistory::observe(const std::string& door, double at_s, bool closed) {
  const auto it = std::find_if(closed_now_.begin(), closed_now_.end(), [&](const Open& o) { return o.door == door; });
  if (closed && it == closed_now_.end()) closed_now_.push_back({door, at_s});
  if (!closed && it != closed_now_.end()) {
    done_.push_back({door, it->since_s, at_s});
    closed_now_.erase(it);
  }
}

std::vector<DoorClosure> DoorHistory::closures() const {
  std::vector<DoorClosure> out = done_;
  for (const Open& o : closed_now_) out.push_back({o.door, o.since_s});
  return out;
}

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct Interval {
  double from_s, to_s;
};

// What the ideal courier needs to know of one place.
struct Stop {
  std::string name;
  double x = 0, y = 0;
  std::vector<std::string> doors;       // into its room; none: always reachable
  std::optional<std::vector<Interval>> presence;  // none: no person (a station)
  std::string person;
  double handover_s = 0;                // the shortest the model allows
};

double shortest_handover(const config::HandoverTime& h, bool given) {
  if (!given) return 10.0;  // idl/scenario.proto: absent means 10 s
  switch (h.model_case()) {
    case config::HandoverTime::kFixedS: return h.fixed_s();
    case config::HandoverTime::kUniform: return h.uniform().min_s();
    case config::HandoverTime::kNormal: return h.normal().min_s();
    default: return 10.0;
  }
}

class Office {
 public:
  Office(const DayPlan& plan, const std::vector<DoorClosure>& closures) : closures_(closures) {
    const config::Scenario& sc = plan.scenario;
    day_start_s_ = clock_seconds(sc.day_start().empty() ? "08:30" : sc.day_start());
    std::map<std::string, std::string> kind_of_room;
    for (const auto& r : sc.rooms()) kind_of_room[r.name()] = r.kind();
    for (const auto& p : sc.places()) {
      Stop s;
      s.name = p.name();
      s.x = p.position().x();
      s.y = p.position().y();
      if (kind_of_room[p.room()] != "hallway")
        for (const auto& d : sc.doors())
          if (std::find(d.rooms().begin(), d.rooms().end(), p.room()) != d.rooms().end()) s.doors.push_back(d.id());
      stops_[s.name] = s;
    }
    for (const auto& person : sc.people()) {
      const auto it = stops_.find(person.desk());
      if (it == stops_.end()) continue;
      Stop& s = it->second;
      s.person = person.name();
      s.presence.emplace();
      for (const auto& w : person.presence())
        s.presence->push_back({clock_seconds(w.start()) - day_start_s_, clock_seconds(w.end()) - day_start_s_});
      s.handover_s = shortest_handover(person.handover_time(), person.has_handover_time());
    }
    for (const auto& station : sc.loading_stations()) {
      const auto it = stops_.find(station.place());
      if (it != stops_.end()) it->second.handover_s = shortest_handover(station.handover_time(), station.has_handover_time());
    }
    const auto& robot = sc.robots(0);
    speed_mps_ = robot.has_max_speed() ? robot.max_speed() : 1.0;
  }

  const Stop& stop(const std::string& name) const {
    const auto it = stops_.find(name);
    if (it == stops_.end()) throw std::invalid_argument("no place '" + name + "' in the day's scenario");
    return it->second;
  }
  double travel_s(const Stop& a, const Stop& b) const { return std::hypot(a.x - b.x, a.y - b.y) / speed_mps_; }
  std::string clock(double s) const { return clock_hhmm(day_start_s_ + s); }

  // The closure of a door into `s`'s room that keeps it shut at `t`, if every door is shut then.
  const DoorClosure* shut_by(const Stop& s, double t) const {
    const DoorClosure* any = nullptr;
    for (const auto& door : s.doors) {
      const DoorClosure* c = nullptr;
      for (const auto& k : closures_)
        if (k.door == door && k.from_s <= t && t < k.to_s) c = &k;
      if (!c) return nullptr;
      any = c;
    }
    return any;
  }
  bool present(const Stop& s, double t) const {
    if (!s.presence) return true;
    for (const auto& w : *s.presence)
      if (w.from_s <= t && t + s.handover_s <= w.to_s) return true;
    return false;
  }

  // The earliest arrival at or after `t0` with the room open and the handover inside the
  // person's hours: t0 itself or a moment one of them turns true (a door opening, someone coming
  // in), so only those need trying.
  double earliest(const Stop& s, double t0) const {
    std::vector<double> when = {t0};
    for (const auto& k : closures_)
      if (k.to_s > t0 && std::find(s.doors.begin(), s.doors.end(), k.door) != s.doors.end()) when.push_back(k.to_s);
    if (s.presence)
      for (const auto& w : *s.presence)
        if (w.from_s > t0) when.push_back(w.from_s);
    std::sort(when.begin(), when.end());
    for (double t : when)
      if (std::isfinite(t) && !shut_by(s, t) && present(s, t)) return t;
    return kInf;
  }

  // Why arriving at `t` does not do: the closed door or the person away.
  std::string obstacle(const Stop& s, double t) const {
    if (const DoorClosure* c = shut_by(s, t))
      return c->door + " closed " + clock(c->from_s) + "-" + (std::isfinite(c->to_s) ? clock(c->to_s) : "end of day");
    if (!present(s, t)) return s.person + " away";
    return "";
  }

 private:
  std::map<std::string, Stop> stops_;
  const std::vector<DoorClosure>& closures_;
  double day_start_s_ = 0, speed_mps_ = 1.0;
};

}  // namespace

std::vector<JobBound> on_time_bound(const DayPlan& plan, const std::vector<DoorClosure>& closures, double day_end_s) {
  const Office office(plan, closures);
  std::vector<JobBound> out;
  for (const DayCommand& c : plan.commands) {
    JobBound b;
    b.command_id = c.command_id;
    const Stop& from = office.stop(c.from);
    const Stop& to = office.stop(c.to);
    const double pickup = office.earliest(from, c.at_s);
    const double reach = pickup + from.handover_s + office.travel_s(from, to);
    const double delivery = std::isfinite(pickup) ? office.earliest(to, reach) : kInf;
    b.earliest_s = std::isfinite(delivery) ? delivery + to.handover_s : kInf;
    if (b.earliest_s > day_end_s) b.earliest_s = kInf;
    b.possible = b.earliest_s <= c.deadline_s;
    if (!b.possible) {
      // The pickup is to blame when even a delivery straight after it would be late.
      const bool at_pickup = !std::isfinite(pickup) || reach + to.handover_s > c.deadline_s;
      const std::string why = at_pickup ? office.obstacle(from, c.at_s) : office.obstacle(to, reach);
      b.why = (at_pickup ? "pickup at " + c.from : "delivery at " + c.to) + (why.empty() ? "" : ": " + why) +
              "; done at the earliest " + (std::isfinite(b.earliest_s) ? office.clock(b.earliest_s) : "never that day") +
              ", due " + c.deadline;
    }
    out.push_back(std::move(b));
  }
  return out;
}

}  // namespace autonomy::office_day
