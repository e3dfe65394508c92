#pragma once
// One simulated working day in the office for the day-in-office experiment (issue 10): the
// shipped office floor with a seeded stream of delivery commands (arrival times, objects,
// pickups, destinations, deadlines), one object per command lying at its pickup from the start,
// and the doors' habits of that day (a door usually closed at some hour is closed then on most
// days, a little earlier or later) on top of the floor's random doors. Pure: a scenario in, a
// scenario and commands out.
#include <cstdint>
#include <string>
#include <vector>

#include "idl/scenario.pb.h"

namespace autonomy::office_day {

// A door closed for a while on most days: what learning can find out.
struct DoorHabit {
  std::string door;
  double from_s = 0, to_s = 0;  // seconds after the day's start
  double probability = 0.8;     // of a day having it
  double jitter_s = 600;        // each end moves by up to this much
};

struct DaySettings {
  double hours = 8.0;                 // the day's length after the scenario's day_start
  double jobs_per_hour = 4.0;         // Poisson arrivals
  double last_command_before_end_s = 1800;
  double deadline_min_s = 20 * 60, deadline_max_s = 90 * 60;  // after the command
  double step_s = 0.5;                // the simulation's step for the day
  int couriers = 1;                   // robots of kind courier (copies of the first one)
  std::vector<DoorHabit> habits;      // default_habits() for the shipped office
};

// Michael's door closed 10:00-11:30, Anna's 13:00-14:30, Wolfram's
// 15:00-16:00, each on 80 % of the days (times after a 09:00 start).
std::vector<DoorHabit> default_habits();

struct DayCommand {
  double at_s = 0;                    // seconds after the day's start
  std::string command_id, object_id, from, to;
  std::string deadline;               // "HH:MM" of the day
  double deadline_s = 0;              // the same, seconds after the day's start
};

struct DayPlan {
  config::Scenario scenario;
  std::vector<DayCommand> commands;   // by time
  std::vector<std::string> habits_today;  // "A-120 closed 10:04-11:27"
};

// Throws std::invalid_argument when the office lacks what a day needs (people, places, the
// habits' doors, a courier robot).
DayPlan plan_day(const config::Scenario& office, const DaySettings& settings, std::uint64_t seed);

// Seconds after midnight of "HH:MM[:SS]"; throws std::invalid_argument otherwise.
double clock_seconds(const std::string& hhmm);
std::string clock_hhmm(double seconds_of_day);

}  // namespace autonomy::office_day
