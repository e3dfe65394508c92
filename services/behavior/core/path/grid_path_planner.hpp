#pragma once
// The exact grid field as a PathPlanner: computes the cost-to-go field towards the goal and walks
// downhill from the start cell, cell centre to cell centre. Its length is the optimum of the
// 8-connected grid graph: the reference the sampling planners are measured against.
#include "services/behavior/core/cost_to_go_field.hpp"
#include "services/behavior/core/path/path_planner.hpp"

#include <memory>

namespace autonomy::behavior {

// The downhill walk of `field` from `start` (start pose, the centres of the cells visited, the
// goal). Status Found, StartBlocked (start outside or in a blocked cell), GoalBlocked or
// Unreachable, with a reason. The poses' headings point along the next segment.
PathResult follow_field(const CostToGoField& field, const OccupancyGrid& grid,
                        const geometry::Pose2& start);

class GridPathPlanner final : public PathPlanner {
 public:
  explicit GridPathPlanner(std::shared_ptr<const OccupancyGrid> grid);
  PathResult plan(const PathRequest& request) override;

 private:
  std::shared_ptr<const OccupancyGrid> grid_;
};

// Checks the request's numbers (finite poses, positive budget); the reason when they are wrong.
std::optional<std::string> request_problem(const PathRequest& request);

}  // namespace autonomy::behavior
