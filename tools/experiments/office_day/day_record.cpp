#include "tools/experiments/office_day/day_record.hpp"

#include <algorithm>
#include <cstdio>

namespace autonomy::office_day {

DayRecord summarize(const std::vector<DayCommand>& commands, const std::map<std::string, JobOutcome>& outcomes,
                    double day_end_s) {
  DayRecord r;
  double lateness_sum = 0;
  for (const DayCommand& c : commands) {
    const auto it = outcomes.find(c.command_id);
    if (it == outcomes.end()) continue;
    ++r.jobs;
    const bool done = it->second.state == "completed";
    const double finish = done ? it->second.completion_s : day_end_s;
    const double late = std::max(0.0, finish - c.deadline_s);
    if (done) ++r.completed;
    if (done && late <= 0) ++r.on_time;
    lateness_sum += late;
    r.max_lateness_s = std::max(r.max_lateness_s, late);
  }
  r.mean_lateness_s = r.jobs ? lateness_sum / r.jobs : 0;
  r.on_time_percent = r.jobs ? 100.0 * r.on_time / r.jobs : 0;
  return r;
}

std::string csv_header() {
  return "strategy,day,seed,jobs,completed,on_time,on_time_percent,mean_lateness_s,max_lateness_s,distance_m,"
         "door_blocks,door_wait_s,doors_seen_closed,handover_refusals,reschedules,opportunities,wall_s,"
         "possible_on_time,possible_percent\n";
}

std::string csv_row(const DayRecord& r) {
  char line[512];
  std::snprintf(line, sizeof line, "%s,%d,%llu,%d,%d,%d,%.2f,%.1f,%.1f,%.1f,%d,%.0f,%d,%d,%d,%d,%.1f,%d,%.2f\n",
                r.strategy.c_str(), r.day, static_cast<unsigned long long>(r.seed), r.jobs, r.completed, r.on_time,
                r.on_time_percent, r.mean_lateness_s, r.max_lateness_s, r.distance_m, r.counts.door_blocks,
                r.counts.door_wait_s, r.counts.doors_seen_closed, r.counts.handover_refusals, r.counts.reschedules,
                r.counts.opportunities, r.wall_s, r.possible_on_time, r.possible_percent);
  return line;
}

}  // namespace autonomy::office_day
