#include "tools/experiments/office_day/day_plan.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <set>
#include <stdexcept>

namespace autonomy::office_day {

std::vector<DoorHabit> default_habits() {
  return {{"A-120", 3600, 9000, 0.8, 600}, {"A-114", 14400, 19800, 0.8, 600}, {"A-118", 21600, 25200, 0.8, 600}};
}

double clock_seconds(const std::string& t) {
  int h = 0, m = 0, s = 0;
  char tail = 0;
  const int n = std::sscanf(t.c_str(), "%d:%d:%d%c", &h, &m, &s, &tail);
  if ((n != 2 && n != 3) || h < 0 || h > 24 || m < 0 || m > 59 || s < 0 || s > 59)
    throw std::invalid_argument("'" + t + "' is not HH:MM or HH:MM:SS");
  return h * 3600.0 + m * 60.0 + s;
}

std::string clock_hhmm(double seconds_of_day) {
  const long minutes = static_cast<long>(std::floor(seconds_of_day / 60.0 + 1e-9));
  char text[8];
  std::snprintf(text, sizeof text, "%02ld:%02ld", (minutes / 60) % 24, minutes % 60);
  return text;
}

DayPlan plan_day(const config::Scenario& office, const DaySettings& settings, std::uint64_t seed) {
  if (office.people().empty()) throw std::invalid_argument("the office has no people to deliver to");
  if (office.robots().empty()) throw std::invalid_argument("the office has no courier robot");
  DayPlan day;
  day.scenario = office;
  config::Scenario& sc = day.scenario;
  const double day_start = clock_seconds(sc.day_start().empty() ? "08:30" : sc.day_start());
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);

  // Pickups: every desk with a person and every station; destinations: the people's desks.
  std::vector<std::string> desks, pickups;
  for (const auto& p : sc.people()) desks.push_back(p.desk());
  pickups = desks;
  for (const auto& s : sc.loading_stations()) pickups.push_back(s.place());

  // The day's objects are only those of its commands.
  sc.clear_objects();
  const std::vector<std::string> kinds = {"letter", "parcel", "envelope", "book"};
  const std::vector<std::string> colours = {"red", "green", "blue", "white", "yellow", "brown"};
  const double last = settings.hours * 3600.0 - settings.last_command_before_end_s;
  std::exponential_distribution<double> gap(settings.jobs_per_hour / 3600.0);
  std::uniform_real_distribution<double> slack(settings.deadline_min_s, settings.deadline_max_s);
  int n = 0;
  for (double t = gap(rng); t < last; t += gap(rng)) {
    DayCommand c;
    c.at_s = t;
    c.command_id = "day-" + std::to_string(++n);
    c.object_id = "item-" + std::to_string(n);
    c.from = pickups[static_cast<std::size_t>(unit(rng) * static_cast<double>(pickups.size())) % pickups.size()];
    do {
      c.to = desks[static_cast<std::size_t>(unit(rng) * static_cast<double>(desks.size())) % desks.size()];
    } while (c.to == c.from && desks.size() > 1);
    // Deadlines in whole minutes ("HH:MM"), never before the command plus the least slack.
    const double due = day_start + t + slack(rng);
    c.deadline = clock_hhmm(std::ceil(due / 60.0) * 60.0);
    c.deadline_s = clock_seconds(c.deadline) - day_start;
    auto* o = sc.add_objects();
    o->set_id(c.object_id);
    o->set_kind(kinds[static_cast<std::size_t>(n) % kinds.size()]);
    o->set_colour(colours[static_cast<std::size_t>(unit(rng) * static_cast<double>(colours.size())) % colours.size()]);
    o->set_place(c.from);
    day.commands.push_back(std::move(c));
  }

  // The doors' habits today: a scripted closing on most days, on top of the floor's own doors.
  for (const DoorHabit& h : settings.habits) {
    config::Door* door = nullptr;
    for (auto& d : *sc.mutable_doors())
      if (d.id() == h.door) door = &d;
    if (!door) throw std::invalid_argument("no door " + h.door + " in the office for a habit");
    const bool today = unit(rng) < h.probability;
    const double from = h.from_s + (2 * unit(rng) - 1) * h.jitter_s;
    const double to = h.to_s + (2 * unit(rng) - 1) * h.jitter_s;
    door->clear_script();
    door->clear_random();
    if (!today || to <= from) continue;
    auto* script = door->mutable_script();
    auto* close = script->add_events();
    close->set_time_s(std::max(0.0, from));
    close->set_angle(0.0);
    auto* open = script->add_events();
    open->set_time_s(to);
    open->set_angle(door->has_max_angle() ? door->max_angle() : M_PI / 2);
    day.habits_today.push_back(h.door + " closed " + clock_hhmm(day_start + from) + "-" + clock_hhmm(day_start + to));
  }
  // Doors the habits do not name keep what the floor gives them, except scripts written for one
  // story (the paper's Fig. 5): open all day.
  for (auto& d : *sc.mutable_doors()) {
    bool habit = false;
    for (const DoorHabit& h : settings.habits) habit = habit || h.door == d.id();
    if (!habit && d.has_script()) d.clear_script();
  }

  // The couriers: the first robot and copies of it. A fleet starts on the office's parking spots
  // (where its idle robots wait, out of the way), the ones beyond them beside the first robot in
  // the hallway; a lone courier starts where the scenario puts it.
  const config::Robot first = sc.robots(0);
  sc.clear_robots();
  const int couriers = std::max(1, settings.couriers);
  for (int k = 0; k < couriers; ++k) {
    config::Robot r = first;
    if (k > 0) r.set_id(first.id() + std::to_string(k + 1));
    if (couriers > 1 && k < sc.parking_size()) {
      r.mutable_start()->set_x(sc.parking(k).position().x());
      r.mutable_start()->set_y(sc.parking(k).position().y());
    } else if (k > 0) {
      r.mutable_start()->set_x(first.start().x() + 1.5 * k);
    }
    *sc.add_robots() = r;
  }

  auto* sim = sc.mutable_simulation();
  sim->set_mode(config::LOCKSTEP);
  sim->set_step_s(settings.step_s);
  // A velocity command lasts one step in lockstep: the world's timeout must not end it sooner.
  if (!sim->has_command_timeout_s() || sim->command_timeout_s() < 1.5 * settings.step_s)
    sim->set_command_timeout_s(1.5 * settings.step_s);
  sim->set_seed(seed);
  sc.set_name(office.name() + "-day");
  return day;
}

}  // namespace autonomy::office_day
