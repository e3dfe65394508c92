// BehaviorNode in goal mode: accepting goals (constraint sets, stored plans), the doors the robot
// saw, and one go-to command per tick (the grid field's controller, or a planned path followed by
// the tracking schema: goal_path.cpp).
#include "services/behavior/dds/behavior_node.hpp"

#include "common/msg/text_limits.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>

namespace autonomy::behavior {

void BehaviorNode::accept_goal(const msg::NavGoal& goal) {
  spdlog::info("goal {} for robot {}: ({:.2f}, {:.2f}) tolerance {} constraints '{}'",
               msg::clipped_for_log(goal.goal_id), goal.robot_id, goal.x, goal.y, goal.tolerance,
               msg::clipped_for_log(goal.constraint_set));
  const double now_s = lockstep_.clock().now_s();
  std::string error;
  auto problem = tracker_->validate(goal.goal_id, goal.x, goal.y, goal.tolerance);
  if (!problem) problem = msg::length_problem("constraint_set", goal.constraint_set, msg::kMaxTextLength);
  if (problem) {
    publish(tracker_->reject(goal.goal_id, goal.x, goal.y, *problem));
    return;
  }
  const auto set = parse_constraint_set(goal.constraint_set, &error);
  if (!set) {
    publish(tracker_->reject(goal.goal_id, goal.x, goal.y, error));
    return;
  }
  forget_waiting_robots();  // a new goal is not refused for robots that will move
  const OccupancyGrid& grid = tracker_->grid();
  const geometry::Vec2 target(goal.x, goal.y);
  // Stored plans were computed with every door open: only while no door is known closed.
  if (options_.plans && doors_.closed().empty()) {
    if (const StoredPlan* stored = options_.plans->match(target, set->name(), grid.geometry(), grid.inflation_radius_m())) {
      if (!stored->map_name.empty() && map_ && stored->map_name != map_->name) {
        spdlog::warn("stored plan '{}' was computed on map '{}', not '{}': computing instead", stored->name,
                     stored->map_name, map_->name);
      } else {
        spdlog::info("goal {}: using stored plan '{}' ({})", goal.goal_id, stored->name, stored->constraint_set);
        pursue(goal, *set, tracker_->set_goal(goal.goal_id, goal.x, goal.y, goal.tolerance, now_s, stored->field()));
        return;
      }
    }
  }
  if (set->layers.empty()) {
    pursue(goal, *set, tracker_->set_goal(goal.goal_id, goal.x, goal.y, goal.tolerance, now_s));
    return;
  }
  auto field = field_for(target, *set, &error);
  if (!field) {
    publish(tracker_->reject(goal.goal_id, goal.x, goal.y, error));
    return;
  }
  pursue(goal, *set, tracker_->set_goal(goal.goal_id, goal.x, goal.y, goal.tolerance, now_s, std::move(*field)));
}

bool BehaviorNode::resume_journalled_goals() {
  if (journalled_goals_.empty()) return false;
  const std::vector<JournalledGoal> goals = std::move(journalled_goals_);
  journalled_goals_.clear();
  // The newest goal still open is driven on; an older one still open lost the race to it (the
  // process died between journalling the new goal and publishing the old one's preemption).
  const auto newest_open = std::find_if(goals.rbegin(), goals.rend(), [](const JournalledGoal& g) { return g.open(); });
  if (newest_open == goals.rend()) {
    // Nothing to drive: the last goal to end is published again as it ended (goal_status is a
    // state topic; a reader that missed the end before the kill learns it now).
    const JournalledGoal& last = goals.back();
    spdlog::info("journal: goal {} had ended ({}); nothing to resume", last.goal.goal_id, to_string(*last.state));
    publish_outside_tracker(last.goal.goal_id, *last.state, last.reason);
    return true;
  }
  for (const JournalledGoal& g : goals)
    if (g.open() && g.seq < newest_open->seq)
      publish_outside_tracker(g.goal.goal_id, GoalState::Preempted, "preempted by goal " + newest_open->goal.goal_id);
  msg::NavGoal goal = newest_open->goal;
  goal.robot_id = options_.robot_id;
  // Taken at the first tick this process sees, not now: the world went on while no behavior ran,
  // and the clock here still shows where it was (the stall clock would count the outage).
  if (!newest_open->state) {  // arrived, never answered: taken as it would have been
    spdlog::info("journal: goal {} arrived before the restart; taking it at the next tick", goal.goal_id);
  } else {
    spdlog::info("journal: resuming goal {} ({} before the restart)", goal.goal_id, to_string(*newest_open->state));
    resuming_goal_ = goal.goal_id;
  }
  queued_goal_ = goal;
  return true;
}

void BehaviorNode::publish_outside_tracker(const std::string& goal_id, GoalState state, const std::string& reason) {
  GoalReport report;
  GoalStatus status;
  status.goal_id = goal_id;
  status.state = state;
  status.reason = reason;
  report.changes.push_back(std::move(status));
  publish(report);
}

void BehaviorNode::pursue(const msg::NavGoal& goal, const ConstraintSet& set, const GoalReport& accepted) {
  // A rejected goal leaves the pursued one running, and with it that goal's constraint set.
  const auto target = tracker_->target();
  if (target && target->id == goal.goal_id) pursued_constraints_ = set;
  GoalReport report = accepted;
  if (target && target->id == goal.goal_id && goal.goal_id == resuming_goal_) {
    // Accepted before the restart: not again. The next update publishes it Active, saying why.
    tracker_->note_resumed("resumed after a restart of behavior " + options_.robot_id + " (journal run " +
                           std::to_string(journal_->run()) + ")");
    report.changes.erase(std::remove_if(report.changes.begin(), report.changes.end(),
                                        [&](const GoalStatus& c) {
                                          return c.goal_id == goal.goal_id && c.state == GoalState::Accepted;
                                        }),
                         report.changes.end());
  }
  publish(report);
  if (follower_ && target && target->id == goal.goal_id) {
    follower_->clear();
    path_wanted_ = true;
    plan_path("new goal");
  }
}

std::optional<CostToGoField> BehaviorNode::field_for(const geometry::Vec2& target, const ConstraintSet& set,
                                                     std::string* error) const {
  const OccupancyGrid& grid = tracker_->grid();  // the obstacles and the doors known closed
  if (set.layers.empty()) return CostToGoField(grid, target);
  const auto world = apply_constraints(planning_world(), set, options_.layers, error);
  if (!world) return std::nullopt;
  const OccupancyGrid constrained(*world, grid.geometry().resolution_m(), grid.inflation_radius_m());
  return CostToGoField(constrained, target);
}

void BehaviorNode::update_door_knowledge(double now_s) {
  std::vector<DoorSighting> sightings;
  for (const auto& [id, angle] : door_sightings_) {
    const bool on_map =
        std::any_of(world_.doors.begin(), world_.doors.end(), [&](const Doorway& d) { return d.id == id; });
    if (on_map)
      sightings.push_back({id, angle});
    else if (unknown_doors_.insert(id).second)
      spdlog::warn("robot {} sees door '{}', which the map does not have; ignored", options_.robot_id, id);
  }
  door_sightings_.clear();
  if (!doors_.update(sightings, now_s, world_)) return;
  if (follower_) update_map_obstacles();
  const std::vector<std::string> closed = doors_.closed();
  spdlog::info("robot {}: {}; replanning", options_.robot_id, describe_closed_doors(closed));
  const OccupancyGrid& old = tracker_->grid();
  tracker_->set_grid(OccupancyGrid(planning_world(), old.geometry().resolution_m(), old.inflation_radius_m()),
                     planning_closures());
  const auto target = tracker_->target();
  if (!target || !pursued_constraints_) return;
  std::string error;
  auto field = field_for(target->goal, *pursued_constraints_, &error);
  if (!field) {  // the layers were known when the goal was accepted; keep the current route
    spdlog::warn("goal {}: cannot replan: {}", target->id, error);
    return;
  }
  publish(tracker_->replan(std::move(*field), now_s));
  if (follower_ && tracker_->active()) {
    path_wanted_ = true;
    plan_path(closed.empty() ? "doors open again" : "door knowledge changed");
  }
}

uint32_t BehaviorNode::control_goal(int64_t tick) {
  const geometry::Pose2 pose{state_->x, state_->y, state_->theta};
  const double now_s = static_cast<double>(state_->sim_time_ns) * 1e-9;
  // What the robot saw this tick first, so that a goal is judged on the doors as they are now.
  update_door_knowledge(now_s);
  publish(tracker_->update(pose, now_s, state_->in_collision));

  // Fleet traffic: a narrow passage held by another robot, or robots to plan around.
  const auto traffic_command = traffic_step(pose, now_s);
  publish_itinerary(now_s, tick);
  if (traffic_command && tracker_->active()) {
    send_command(brake_for_robots(pose, *traffic_command), tick);
    return 1;
  }
  if (tracker_->active() && follower_) {
    if (const auto command = follow_path(pose, now_s)) {
      send_command(brake_for_robots(pose, *command), tick);
      return 1;
    }
  }
  if (tracker_->active()) {
    const GoToDecision decision = controller_->command(pose, *tracker_->field(), tracker_->tolerance_m());
    send_command(brake_for_robots(pose, decision.command), tick);
    return 1;
  }
  if (follower_) follower_->clear();
  if (!stopped_robot_) {
    send_command({}, tick);  // the goal ended: stop now rather than when the command expires
    return 1;
  }
  return 0;
}

}  // namespace autonomy::behavior
