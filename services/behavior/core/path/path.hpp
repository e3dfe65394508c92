#pragma once
// A planned go-to path and what a planner says about it: the poses a robot should pass through,
// with a status and, when there is no path, the reason. Shared by every PathPlanner (grid field,
// OMPL) so the go-to logic, the tracker and the benchmark do not care which planner ran.
#include "common/geometry/geometry.hpp"
#include "services/behavior/core/occupancy_grid.hpp"

#include <optional>
#include <string>
#include <vector>

namespace autonomy::behavior {

class CostToGoField;

enum class PathStatus {
  Found,           // poses lead from the start to the goal, clear of the map
  InvalidRequest,  // non-finite pose, non-positive budget
  StartBlocked,    // the start lies in an obstacle (or outside the map)
  GoalBlocked,     // the goal lies in an obstacle (or outside the map)
  Unreachable,     // proven: no collision-free route joins start and goal on this map
  NotFound,        // a route exists on the grid but the planner found none within its budget
};
const char* to_string(PathStatus s);

struct PathRequest {
  geometry::Pose2 start;
  geometry::Vec2 goal;
  // Heading at the goal; without it the planner picks the heading the grid's route arrives with.
  std::optional<double> goal_heading;
  double budget_s = 0.05;  // > 0: planning time the caller grants
  // The goal's cost-to-go field on the planner's grid when the caller has it already (the
  // behavior's goal tracker computes it on accepting the goal): used instead of computing the same
  // field again, the largest part of a plan on a big map (docs/fields.md). Used only when its cell
  // geometry and goal cell are the grid's and the goal's; the caller vouches that it was computed on
  // the same blocked cells. Not owned; must outlive plan().
  const CostToGoField* field = nullptr;
};

struct PathResult {
  PathStatus status = PathStatus::NotFound;
  std::string reason;                  // empty when Found
  std::vector<geometry::Pose2> poses;  // start first, goal last; consecutive poses <= 5 cm apart
                                       // for OMPL paths, cell to cell for grid paths
  double length_m = 0.0;               // along the poses
  double planning_s = 0.0;             // time spent (OMPL planners; 0 for the grid)
  bool route_guided = false;           // OMPL: the grid route's guide found it, no sampling

  bool found() const { return status == PathStatus::Found; }
};

// Metres along the polyline.
double path_length(const std::vector<geometry::Pose2>& poses);
// Sum over interior vertices of the squared turn angle (rad^2) per metre of the two segments
// around it: 0 for a straight path, large for zig-zags. Segments shorter than 1 mm are skipped.
double path_smoothness(const std::vector<geometry::Pose2>& poses);

// Index of the first segment of `poses` that leaves the free cells of `grid`, tested at most
// `step_m` apart along each segment (and at every pose); nullopt when the whole path is clear.
// This is the map's own collision test: every planner's result passes it before it is returned.
std::optional<std::size_t> first_collision(const OccupancyGrid& grid,
                                           const std::vector<geometry::Pose2>& poses,
                                           double step_m);

}  // namespace autonomy::behavior
