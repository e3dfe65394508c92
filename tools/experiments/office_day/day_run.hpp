#pragma once
// One day of one strategy through the real processes over DDS, in lockstep: the simulator with
// the day's scenario, one behavior process per courier robot, the courier service with the
// strategy's flags, and this process as the office's people (a lockstep participant that sends
// each command at its time of day and acknowledges every tick, so commands arrive on time to the
// tick). What the day came to is read from the job states on the wire, the courier's events file
// and the simulator's metrics.
#include <chrono>
#include <filesystem>
#include <string>

#include "tools/experiments/office_day/day_plan.hpp"
#include "tools/experiments/office_day/day_record.hpp"
#include "tools/experiments/office_day/strategy.hpp"

namespace autonomy::office_day {

struct RunSetup {
  std::string bin_dir;            // simulator, behavior, courier
  std::filesystem::path out_dir;  // days/ (scenarios, events, metrics), logs/
  double day_s = 8 * 3600.0;
  bool trajectory = false;        // write days/<s>-<day>.trajectory.csv (for pictures)
  bool every_tick = false;        // the simulator publishes quiet ticks too (simulator --every-tick)
  std::chrono::seconds timeout{900};  // wall time a day may take
};

// Runs `day` of `strategy` on DDS `domain` with the courier journal `journal` (fresh, or
// holding the knowledge carried from yesterday). Throws std::runtime_error naming the log to
// read when a process fails or the day times out.
DayRecord run_day(const RunSetup& setup, const Strategy& strategy, const DayPlan& plan, int day, std::uint64_t seed,
                  int domain, const std::filesystem::path& journal);

// Files of one day: "<out>/days/<strategy>-<day>.<what>".
std::filesystem::path day_file(const RunSetup& setup, const std::string& strategy, int day, const std::string& what);

}  // namespace autonomy::office_day
