#include "tools/autonomy/text.hpp"

#include <cstdio>
#include <ctime>

namespace autonomy::tools {

std::string human_bytes(uint64_t bytes) {
  const char* units[] = {"B", "KiB", "MiB", "GiB", "TiB"};
  double v = static_cast<double>(bytes);
  int u = 0;
  while (v >= 1024.0 && u < 4) {
    v /= 1024.0;
    ++u;
  }
  char buf[32];
  std::snprintf(buf, sizeof buf, u == 0 ? "%.0f %s" : "%.1f %s", v, units[u]);
  return buf;
}

std::string utc_time(uint64_t ns) {
  const std::time_t s = static_cast<std::time_t>(ns / 1'000'000'000ull);
  std::tm tm{};
  gmtime_r(&s, &tm);
  char buf[64];
  std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M:%S", &tm);
  char out[96];
  std::snprintf(out, sizeof out, "%s.%03u UTC", buf, static_cast<unsigned>((ns / 1'000'000ull) % 1000));
  return out;
}

}  // namespace autonomy::tools

#include <cstdlib>

namespace autonomy::tools {

std::string where_we_looked(int domain) {
  const char* uri = std::getenv("CYCLONEDDS_URI");
  std::string s = "looked on DDS domain " + std::to_string(domain) + " (--domain or AUTONOMY_DOMAIN) with ";
  if (uri && *uri)
    s += "CYCLONEDDS_URI=" + std::string(uri);
  else
    s += "CYCLONEDDS_URI unset (Cyclone's default: the first multicast interface, not the project's loopback profile)";
  s += "; the processes must use the same two: e.g. export CYCLONEDDS_URI=file://$PWD/deploy/dds/loopback.xml "
       "AUTONOMY_DOMAIN=" + std::to_string(domain) + " (as in README, 'Running things yourself')";
  return s;
}

}  // namespace autonomy::tools
