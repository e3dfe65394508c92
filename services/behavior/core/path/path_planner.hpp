#pragma once
// One way to plan a go-to path: the exact grid field (grid_path_planner.hpp) or a sampling
// planner in SE(2) (ompl_path_planner.hpp). Chosen per robot or per goal by the go-to logic.
#include "services/behavior/core/path/path.hpp"

namespace autonomy::behavior {

class PathPlanner {
 public:
  virtual ~PathPlanner() = default;
  // Never throws on bad input: an invalid request comes back as a status with a reason.
  virtual PathResult plan(const PathRequest& request) = 0;
};

}  // namespace autonomy::behavior
