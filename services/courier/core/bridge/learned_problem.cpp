#include "services/courier/core/bridge/learned_problem.hpp"

#include <cmath>
#include <optional>
#include <vector>

#include "services/courier/core/execution/courier_executive.hpp"

namespace autonomy::courier {

namespace sched = scheduling;

namespace {

constexpr double kHalfHour = 1800.0;

std::string desk_of(const Floor& floor, const std::string& person) {
  for (const auto& [name, place] : floor.places)
    if (place.person == person) return name;
  return "";
}

}  // namespace

std::map<std::string, std::string> apply_experience(const Experience& experience, const Floor& floor,
                                                    const std::set<std::string>& doors_seen_open, bool detours,
                                                    std::size_t places, sched::SchedulingProblem& problem) {
  std::map<std::string, std::string> notes;
  for (sched::Person& person : problem.people) {
    person.handover_s = experience.expected_handover(person.name, person.handover_s);

    std::optional<std::string> door = floor.door_to(desk_of(floor, person.name));
    if (door && doors_seen_open.count(*door)) door.reset();  // seen open lately: no habit applies
    const auto why_cut = [&](double t) -> std::string {
      if (door && experience.usually_closed(*door, t)) return *door + " usually closed";
      if (experience.usually_absent(person.name, t)) return person.name + " usually away";
      return "";
    };
    // Empty presence = always there: from now for a day.
    std::vector<sched::TimeWindow> windows = person.presence;
    if (windows.empty()) windows.push_back({problem.now_s, problem.now_s + 86400.0});
    std::vector<sched::TimeWindow> kept;
    std::string first_cut;
    double cut_from = 0, cut_to = 0;
    for (const sched::TimeWindow& w : windows) {
      for (double t = w.start_s; t < w.end_s;) {
        const double slot_end = std::min(w.end_s, (std::floor(t / kHalfHour) + 1.0) * kHalfHour);
        const std::string why = t + 1e-9 < problem.now_s && slot_end <= problem.now_s ? "" : why_cut(t);
        if (why.empty()) {
          if (!kept.empty() && std::abs(kept.back().end_s - t) < 1e-9) kept.back().end_s = slot_end;
          else kept.push_back({t, slot_end});
        } else if (first_cut.empty()) {
          first_cut = why;
          cut_from = t;
          cut_to = slot_end;
        } else if (why == first_cut && std::abs(cut_to - t) < 1e-9) {
          cut_to = slot_end;
        }
        t = slot_end;
      }
    }
    if (first_cut.empty()) continue;  // nothing learned against these hours
    person.presence = kept.empty() ? std::vector<sched::TimeWindow>{{0.0, 0.0}} : kept;
    notes[person.name] = "learned: " + first_cut + " " + clock_text(cut_from).substr(0, 5) + "-" +
                         clock_text(cut_to).substr(0, 5);
  }
  for (std::size_t from = 0; from < places && from < problem.locations.size(); ++from)
    for (std::size_t to = 0; to < places && to < problem.locations.size(); ++to) {
      if (from == to || !std::isfinite(problem.travel.at(from, to))) continue;  // no route: stays so
      if (const auto t = experience.travel_time(problem.locations[from].name, problem.locations[to].name))
        if (!detours || *t > problem.travel.at(from, to)) problem.travel.set(from, to, *t);
    }
  return notes;
}

}  // namespace autonomy::courier
