// BehaviorNode in goal mode with planned paths (GoToPlanner::Ompl): plans the pursued goal in
// SE(2) on what the robot knows (its grid: obstacles, doors believed closed, the goal's constraint
// layers), follows the path with the tracking schema and replans when the robot strays. A goal
// with no path within the budget ends Blocked with the planner's reason.
#include "services/behavior/dds/behavior_node.hpp"

#include "services/behavior/core/constraint_sets.hpp"

#include <spdlog/spdlog.h>

#include <cmath>
#include <string_view>

namespace autonomy::behavior {

namespace {

// Range hits within this of the map's obstacles are the map's own (range noise, cell rounding).
constexpr double kMapHitMargin = 0.15;
constexpr double kMapHitResolution = 0.05;

}  // namespace

void BehaviorNode::update_map_obstacles() {
  // Closed doors' slabs and open doors' leaves where the robot believes them: hits there are the
  // map's; a leaf anywhere else (a door swinging, a map that says nothing of its leaf) is in the
  // way like anything else the scan sees.
  map_obstacles_.emplace(doors_.apply(world_), kMapHitResolution, kMapHitMargin);
}

std::shared_ptr<const OccupancyGrid> BehaviorNode::path_grid(std::string* error) {
  const OccupancyGrid& grid = tracker_->grid();  // the obstacles and the doors known closed
  if (!pursued_constraints_ || pursued_constraints_->layers.empty()) {
    if (!path_grid_ || &path_grid_->raster() != &grid.raster()) path_grid_ = std::make_shared<const OccupancyGrid>(grid);
    return path_grid_;
  }
  const auto world =
      apply_constraints(doors_.apply(world_), *pursued_constraints_, options_.layers, error);
  if (!world) return nullptr;
  return std::make_shared<const OccupancyGrid>(*world, grid.geometry().resolution_m(),
                                               grid.inflation_radius_m());
}

void BehaviorNode::plan_path(const char* why) {
  const auto target = tracker_->target();
  if (!target || !state_) return;
  const double now_s = static_cast<double>(state_->sim_time_ns) * 1e-9;
  last_plan_s_ = now_s;
  std::string error;
  const auto grid = path_grid(&error);
  if (!grid) {
    follower_->clear();
    path_wanted_ = false;
    publish(tracker_->block("cannot plan a path: " + error));
    return;
  }
  PathRequest request;
  request.start = {state_->x, state_->y, state_->theta};
  request.goal = target->goal;
  request.budget_s = options_.path.budget_s;
  // The tracker's field for this goal, computed on the same cells (the tracker's grid, or the
  // constrained grid field_for and path_grid both build): not computed twice. A stored plan's field
  // was computed elsewhere (plan_tool, without door leaves): the planner computes its own then.
  if (!options_.plans) request.field = tracker_->field();
  PathResult result;
  try {
    OmplPathPlanner planner(grid, options_.path.ompl);
    result = planner.plan(request);
  } catch (
      const std::exception& e) {  // settings were checked at start; never stop the robot's service
    result.status = PathStatus::NotFound;
    result.reason = e.what();
  }
  if (result.found()) {
    follower_->follow(std::move(result.poses));
    follower_->set_goal_tolerance(
        std::min(options_.path.follower.pursuit.goal_tolerance_m, 0.5 * target->tolerance_m));
    path_wanted_ = false;
    spdlog::info("goal {} ({}): {} {} path of {:.2f} m in {:.1f} ms{}", target->id, why,
                 to_string(options_.path.ompl.curve), options_.path.ompl.planner, result.length_m,
                 result.planning_s * 1e3, result.route_guided ? " (route guide)" : "");
    return;
  }
  follower_->clear();
  if (result.status == PathStatus::StartBlocked) {
    // Pushed into the inflation margin (or spawned there): the grid controller escapes, then the
    // next tick plans again.
    // Once at info: the retries, every tick until the robot is out, at debug.
    const auto level = std::string_view(why) == "retry" ? spdlog::level::debug : spdlog::level::info;
    spdlog::log(level, "goal {} ({}): start in the margin, escaping before planning: {}", target->id, why,
                result.reason);
    return;
  }
  path_wanted_ = false;
  const std::vector<std::string> closed = doors_.closed();
  std::string reason =
      "no " + std::string(to_string(options_.path.ompl.curve)) + " path: " + result.reason;
  if (!closed.empty()) reason += " (" + describe_closed_doors(closed) + ")";
  publish(tracker_->block(std::move(reason)));
}

std::optional<VelocityCommand> BehaviorNode::follow_path(const geometry::Pose2& pose,
                                                         double now_s) {
  if (path_wanted_) plan_path("retry");
  if (!tracker_->active() || !follower_->has_path()) return std::nullopt;
  FollowStep step = follower_->step(pose, range_rays());
  if (step.outcome == FollowOutcome::Strayed &&
      now_s - last_plan_s_ >= options_.path.replan_interval_s) {
    spdlog::info("goal {}: {:.2f} m off the path; replanning", tracker_->target()->id,
                 step.off_path_m);
    plan_path("strayed");
    if (!tracker_->active() || !follower_->has_path()) return std::nullopt;
    step = follower_->step(pose, range_rays());
  }
  // At the path's end but not yet within the goal's tolerance: the grid controller finishes.
  if (step.outcome == FollowOutcome::Arrived || step.outcome == FollowOutcome::NoPath)
    return std::nullopt;
  return step.command;
}

std::vector<RangeRay> BehaviorNode::range_rays() const {
  std::vector<RangeRay> rays;
  // Only a scan of this tick or the previous one: an old scan would repel from where things were.
  if (!scan_ || !state_ || scan_->tick < state_->tick - 1) return rays;
  rays.reserve(scan_->ranges.size());
  for (std::size_t i = 0; i < scan_->ranges.size(); ++i) {
    const double range = static_cast<double>(scan_->ranges[i]);
    if (!std::isfinite(range)) continue;
    const double angle = scan_->angle_min + static_cast<double>(i) * scan_->angle_increment;
    if (map_obstacles_ && range < scan_->max_range) {
      const double a = state_->theta + angle;
      const geometry::Vec2 hit(state_->x + range * std::cos(a), state_->y + range * std::sin(a));
      const auto cell = map_obstacles_->geometry().cell_at(hit);
      if (!cell || map_obstacles_->blocked(*cell)) continue;  // a wall the path already keeps off
    }
    rays.push_back({angle, range, scan_->max_range});
  }
  return rays;
}

}  // namespace autonomy::behavior
