#pragma once
// What the pictures tell, derived from the courier's events in order: the numbered steps of the
// paper's figures (step 1 is the start; events of one tick that matter to the paper - loaded,
// unloaded, doors seen, failures, opportunities, returns, blocked goals - share one number, as
// the paper's "A-120 is closed, a failure is signalled" is one step), and each job's phases for
// the timeline. Pure.
#include "tools/courier_plot/run_records.hpp"

#include <string>
#include <vector>

namespace autonomy::courier_plot {

struct StepLine {
  std::string time;  // HH:MM:SS
  std::string kind;
  std::string text;  // the event's sentence without its trailing clock time
};

struct Step {
  int number = 0;
  bool has_position = false;
  geometry::Vec2 position{0.0, 0.0};
  std::vector<StepLine> lines;
};

// `start` (the robot's first trajectory point) becomes step 1 when given.
std::vector<Step> numbered_steps(const std::vector<CourierEvent>& events,
                                 const std::optional<geometry::Vec2>& start,
                                 const std::string& start_robot);

enum class Phase { Waiting, Carried, Opportunistic, Returning };
const char* phase_name(Phase p);

struct PhaseBar {
  Phase phase = Phase::Waiting;
  double from_s = 0.0;  // sim_s
  double to_s = 0.0;
};

struct JobRow {
  std::string id;      // job-1
  std::string object;  // letter-red ("" when never loaded)
  std::vector<PhaseBar> bars;
  std::string outcome;  // the finished sentence without "job ID ", or "unfinished"
  bool failed = false;
};

struct DoorMark {
  double at_s = 0.0;
  std::string door;
  bool open = false;
};

struct Timeline {
  std::vector<JobRow> jobs;  // in order of acceptance
  std::vector<DoorMark> doors;
  double start_s = 0.0, end_s = 0.0;
  double clock_offset_s = 0.0;  // office clock seconds of the day at sim_s == 0
};

Timeline job_timeline(const std::vector<CourierEvent>& events);

// The sentence without a trailing " (HH:MM:SS)" or " at HH:MM:SS" (the legend shows the time).
std::string without_clock(const std::string& text);

}  // namespace autonomy::courier_plot
