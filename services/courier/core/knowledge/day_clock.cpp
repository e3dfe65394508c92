#include "services/courier/core/knowledge/day_clock.hpp"

#include <cmath>
#include <cstdio>

namespace autonomy::courier {

double DayClock::time_of_day(double sim_s) const {
  const double t = std::fmod(day_start_s + sim_s, kSecondsPerDay);
  return t < 0.0 ? t + kSecondsPerDay : t;
}

long DayClock::day_of(double sim_s) const {
  return static_cast<long>(std::floor((day_start_s + sim_s) / kSecondsPerDay));
}

double DayClock::sim_time_of(double seconds_of_day, double now_sim_s) const {
  // The start of now's day in simulated time, then the offset into that day.
  const double midnight_sim = now_sim_s - time_of_day(now_sim_s);
  return midnight_sim + seconds_of_day;
}

std::optional<double> parse_clock(std::string_view text) {
  // Splits on ':' into 2 or 3 fields of digits; the hour has 1-2 digits, the others exactly 2.
  int fields[3] = {0, 0, 0};
  int count = 0;
  std::size_t digits = 0;
  for (std::size_t i = 0; i <= text.size(); ++i) {
    if (i == text.size() || text[i] == ':') {
      if (digits == 0 || digits > 2 || (count > 0 && digits != 2) || count == 3)
        return std::nullopt;
      ++count;
      digits = 0;
      continue;
    }
    if (text[i] < '0' || text[i] > '9' || count == 3) return std::nullopt;  // a fourth field
    fields[count] = fields[count] * 10 + (text[i] - '0');
    ++digits;
  }
  if (count < 2) return std::nullopt;
  const int h = fields[0], m = fields[1], s = fields[2];
  if (h > 24 || m > 59 || s > 59 || (h == 24 && (m != 0 || s != 0))) return std::nullopt;
  return h * 3600.0 + m * 60.0 + s;
}

std::string format_clock(double seconds_of_day) {
  const long total =
      std::isfinite(seconds_of_day) ? static_cast<long>(std::floor(seconds_of_day)) : 0;
  const long h = total / 3600, m = (total / 60) % 60, s = total % 60;
  char buf[48];
  if (s == 0)
    std::snprintf(buf, sizeof buf, "%02ld:%02ld", h, m);
  else
    std::snprintf(buf, sizeof buf, "%02ld:%02ld:%02ld", h, m, s);
  return buf;
}

}  // namespace autonomy::courier
