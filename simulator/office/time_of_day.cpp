#include "simulator/office/time_of_day.hpp"

#include <cmath>
#include <cstdio>

namespace autonomy::sim::office {

double DayClock::time_of_day(double sim_time_s) const {
  const double t = std::fmod(day_start_s + sim_time_s, kSecondsPerDay);
  return t < 0.0 ? t + kSecondsPerDay : t;
}

std::optional<double> parse_clock(const std::string& text) {
  auto two_digits = [&](size_t at) -> int {
    if (at + 2 > text.size()) return -1;
    const char a = text[at], b = text[at + 1];
    if (a < '0' || a > '9' || b < '0' || b > '9') return -1;
    return (a - '0') * 10 + (b - '0');
  };
  if (text.size() != 5 && text.size() != 8) return std::nullopt;
  if (text[2] != ':' || (text.size() == 8 && text[5] != ':')) return std::nullopt;
  const int h = two_digits(0), m = two_digits(3), s = text.size() == 8 ? two_digits(6) : 0;
  if (h < 0 || m < 0 || s < 0 || m > 59 || s > 59 || h > 24) return std::nullopt;
  if (h == 24 && (m != 0 || s != 0)) return std::nullopt;
  return h * 3600.0 + m * 60.0 + s;
}

std::string format_clock(double seconds_of_day) {
  const long total = static_cast<long>(std::floor(seconds_of_day));
  const long h = total / 3600, m = (total / 60) % 60, s = total % 60;
  char buf[64];
  if (s == 0)
    std::snprintf(buf, sizeof buf, "%02ld:%02ld", h, m);
  else
    std::snprintf(buf, sizeof buf, "%02ld:%02ld:%02ld", h, m, s);
  return buf;
}

}  // namespace autonomy::sim::office
