#include "services/behavior/core/goal_tracker.hpp"

#include "common/msg/text_limits.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <utility>

namespace autonomy::behavior {

namespace {

void require_same_geometry(const GridGeometry& a, const GridGeometry& b, const char* what) {
  if (a.cols() != b.cols() || a.rows() != b.rows() || a.resolution_m() != b.resolution_m())
    throw std::invalid_argument(std::string(what) + " geometry differs from the tracker's grid");
}

bool positive_finite_setting(double v) { return std::isfinite(v) && v > 0.0; }

template <typename... Args>
std::string format(const char* fmt, Args... args) {
  char buffer[256];
  std::snprintf(buffer, sizeof buffer, fmt, args...);
  return buffer;
}

}  // namespace

GoalTracker::GoalTracker(OccupancyGrid grid, GoalTrackerConfig config)
    : grid_(std::move(grid)), config_(config) {
  if (!positive_finite_setting(config.default_tolerance_m) || !positive_finite_setting(config.stall_timeout_s) ||
      !positive_finite_setting(config.min_progress_m) || !std::isfinite(config.collision_timeout_s) ||
      config.collision_timeout_s < 0.0 ||
      !std::isfinite(config.route_search_radius_m) ||
      config.route_search_radius_m < 0.0) {
    throw std::invalid_argument("goal tracker parameters must be positive and finite");
  }
}

std::optional<std::string> GoalTracker::validate(const std::string& goal_id, double x, double y,
                                                double tolerance_m) const {
  std::string rejection;
  if (goal_id.empty()) {
    rejection = "goal id is empty";
  } else if (auto too_long = msg::length_problem("goal_id", goal_id, msg::kMaxIdLength)) {
    rejection = std::move(*too_long);
  } else if (!std::isfinite(x) || !std::isfinite(y)) {
    rejection = "goal coordinates are not finite";
  } else if (std::isnan(tolerance_m) || std::isinf(tolerance_m)) {
    rejection = "goal tolerance is not finite";
  } else if (tolerance_m < 0.0) {
    rejection = format("goal tolerance %.3f m is negative (0 means the controller's default)", tolerance_m);
  } else if (!grid_.inside_world(geometry::Vec2(x, y))) {
    rejection = format("goal (%.2f, %.2f) is outside the world [0, %.2f] x [0, %.2f]", x, y,
                       grid_.width_m(), grid_.height_m());
  }
  if (rejection.empty()) return std::nullopt;
  return rejection;
}

GoalReport GoalTracker::rejected(const std::string& goal_id, const geometry::Vec2& goal, std::string reason) {
  GoalReport report;
  // An overlong id is echoed cut to the limit: the sender still recognises its goal.
  report.changes.push_back(make_status(msg::clipped_id(goal_id), GoalState::Rejected, std::move(reason), goal));
  // A rejected goal becomes "the latest goal" only when nothing is being pursued.
  if (!pursued_) status_ = report.changes.back();
  report.current = status_;
  return report;
}

GoalReport GoalTracker::pursue(const std::string& goal_id, const geometry::Vec2& goal, double tolerance_m,
                               double now_s, CostToGoField field) {
  GoalReport report;
  if (pursued_) end_pursuit(GoalState::Preempted, "preempted by goal " + goal_id, report);
  const double tolerance = tolerance_m > 0.0 ? tolerance_m : config_.default_tolerance_m;
  pursued_.emplace(Pursuit{goal_id, goal, tolerance, std::move(field),
                           std::numeric_limits<double>::infinity(), now_s, std::nullopt});
  status_ = make_status(goal_id, GoalState::Accepted, "", goal);
  report.changes.push_back(*status_);
  report.current = status_;
  return report;
}

GoalReport GoalTracker::set_goal(const std::string& goal_id, double x, double y, double tolerance_m,
                                 double now_s) {
  const geometry::Vec2 goal(x, y);
  if (auto rejection = validate(goal_id, x, y, tolerance_m)) return rejected(goal_id, goal, std::move(*rejection));
  return pursue(goal_id, goal, tolerance_m, now_s, CostToGoField(grid_, goal));
}

GoalReport GoalTracker::set_goal(const std::string& goal_id, double x, double y, double tolerance_m,
                                 double now_s, CostToGoField field) {
  const geometry::Vec2 goal(x, y);
  if (auto rejection = validate(goal_id, x, y, tolerance_m)) return rejected(goal_id, goal, std::move(*rejection));
  require_same_geometry(field.geometry(), grid_.geometry(), "goal field");
  return pursue(goal_id, goal, tolerance_m, now_s, std::move(field));
}

void GoalTracker::set_grid(OccupancyGrid grid, std::string closures) {
  require_same_geometry(grid.geometry(), grid_.geometry(), "new grid");
  grid_ = std::move(grid);
  closures_ = std::move(closures);
}

std::string GoalTracker::no_route_reason(const geometry::Vec2& goal) const {
  return format("no route to goal (%.2f, %.2f)", goal.x(), goal.y()) + (closures_.empty() ? "" : ": " + closures_);
}

std::optional<GoalTracker::Target> GoalTracker::target() const {
  if (!pursued_) return std::nullopt;
  return Target{pursued_->id, pursued_->goal, pursued_->tolerance_m};
}

GoalReport GoalTracker::replan(CostToGoField field, double now_s) {
  GoalReport report;
  if (pursued_) {
    require_same_geometry(field.geometry(), grid_.geometry(), "replanned field");
    Pursuit& p = *pursued_;
    p.field = std::move(field);
    const double remaining =
        last_position_ ? remaining_path_m(p, *last_position_) : std::numeric_limits<double>::infinity();
    const bool arrived = last_position_ && (p.goal - *last_position_).norm() <= p.tolerance_m;
    if (last_position_ && !arrived && !std::isfinite(remaining)) {
      end_pursuit(GoalState::Blocked, no_route_reason(p.goal), report);
    } else {
      p.best_remaining_m = remaining;
      p.last_progress_s = now_s;
    }
  }
  report.current = status_;
  return report;
}

GoalReport GoalTracker::reject(const std::string& goal_id, double x, double y, std::string reason) {
  return rejected(goal_id, geometry::Vec2(x, y), std::move(reason));
}

GoalReport GoalTracker::block(std::string reason) {
  GoalReport report;
  if (pursued_) end_pursuit(GoalState::Blocked, std::move(reason), report);
  report.current = status_;
  return report;
}

void GoalTracker::note_resumed(std::string note) {
  if (pursued_ && status_ && status_->state == GoalState::Accepted) status_->reason = std::move(note);
}

GoalReport GoalTracker::wait(std::string why, double now_s) {
  GoalReport report;
  if (pursued_ && status_ && status_->state == GoalState::Active) {
    pursued_->waiting = true;
    pursued_->last_progress_s = now_s;
    if (status_->reason != why) {
      status_->reason = std::move(why);
      report.changes.push_back(*status_);
    }
  }
  report.current = status_;
  return report;
}

GoalReport GoalTracker::proceed(double now_s) {
  GoalReport report;
  if (pursued_ && pursued_->waiting) {
    pursued_->waiting = false;
    pursued_->last_progress_s = now_s;
    pursued_->best_remaining_m = std::numeric_limits<double>::infinity();  // it may have stepped aside
    if (status_ && !status_->reason.empty()) {
      status_->reason.clear();
      report.changes.push_back(*status_);
    }
  }
  report.current = status_;
  return report;
}

GoalReport GoalTracker::cancel(const std::string& goal_id, std::string reason) {
  GoalReport report;
  if (pursued_ && (goal_id.empty() || goal_id == pursued_->id)) {
    end_pursuit(GoalState::Cancelled, reason.empty() ? std::string("cancelled") : std::move(reason), report);
  }
  report.current = status_;
  return report;
}

GoalReport GoalTracker::update(const geometry::Pose2& pose, double now_s, bool in_collision) {
  GoalReport report;
  if (!std::isfinite(pose.x) || !std::isfinite(pose.y)) {
    report.current = status_;
    return report;
  }
  const geometry::Vec2 position = pose.position();
  last_position_ = position;
  if (!pursued_) {
    report.current = status_;
    return report;
  }

  Pursuit& p = *pursued_;
  const double distance = (p.goal - position).norm();
  status_->distance_to_goal = distance;

  if (status_->state == GoalState::Accepted) {
    const double remaining = remaining_path_m(p, position);
    if (distance > p.tolerance_m && !std::isfinite(remaining)) {
      end_pursuit(GoalState::Blocked, no_route_reason(p.goal), report);
      report.current = status_;
      return report;
    }
    status_->state = GoalState::Active;
    report.changes.push_back(*status_);
    p.best_remaining_m = remaining;
    // The stall clock started at acceptance: a robot that never moves fails stall_timeout_s after
    // the goal arrived, however late the first pose came.
  }

  if (distance <= p.tolerance_m) {
    end_pursuit(GoalState::Reached, "", report);
    report.current = status_;
    return report;
  }

  if (!in_collision || config_.collision_timeout_s <= 0.0) {
    p.collision_since_s.reset();
  } else if (!p.collision_since_s) {
    p.collision_since_s = now_s;
  } else if (now_s - *p.collision_since_s >= config_.collision_timeout_s) {
    end_pursuit(GoalState::Blocked,
                format("in collision for %.1f s, %.1f m from goal", config_.collision_timeout_s, distance), report);
    report.current = status_;
    return report;
  }

  const double remaining = remaining_path_m(p, position);
  if (p.waiting) {
    p.last_progress_s = now_s;  // waiting for a passage is no stall (wait() bounds it)
  } else if (remaining <= p.best_remaining_m - config_.min_progress_m ||
      (std::isinf(p.best_remaining_m) && std::isfinite(remaining))) {
    p.best_remaining_m = remaining;
    p.last_progress_s = now_s;
  } else if (now_s - p.last_progress_s >= config_.stall_timeout_s) {
    end_pursuit(GoalState::Blocked,
                format("no progress for %.1f s, %.1f m from goal", config_.stall_timeout_s, distance),
                report);
  }
  report.current = status_;
  return report;
}

GoalStatus GoalTracker::make_status(const std::string& id, GoalState state, std::string reason,
                                    const geometry::Vec2& goal) const {
  GoalStatus s;
  s.goal_id = id;
  s.state = state;
  s.reason = std::move(reason);
  if (last_position_ && std::isfinite(goal.x()) && std::isfinite(goal.y())) {
    s.distance_to_goal = (goal - *last_position_).norm();
  }
  return s;
}

// Path cost from the robot's position: the field at its cell, or, when the robot sits in the
// inflation margin, the way out to the nearest reachable cell plus that cell's cost.
double GoalTracker::remaining_path_m(const Pursuit& p, const geometry::Vec2& position) const {
  const float here = p.field.cost_at(position);
  if (std::isfinite(here)) return here;
  const auto refuge = p.field.nearest_reachable(position, config_.route_search_radius_m);
  if (!refuge) return std::numeric_limits<double>::infinity();
  return p.field.cost(*refuge) + (p.field.geometry().centre(*refuge) - position).norm();
}

void GoalTracker::end_pursuit(GoalState state, std::string reason, GoalReport& report) {
  status_ = make_status(pursued_->id, state, std::move(reason), pursued_->goal);
  report.changes.push_back(*status_);
  pursued_.reset();
}

}  // namespace autonomy::behavior
