#pragma once
// Continuous go-to paths in SE(2) with OMPL, for robots that cannot follow a grid's corners:
// Dubins curves (forward only), Reeds-Shepp curves (forward and reverse) or plain SE(2)
// (holonomic). The robot is a disc: a pose is valid when its centre lies in a free cell of the
// behavior's OccupancyGrid (obstacles grown by the robot's radius plus a margin, doors believed
// closed included via DoorKnowledge::apply), and motions are checked every <= 5 cm (OMPL's default
// step would jump through 0.2 m walls).
//
// The exact cost-to-go field towards the goal is computed first: it proves unreachability at once
// (status Unreachable instead of a timeout), gives the goal heading when the caller gives none,
// biases half of the planners' samples towards its route (narrow doorways are a thin slice of
// SE(2) that uniform samples rarely hit), and serves the optimising planners as their cost-to-go
// heuristic and stop threshold, so their paths stay close to the grid optimum. Before any
// sampling, the route itself is tried as a chain of curves (OmplPlannerSettings::route_guide):
// in the office that alone solves almost every Reeds-Shepp query within a few milliseconds, where
// RRT-Connect sampling from the start solved a third within 50 ms (docs/ompl-paths.md). Results are
// simplified with OMPL's path simplifier and checked against the grid again (first_collision)
// before they are returned.
//
// OMPL's headers stay in ompl_path_planner.cpp (pimpl): they are heavy to compile.
#include "services/behavior/core/path/path_planner.hpp"

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace autonomy::behavior {

enum class CurveModel {
  Dubins,      // forward only, minimum turning radius
  ReedsShepp,  // forward and reverse, minimum turning radius
  Holonomic,   // plain SE(2): straight lines, heading free
};
const char* to_string(CurveModel m);
std::optional<CurveModel> parse_curve_model(const std::string& text);

struct OmplPlannerSettings {
  CurveModel curve = CurveModel::ReedsShepp;
  std::string planner = "RRTConnect";  // one of ompl_planner_names()
  double turning_radius_m = 0.5;       // > 0; Dubins and Reeds-Shepp only
  double motion_step_m = 0.05;         // (0, 0.05]: collision checks along motions
  // Optimising planners stop once their path is no longer than this times the grid optimum's
  // length (they use the whole budget otherwise).
  double good_enough_ratio = 1.05;
  bool simplify = true;
  // Before sampling, try the grid route as a guide: from the start, hop to the farthest pose of
  // the route (within route_guide_reach_m along it, heading along the route) that one curve
  // reaches without collision, and so on to the goal. In an office almost every query is solved
  // this way in about a millisecond; the planner samples only when a hop fails (a start heading
  // that needs room to turn, a route too tight for the turning radius).
  bool route_guide = true;
  double route_guide_reach_m = 6.0;  // > 0
  // Unicycles turn on the spot: the curves start at the start position facing along the grid
  // route, after a turn in place (the path's first two poses share the position). Without it a
  // Reeds-Shepp path starts with the manoeuvres a car needs to turn (cusps).
  bool turn_in_place_at_start = false;
};

// The planner names `OmplPlannerSettings::planner` accepts, in a fixed order.
const std::vector<std::string>& ompl_planner_names();

// Checks settings; the reason when they are wrong (unknown planner names list the known ones).
std::optional<std::string> settings_problem(const OmplPlannerSettings& s);

// Seeds OMPL's random number generators. Takes effect only before the first plan() of the
// process (OMPL's rule); call it once at start for reproducible runs.
void seed_ompl(std::uint32_t seed);

class OmplPathPlanner final : public PathPlanner {
 public:
  // Throws std::invalid_argument when settings_problem() finds a problem.
  OmplPathPlanner(std::shared_ptr<const OccupancyGrid> grid, OmplPlannerSettings settings);
  ~OmplPathPlanner() override;
  OmplPathPlanner(const OmplPathPlanner&) = delete;
  OmplPathPlanner& operator=(const OmplPathPlanner&) = delete;

  const OmplPlannerSettings& settings() const { return settings_; }
  PathResult plan(const PathRequest& request) override;

 private:
  struct Impl;
  OmplPlannerSettings settings_;
  std::unique_ptr<Impl> impl_;
};

// The planner's Dubins curves (OMPL's, guarded against OMPL 1.5.2's assertions on near-coincident
// pose pairs, which abort the process): length from a to b, and the pose at fraction t in [0, 1].
// Headings in radians, any range. For tests and tools.
double dubins_distance(const geometry::Pose2& a, const geometry::Pose2& b, double turning_radius_m);
geometry::Pose2 dubins_interpolate(const geometry::Pose2& a, const geometry::Pose2& b, double t,
                                   double turning_radius_m);

// One experiment in OMPL's benchmark log format (read by ompl_benchmark_statistics.py and Planner
// Arena). Property names carry their type as OMPL expects: "time REAL", "solved BOOLEAN", ...
struct BenchmarkLog {
  std::string experiment;
  double max_time_s = 0.0;
  unsigned run_count = 0;
  std::uint32_t seed = 0;
  double total_duration_s = 0.0;
  std::string setup_info;
  std::map<std::string, std::string> parameters;
  struct Planner {
    std::string name;
    std::vector<std::map<std::string, std::string>> runs;
  };
  std::vector<Planner> planners;
};
// Written by OMPL's own writer (ompl::tools::Benchmark::saveResultsToStream). False on failure.
bool write_benchmark_log(std::ostream& out, const BenchmarkLog& log);

}  // namespace autonomy::behavior
