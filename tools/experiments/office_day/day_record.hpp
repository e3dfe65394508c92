#pragma once
// What one day of one strategy came to (one CSV row of the day-in-office experiment), from the
// day's commands, the courier's final job states, what its events file says happened, and the
// simulator's distance. Pure.
#include <map>
#include <string>
#include <vector>

#include "tools/experiments/office_day/day_plan.hpp"

namespace autonomy::office_day {

struct JobOutcome {
  std::string state;        // completed, failed, cancelled, opportunistic, queued, underway, stranded
  double completion_s = 0;  // seconds after the day's start (completed jobs)
};

// Counts of the courier's events (courier --events kinds) and schedules published.
struct DayCounts {
  int door_blocks = 0;         // goals blocked (by a closed door, mostly)
  double door_wait_s = 0;      // waiting to try a blocked goal again (strategy a)
  int doors_seen_closed = 0;
  int handover_refusals = 0;   // nobody present, helper busy
  int reschedules = 0;         // schedules published
  int opportunities = 0;       // opportunities taken
};

struct DayRecord {
  std::string strategy;
  int day = 0;
  std::uint64_t seed = 0;
  int jobs = 0;                // commands accepted
  int completed = 0;
  int on_time = 0;             // completed by their deadline
  double on_time_percent = 0;
  // Jobs any fleet could have finished on time that day (on_time_bound.hpp): the ceiling of
  // on_time, from the doors as they were and the people's hours.
  int possible_on_time = 0;
  double possible_percent = 0;
  double mean_lateness_s = 0;  // over every job; unfinished ones late by the day's end
  double max_lateness_s = 0;
  double distance_m = 0;
  DayCounts counts;
  double wall_s = 0;           // how long the day took to simulate
};

// `outcomes` by command id (commands the courier never accepted are left out of the jobs).
DayRecord summarize(const std::vector<DayCommand>& commands, const std::map<std::string, JobOutcome>& outcomes,
                    double day_end_s);

std::string csv_header();
std::string csv_row(const DayRecord& r);

}  // namespace autonomy::office_day
