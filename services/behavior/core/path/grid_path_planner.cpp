#include "services/behavior/core/path/grid_path_planner.hpp"

#include <cmath>
#include <sstream>

namespace autonomy::behavior {

namespace {

std::string where(const geometry::Vec2& p) {
  std::ostringstream s;
  s << "(" << p.x() << ", " << p.y() << ")";
  return s.str();
}

PathResult grid_failure(PathStatus status, std::string reason) {
  PathResult r;
  r.status = status;
  r.reason = std::move(reason);
  return r;
}

// Headings along the polyline: each pose faces the next one; the last keeps the last segment's.
void set_headings(std::vector<geometry::Pose2>& poses) {
  for (std::size_t i = 0; i + 1 < poses.size(); ++i) {
    const double dx = poses[i + 1].x - poses[i].x;
    const double dy = poses[i + 1].y - poses[i].y;
    if (dx != 0.0 || dy != 0.0)
      poses[i].theta = std::atan2(dy, dx);
    else if (i > 0)
      poses[i].theta = poses[i - 1].theta;
  }
  if (poses.size() >= 2) poses.back().theta = poses[poses.size() - 2].theta;
}

}  // namespace

std::optional<std::string> request_problem(const PathRequest& q) {
  if (!std::isfinite(q.start.x) || !std::isfinite(q.start.y) || !std::isfinite(q.start.theta)) {
    return "start pose is not finite";
  }
  if (!std::isfinite(q.goal.x()) || !std::isfinite(q.goal.y()))
    return "goal position is not finite";
  if (q.goal_heading && !std::isfinite(*q.goal_heading)) return "goal heading is not finite";
  if (!(q.budget_s > 0.0) || !std::isfinite(q.budget_s))
    return "planning budget must be positive and finite";
  return std::nullopt;
}

PathResult follow_field(const CostToGoField& field, const OccupancyGrid& grid,
                        const geometry::Pose2& start) {
  const auto& geo = field.geometry();
  const auto goal_cell = field.goal_cell();
  if (!goal_cell || grid.blocked(*goal_cell)) {
    return grid_failure(PathStatus::GoalBlocked,
                   "goal " + where(field.goal()) + " is outside the map or in an obstacle");
  }
  const auto start_cell = geo.cell_at(start.position());
  if (!start_cell || grid.blocked(*start_cell)) {
    return grid_failure(PathStatus::StartBlocked,
                   "start " + where(start.position()) + " is outside the map or in an obstacle");
  }
  if (!field.reachable(*start_cell)) {
    return grid_failure(PathStatus::Unreachable, "no route from " + where(start.position()) + " to " +
                                                where(field.goal()) + " on the map");
  }
  PathResult r;
  r.status = PathStatus::Found;
  r.poses.push_back(start);
  GridCell c = *start_cell;
  // Each step strictly lowers the cost, so the walk ends at the goal within cell_count steps.
  for (std::size_t steps = 0; c != *goal_cell && steps < geo.cell_count(); ++steps) {
    r.poses.push_back({geo.centre(c).x(), geo.centre(c).y(), 0.0});
    const geometry::Vec2 a = field.advice(c);
    const int dc = a.x() > 0.3 ? 1 : (a.x() < -0.3 ? -1 : 0);
    const int dr = a.y() > 0.3 ? 1 : (a.y() < -0.3 ? -1 : 0);
    if (dc == 0 && dr == 0) break;
    c = {c.col + dc, c.row + dr};
  }
  if (c != *goal_cell)
    return grid_failure(PathStatus::Unreachable, "the field's walk did not reach the goal");
  r.poses.push_back({geo.centre(c).x(), geo.centre(c).y(), 0.0});
  r.poses.push_back({field.goal().x(), field.goal().y(), 0.0});
  set_headings(r.poses);
  r.poses.front().theta = start.theta;
  r.length_m = path_length(r.poses);
  return r;
}

GridPathPlanner::GridPathPlanner(std::shared_ptr<const OccupancyGrid> grid)
    : grid_(std::move(grid)) {}

PathResult GridPathPlanner::plan(const PathRequest& request) {
  if (auto problem = request_problem(request)) return grid_failure(PathStatus::InvalidRequest, *problem);
  const CostToGoField field(*grid_, request.goal);
  auto r = follow_field(field, *grid_, request.start);
  if (r.found() && request.goal_heading) r.poses.back().theta = *request.goal_heading;
  return r;
}

}  // namespace autonomy::behavior
