#pragma once
// The two records of a courier run that the pictures are drawn from, parsed with checks: the
// courier's events file (`courier --events`, one JSON object per line) and the simulator's
// trajectory CSV (`simulator --trajectory`: tick,time_s,robot,x,y,theta; a last line without its
// newline is a row cut short by a stopped simulator and is ignored). Pure: text in, plain
// structs out; every problem names source:line.
#include "common/geometry/geometry.hpp"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace autonomy::courier_plot {

struct CourierEvent {
  std::string kind;  // accepted, loaded, door_closed, ...
  std::string text;  // the courier's sentence
  long tick = 0;
  double sim_s = 0.0;
  std::string time;                              // HH:MM:SS, office clock
  std::map<std::string, geometry::Vec2> robots;  // where each courier robot stood (may be empty)
};

struct EventsParse {
  std::vector<CourierEvent> events;
  std::optional<std::string> error;  // "source:line: reason"; events then incomplete
};

EventsParse parse_events(const std::string& text, const std::string& source);

struct TrajectoryParse {
  std::map<std::string, std::vector<geometry::Vec2>> paths;  // by robot id, in file order
  std::optional<std::string> error;
};

TrajectoryParse parse_trajectory_csv(const std::string& text, const std::string& source);

// "HH:MM:SS" as seconds of the day, or nothing when it is not that shape.
std::optional<int> clock_seconds(const std::string& hh_mm_ss);
std::string clock_text(double seconds_of_day);

}  // namespace autonomy::courier_plot
