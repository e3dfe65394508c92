#pragma once
// Office hours against simulated time. A run starts at a configured time of day (08:30 by
// default), so simulated second t is clock time day_start_s + t, wrapped to one day. Presence
// of people is written in seconds of the day, so "09:00-12:00" is [32400, 43200).
#include <optional>
#include <string>

namespace autonomy::sim::office {

inline constexpr double kSecondsPerDay = 86400.0;

struct DayClock {
  double day_start_s = 8.5 * 3600.0;  // clock time at simulated time 0, in [0, 86400)

  // Seconds since midnight at simulated time sim_time_s (>= 0), in [0, 86400).
  double time_of_day(double sim_time_s) const;
};

// "HH:MM" or "HH:MM:SS" (00:00 .. 24:00) to seconds of the day; nothing when malformed.
std::optional<double> parse_clock(const std::string& text);
// Seconds of the day as "HH:MM", or "HH:MM:SS" when the seconds are not zero (rounded down).
std::string format_clock(double seconds_of_day);

}  // namespace autonomy::sim::office
