#pragma once
// The navigation-goal lifecycle of one robot: validates new goals, owns the cost-to-go field of the
// goal being pursued, and decides when that goal is reached, failed or preempted. It does not move
// the robot: the node asks GoToController for a command using field() while active() holds.
//
// Every call returns the transitions it caused, in order, so the node can publish each one
// (accepted -> active -> reached arrive as three samples, never collapsed into the last).
// Time is an argument (seconds on the caller's clock, simulated or wall); the tracker keeps none.
//
// Policies:
//  - A malformed goal is Rejected and the goal being pursued carries on (as a ROS action server
//    rejects a bad request without aborting the running one).
//  - A valid new goal preempts the pursued one, whatever its id: [old Preempted, new Accepted].
//  - A goal becomes Active on the first update() after set_goal(); it Fails right there instead when
//    its cell is blocked or the robot's position has no route to it.
//  - Progress is measured on the field's path cost, not the straight distance, so going around a
//    wall counts as progress. No decrease of at least min_progress_m for stall_timeout_s -> Blocked.
//  - A robot reported in collision (RobotState.in_collision) for collision_timeout_s without a
//    break -> Blocked ("in collision for ..."): something (a closed door, a robot) is in the way.
//    Off by default (0): then a door that stays closed ends the goal through the stall rule.
//  - cancel() ends the pursued goal as Cancelled (only when the id matches, or for an empty id);
//    the node then stops the robot. Cancelling a goal that is not pursued changes nothing.
//  - A goal may come with its own field (a stored plan, a plan honouring constraint layers) instead
//    of the one computed on grid(); it must share grid()'s geometry.
#include "common/geometry/geometry.hpp"
#include "services/behavior/core/cost_to_go_field.hpp"
#include "services/behavior/core/goal_status.hpp"
#include "services/behavior/core/occupancy_grid.hpp"

#include <optional>
#include <string>
#include <vector>

namespace autonomy::behavior {

struct GoalTrackerConfig {
  double default_tolerance_m = 0.2;  // for goals that ask for tolerance <= 0 (NavGoal allows it)
  double stall_timeout_s = 10.0;
  double min_progress_m = 0.1;  // smaller decreases of the remaining path are noise, not progress
  // How far from the robot a reachable cell may be for the robot to count as having a route; keep
  // it equal to GoToConfig::lookahead_m, the distance the controller will escape over.
  double route_search_radius_m = 1.0;
  // Continuously in collision this long -> Blocked; 0 (default) disables it, so a robot held by a
  // closed door keeps pushing until the door opens or stall_timeout_s ends the goal.
  double collision_timeout_s = 0.0;
};

struct GoalReport {
  std::optional<GoalStatus> current;  // the pursued goal, else the last one to end; nullopt before any
  std::vector<GoalStatus> changes;    // transitions caused by this call, in order; publish each
};

class GoalTracker {
 public:
  // Throws std::invalid_argument on non-positive or non-finite config values.
  explicit GoalTracker(OccupancyGrid grid, GoalTrackerConfig config = {});

  // tolerance_m <= 0 means config.default_tolerance_m. Computes the field for a valid goal.
  [[nodiscard]] GoalReport set_goal(const std::string& goal_id, double x, double y,
                                    double tolerance_m, double now_s);
  // The same with a ready field (stored or computed with constraint layers). Throws
  // std::invalid_argument when its geometry differs from grid()'s.
  [[nodiscard]] GoalReport set_goal(const std::string& goal_id, double x, double y,
                                    double tolerance_m, double now_s, CostToGoField field);

  // What the robot knows of the world changed (a door seen closed or open again): later goals are
  // planned on `grid`. `closures` says what blocks it beyond the map ("door d1 closed"; "" for
  // nothing) and ends every "no route to goal (x, y)" reason from now on. Throws
  // std::invalid_argument when its geometry differs from grid()'s.
  void set_grid(OccupancyGrid grid, std::string closures = "");
  // The pursued goal's route changed: follow `field` from now on (same geometry as grid()). When
  // the robot's last position has no route on it, the goal ends Blocked ("no route to goal (x, y)"
  // and the closures); otherwise the stall clock restarts (a detour is progress anew). Without a
  // pursued goal nothing changes.
  [[nodiscard]] GoalReport replan(CostToGoField field, double now_s);
  // The pursued goal: its id, target and effective tolerance, to replan it.
  struct Target {
    std::string id;
    geometry::Vec2 goal;
    double tolerance_m = 0.0;
  };
  std::optional<Target> target() const;

  // Why a goal cannot be pursued (empty or overlong id, non-finite or outside the world, negative
  // tolerance), or nothing. set_goal() checks it too; the node asks first so that it computes no
  // field for a goal it will reject.
  std::optional<std::string> validate(const std::string& goal_id, double x, double y, double tolerance_m) const;

  // Rejects a goal for a reason found outside the tracker (e.g. an unknown constraint set), with
  // the same policy as a malformed goal: the pursued goal carries on.
  [[nodiscard]] GoalReport reject(const std::string& goal_id, double x, double y, std::string reason);

  // Ends the pursued goal Blocked for a reason found outside the tracker (a path planner found no
  // path within its budget). Without a pursued goal nothing changes.
  [[nodiscard]] GoalReport block(std::string reason);

  // The pursued goal was pursued before a restart of this process (behavior --journal): it was
  // accepted then, so its next transition (Active, on the next update) carries `note` as its
  // reason, saying so. Only while the pursued goal is still Accepted; otherwise nothing changes.
  void note_resumed(std::string note);

  // The pursued goal waits for a narrow passage (traffic, docs/traffic.md): it is published Active
  // again with `why` as its reason ("waiting for r2 to clear doorway A-114"; once per new reason),
  // and waiting is no stall: the stall clock stands still until proceed(). Only while Active.
  [[nodiscard]] GoalReport wait(std::string why, double now_s);
  // The wait is over: Active again with an empty reason; progress is judged afresh from now.
  [[nodiscard]] GoalReport proceed(double now_s);
  bool waiting() const { return pursued_ && pursued_->waiting; }

  // Cancels the pursued goal when goal_id is empty or names it: [Cancelled]. Otherwise no change.
  [[nodiscard]] GoalReport cancel(const std::string& goal_id, std::string reason);

  // Feeds the robot's pose at now_s. A non-finite pose changes nothing. in_collision: the
  // simulator stopped the last commanded motion (RobotState.in_collision).
  [[nodiscard]] GoalReport update(const geometry::Pose2& pose, double now_s, bool in_collision = false);

  // A goal is Accepted or Active: the node should drive the robot with field().
  bool active() const { return pursued_.has_value(); }
  // The field of the pursued goal; nullptr when none is pursued.
  const CostToGoField* field() const { return pursued_ ? &pursued_->field : nullptr; }
  // Effective tolerance of the pursued goal (0 when none).
  double tolerance_m() const { return pursued_ ? pursued_->tolerance_m : 0.0; }
  const std::optional<GoalStatus>& status() const { return status_; }
  const OccupancyGrid& grid() const { return grid_; }
  const GoalTrackerConfig& config() const { return config_; }

 private:
  struct Pursuit {
    std::string id;
    geometry::Vec2 goal;
    double tolerance_m;
    CostToGoField field;
    double best_remaining_m;  // least path cost seen so far (+inf before activation)
    double last_progress_s;   // when best_remaining_m last dropped by min_progress_m
    std::optional<double> collision_since_s;  // start of the current run of collisions
    bool waiting = false;                     // wait(): the stall clock stands still
  };

  GoalReport rejected(const std::string& goal_id, const geometry::Vec2& goal, std::string reason);
  GoalReport pursue(const std::string& goal_id, const geometry::Vec2& goal, double tolerance_m,
                    double now_s, CostToGoField field);

  GoalStatus make_status(const std::string& id, GoalState state, std::string reason,
                         const geometry::Vec2& goal) const;
  double remaining_path_m(const Pursuit& p, const geometry::Vec2& position) const;
  void end_pursuit(GoalState state, std::string reason, GoalReport& report);
  std::string no_route_reason(const geometry::Vec2& goal) const;

  OccupancyGrid grid_;
  std::string closures_;  // what blocks grid_ beyond the map, for reasons
  GoalTrackerConfig config_;
  std::optional<Pursuit> pursued_;
  std::optional<GoalStatus> status_;
  std::optional<geometry::Vec2> last_position_;
};

}  // namespace autonomy::behavior
