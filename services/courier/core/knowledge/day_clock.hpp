#pragma once
// Office hours against simulated time, for the courier. A run starts at a configured time of day
// (08:30 in the office scenario), so simulated second t is clock time day_start_s + t, wrapped to
// one day. People's presence and job deadlines are written in seconds of the day ("10:30" is
// 37800); the scheduler works in simulated seconds, so both directions are here.
#include <optional>
#include <string>
#include <string_view>

namespace autonomy::courier {

inline constexpr double kSecondsPerDay = 86400.0;

struct DayClock {
  double day_start_s = 8.5 * 3600.0;  // clock time at simulated time 0, in [0, 86400)

  // Seconds since midnight at simulated time sim_s, in [0, 86400).
  double time_of_day(double sim_s) const;
  // Midnights passed since simulated time 0 (0 on the first day).
  long day_of(double sim_s) const;
  // The simulated time at which the clock shows seconds_of_day on the same day as now_sim_s
  // (possibly earlier than now_sim_s: callers compare).
  double sim_time_of(double seconds_of_day, double now_sim_s) const;
};

// "H:MM", "HH:MM" or "HH:MM:SS" (00:00 .. 24:00) to seconds of the day; nothing when malformed.
std::optional<double> parse_clock(std::string_view text);
// Seconds of the day as "HH:MM", or "HH:MM:SS" when the seconds are not whole minutes.
std::string format_clock(double seconds_of_day);

}  // namespace autonomy::courier
