#include "tools/courier_plot/run_records.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <sstream>

namespace autonomy::courier_plot {

namespace {

std::string at(const std::string& source, size_t line) {
  return source + ":" + std::to_string(line) + ": ";
}

// The reason a JSON line is not an event, or nothing; fills `e`.
std::optional<std::string> read_event(const nlohmann::json& j, CourierEvent& e) {
  if (!j.is_object()) return "not a JSON object";
  for (const char* key : {"kind", "text", "time"})
    if (!j.contains(key) || !j[key].is_string())
      return std::string("'") + key + "' missing or not a string";
  if (!j.contains("tick") || !j["tick"].is_number_integer())
    return "'tick' missing or not an integer";
  if (!j.contains("sim_s") || !j["sim_s"].is_number()) return "'sim_s' missing or not a number";
  e.kind = j["kind"].get<std::string>();
  e.text = j["text"].get<std::string>();
  e.time = j["time"].get<std::string>();
  e.tick = j["tick"].get<long>();
  e.sim_s = j["sim_s"].get<double>();
  if (e.kind.empty()) return "'kind' is empty";
  if (!clock_seconds(e.time)) return "'time' is not HH:MM:SS: '" + e.time + "'";
  if (!std::isfinite(e.sim_s) || e.sim_s < 0.0) return "'sim_s' must be finite and >= 0";
  if (j.contains("robots")) {
    if (!j["robots"].is_object()) return "'robots' is not an object";
    for (const auto& [id, xy] : j["robots"].items()) {
      if (!xy.is_array() || xy.size() != 2 || !xy[0].is_number() || !xy[1].is_number())
        return "robot '" + id + "' position is not [x, y]";
      e.robots[id] = geometry::Vec2(xy[0].get<double>(), xy[1].get<double>());
    }
  }
  return std::nullopt;
}

}  // namespace

EventsParse parse_events(const std::string& text, const std::string& source) {
  EventsParse out;
  std::istringstream in(text);
  std::string line;
  size_t number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
    if (j.is_discarded()) {
      out.error = at(source, number) + "not valid JSON";
      return out;
    }
    CourierEvent e;
    if (auto problem = read_event(j, e)) {
      out.error = at(source, number) + *problem;
      return out;
    }
    if (!out.events.empty() && e.sim_s < out.events.back().sim_s) {
      out.error = at(source, number) + "sim_s goes backwards";
      return out;
    }
    out.events.push_back(std::move(e));
  }
  if (out.events.empty()) out.error = source + ": no events";
  return out;
}

TrajectoryParse parse_trajectory_csv(const std::string& text, const std::string& source) {
  TrajectoryParse out;
  // A simulator stopped by a signal leaves its last row cut short: only whole lines count.
  const size_t whole = text.rfind('\n');
  std::istringstream in(whole == std::string::npos ? text : text.substr(0, whole + 1));
  std::string line;
  size_t number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (number == 1) {
      if (line != "tick,time_s,robot,x,y,theta") {
        out.error = at(source, number) + "expected the header tick,time_s,robot,x,y,theta";
        return out;
      }
      continue;
    }
    if (line.empty()) continue;
    std::vector<std::string> fields;
    std::stringstream row(line);
    for (std::string f; std::getline(row, f, ',');) fields.push_back(f);
    if (fields.size() != 6 || fields[2].empty()) {
      out.error = at(source, number) + "expected 6 fields tick,time_s,robot,x,y,theta";
      return out;
    }
    double v[2];
    for (int k = 0; k < 2; ++k) {
      size_t used = 0;
      try {
        v[k] = std::stod(fields[3 + k], &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used != fields[3 + k].size() || used == 0 || !std::isfinite(v[k])) {
        out.error =
            at(source, number) + (k == 0 ? "x" : "y") + " is not a number: '" + fields[3 + k] + "'";
        return out;
      }
    }
    out.paths[fields[2]].emplace_back(v[0], v[1]);
  }
  if (out.paths.empty() && !out.error) out.error = source + ": no trajectory rows";
  return out;
}

std::optional<int> clock_seconds(const std::string& s) {
  int h = 0, m = 0, sec = 0;
  char tail = 0;
  if (s.size() != 8 || std::sscanf(s.c_str(), "%2d:%2d:%2d%c", &h, &m, &sec, &tail) != 3)
    return std::nullopt;
  if (h < 0 || h > 23 || m < 0 || m > 59 || sec < 0 || sec > 59) return std::nullopt;
  return h * 3600 + m * 60 + sec;
}

std::string clock_text(double seconds_of_day) {
  const long t = std::lround(seconds_of_day);
  char buf[16];
  std::snprintf(buf, sizeof buf, "%02ld:%02ld:%02ld", (t / 3600) % 24, (t / 60) % 60, t % 60);
  return buf;
}

}  // namespace autonomy::courier_plot
