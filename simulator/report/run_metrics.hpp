#pragma once
// The metrics of a team reconnaissance run from Wagner & Arkin, "Internalized Plans for
// Communication-Sensitive Robot Team Behaviors" (experiment section): per robot the mission
// time, the distance travelled and the time connected to at least one teammate; for the team the
// percent of time it was one connected network ("fully connected"); and coverage, the area
// sensed by any robot within a 3 m x 3 m square around it, not through obstacles.
//
// Fed once per simulation step with a plain TickSample, so this module knows nothing about the
// radio model: the caller derives the flags (with simulator/radio's Connectivity,
// connected_to_teammate = !neighbours(i).empty() and team_fully_connected = fully_connected()).
//
// A sample describes the state at the END of a step of dt seconds:
// - time:      dt counts towards a robot's mission time when the robot was not finished at the
//              start of the step (its previous sample, or it is new), so the step in which it
//              reaches its goal counts and later ones do not. A robot that gets unfinished
//              again (a new goal) accumulates again.
// - distance:  straight-line distance from the robot's previous sampled position (0 when new).
// - connected: dt counts when the flag is set in this sample (sample and hold, like the paper's
//              time steps). Percentages are of the robot's present time (from the sample in
//              which it first appears) and, for the team, of the whole run.
// - coverage:  after each sample, every grid cell whose centre lies inside the sensing square
//              (inclusive) of a robot and is visible from it (line_of_sight) becomes covered.
//              Coverage is counted over the whole run, finished or not.
//
// Pure: no clocks or files; the outputs are strings.
#include "common/geometry/geometry.hpp"

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace autonomy::sim {

using LineOfSight = std::function<bool(const geometry::Vec2& from, const geometry::Vec2& to)>;

struct CoverageSettings {
  geometry::Rect area;            // the grid spans it; cells of the last row/column may stick out
  double cell_size_m = 1.0;
  double sensor_square_m = 3.0;   // side of the sensed square centred on the robot
};

struct RobotTickSample {
  std::string id;
  geometry::Vec2 position{0.0, 0.0};
  bool finished = false;               // reached its goal (or otherwise done with the mission)
  bool connected_to_teammate = false;  // a connected link to at least one other robot
};

struct TickSample {
  double dt_s = 0.0;  // length of the step this sample ends; > 0
  std::vector<RobotTickSample> robots;
  bool team_fully_connected = true;  // one network holding every robot (true for 0 or 1 robots)
};

struct RobotMetrics {
  std::string id;
  double mission_time_s = 0.0;
  double distance_m = 0.0;
  double time_connected_s = 0.0;
  double present_time_s = 0.0;
  double percent_time_connected = 0.0;  // of present_time_s; 0 when never present for a step
  int64_t cells_covered = 0;            // cells this robot sensed
  double area_covered_m2 = 0.0;
  bool finished = false;                // in the latest sample it appeared in
};

struct TeamMetrics {
  double run_time_s = 0.0;
  int64_t steps = 0;
  double mission_time_s = 0.0;          // the longest robot mission time
  double distance_m = 0.0;              // sum over robots
  double time_fully_connected_s = 0.0;
  double percent_time_fully_connected = 0.0;  // of run_time_s; 0 for an empty run
  int64_t cells_total = 0;
  int64_t cells_covered = 0;            // cells sensed by any robot
  double area_covered_m2 = 0.0;
  double percent_covered = 0.0;         // of cells_total
  bool all_finished = false;
};

struct RunMetricsReport {
  CoverageSettings coverage;
  TeamMetrics team;
  std::vector<RobotMetrics> robots;  // sorted by id
};

class CoverageGrid {
 public:
  // Throws std::invalid_argument for an invalid area or a non-positive cell or square size.
  explicit CoverageGrid(const CoverageSettings& settings);

  int columns() const { return columns_; }
  int rows() const { return rows_; }
  int64_t cells() const { return static_cast<int64_t>(columns_) * rows_; }
  geometry::Vec2 centre(int column, int row) const;
  // Visits every cell whose centre is inside the square of side settings.sensor_square_m around
  // `position` (inclusive), in row-major order.
  void for_each_sensed(const geometry::Vec2& position,
                       const std::function<void(int column, int row)>& visit) const;
  const CoverageSettings& settings() const { return settings_; }

 private:
  CoverageSettings settings_;
  int columns_ = 0;
  int rows_ = 0;
};

class RunMetrics {
 public:
  // An empty line_of_sight means nothing blocks sight. Throws like CoverageGrid.
  RunMetrics(CoverageSettings coverage, LineOfSight line_of_sight);

  void add(const TickSample& sample);
  RunMetricsReport report() const;

  // Cells sensed by any robot so far, row-major (columns() * rows() flags), for pictures.
  const std::vector<bool>& covered() const { return team_covered_; }
  const CoverageGrid& grid() const { return grid_; }

 private:
  struct Robot {
    RobotMetrics m;
    geometry::Vec2 last_position{0.0, 0.0};
    std::vector<bool> covered;
  };
  void sense(Robot& robot, const geometry::Vec2& position);

  CoverageGrid grid_;
  LineOfSight line_of_sight_;
  std::map<std::string, Robot> robots_;
  std::vector<bool> team_covered_;
  int64_t team_cells_ = 0;
  double run_time_s_ = 0.0;
  int64_t steps_ = 0;
  double fully_connected_s_ = 0.0;
};

// One header line, one row per robot (by id), then one row "team" where mission_time_s is the
// longest mission, distance_m the sum, time_connected_s / percent_time_connected the time the
// team was fully connected, cells/area the union and finished = all finished. Columns:
// robot,mission_time_s,distance_m,time_connected_s,percent_time_connected,cells_covered,area_covered_m2,finished
std::string metrics_csv(const RunMetricsReport& report);
// {"coverage": {...settings, cells_total}, "team": {...}, "robots": [{...}, ...]}, indented.
std::string metrics_json(const RunMetricsReport& report);

}  // namespace autonomy::sim
