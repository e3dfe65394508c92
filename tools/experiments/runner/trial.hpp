#pragma once
// One trial of the robot-teams experiment: the real simulator and three behavior controllers on a
// DDS domain of their own, in lockstep, until every robot finished its mission (or the tick
// limit); the simulator's metrics file becomes one TrialRecord. The nodes run in one process
// (experiment_trial_host) or, as before, each in its own (simulator, behavior): the same code and
// flags, so the same results; one process spares the lockstep round trips the network.
#include "tools/experiments/stats/report.hpp"

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace autonomy::experiments {

// What every trial shares.
struct TrialSetup {
  std::string bin_dir;                   // experiment_trial_host, simulator and behavior
  bool one_process = true;               // experiment_trial_host, else a process per node
  std::filesystem::path missions_dir;    // <configuration>_<robot>.pbtxt
  std::filesystem::path scenario;        // its own robots are not spawned (--without-robots)
  std::filesystem::path out_dir;         // metrics, pictures; logs/ below it
  std::string dds_uri;                   // CYCLONEDDS_URI of the children ("" inherits)
  std::vector<std::string> robots = {"r1", "r2", "r3"};
  int max_ticks = 4000;                  // the run ends here if the team has not finished
  double grid_resolution_m = 1.0;        // the behaviors' planning grid
  double start_min_x = 10.0, start_max_x = 240.0, start_y = 3.0;
  double min_start_spacing_m = 3.0;      // robots must not be spawned on top of each other
  std::chrono::seconds timeout{600};     // wall time one trial may take
};

// Random start x positions along the bottom edge, drawn from `seed`, uniform over the
// arrangements at least min_start_spacing_m apart, sorted west to east (robot k gets the k-th:
// each mission's dispersion waypoint lies on its robot's side). Throws std::invalid_argument when
// the robots cannot fit that far apart.
std::vector<double> start_positions(const TrialSetup& setup, std::uint64_t seed);

// Runs trial `trial` of `configuration` on DDS domain `domain`. Writes <out>/<cfg>-<trial>.json,
// .csv and .svg and logs/<cfg>-<trial>-*.out (one process: -trial.out and trial-<cfg>-<trial>.log). Throws std::runtime_error naming the log to read
// when a process fails or the trial times out.
// check_for_other_world: the simulator listens (its --world-check, 1 s) for another world on the
// domain before it starts. The runner asks it for the first trial of each domain only: later trials
// on that domain follow its own, which have ended, and 1 s each was a third of a trial's wall time.
stats::TrialRecord run_trial(const TrialSetup& setup, const std::string& configuration, int trial,
                             std::uint64_t seed, int domain, bool check_for_other_world = true);

}  // namespace autonomy::experiments
