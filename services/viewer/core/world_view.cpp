#include "services/viewer/core/world_view.hpp"

#include <algorithm>
#include <cmath>

namespace autonomy::viewer {

namespace {

bool job_ended(msg::JobState s) {
  return s == msg::JobState::Completed || s == msg::JobState::Failed || s == msg::JobState::Cancelled ||
         s == msg::JobState::Stranded;
}

}  // namespace

void WorldView::apply(const msg::WorldMap& map) {
  map_ = map;
  ++map_version_;
  ++state_version_;  // door leaves are drawn from the map's doorways
}

RobotView& WorldView::robot(const std::string& robot_id) {
  auto [it, added] = robots_.try_emplace(robot_id);
  if (added) it->second.state.robot_id = robot_id;
  return it->second;
}

void WorldView::apply(const msg::RobotState& state) {
  RobotView& r = robot(state.robot_id);
  // The state topic keeps one sample per robot; an older tick (another writer, a reordering)
  // would move the robot back in time.
  if (r.has_state && state.tick < r.state.tick) return;
  r.state = state;
  r.has_state = true;
  const bool far_enough =
      r.trail.empty() ||
      std::hypot(state.x - r.trail.back().x, state.y - r.trail.back().y) >= limits_.trail_spacing_m;
  if (far_enough) {
    r.trail.push_back({state.x, state.y});
    while (r.trail.size() > limits_.trail_points) r.trail.pop_front();
  }
  sim_time_ns_ = std::max(sim_time_ns_, state.sim_time_ns);
  tick_ = std::max(tick_, state.tick);
  ++state_version_;
}

void WorldView::remove_robot(const std::string& robot_id) {
  if (robots_.erase(robot_id) > 0) ++state_version_;
}

void WorldView::apply(const msg::DoorState& door) {
  doors_[door.door_id] = door;
  ++state_version_;
}

void WorldView::apply(const msg::NavGoal& goal) {
  RobotView& r = robot(goal.robot_id);
  GoalView g;
  g.goal_id = goal.goal_id;
  g.has_position = true;
  g.x = goal.x;
  g.y = goal.y;
  // The status of this goal may have come first (statuses are state samples, goals commands).
  if (r.goal && r.goal->goal_id == goal.goal_id && r.goal->has_status) {
    g.has_status = true;
    g.state = r.goal->state;
    g.reason = r.goal->reason;
    g.distance_to_goal = r.goal->distance_to_goal;
  }
  r.goal = g;
  ++state_version_;
}

void WorldView::apply(const msg::GoalStatus& status) {
  RobotView& r = robot(status.robot_id);
  if (!r.goal || r.goal->goal_id != status.goal_id) {
    r.goal = GoalView{};
    r.goal->goal_id = status.goal_id;
  }
  r.goal->has_status = true;
  r.goal->state = status.state;
  r.goal->reason = status.reason;
  r.goal->distance_to_goal = status.distance_to_goal;
  ++state_version_;
}

void WorldView::apply(const msg::Itinerary& itinerary) {
  robot(itinerary.robot_id).itinerary = itinerary;
  ++state_version_;
}

void WorldView::apply(const msg::RadioLink& link) {
  links_[{link.robot_a, link.robot_b}] = link;
  ++state_version_;
}

void WorldView::apply(const msg::CourierJobStatus& job) {
  auto [it, added] = jobs_.try_emplace(job.job_id);
  JobView& v = it->second;
  if (added) v.first_seen = ++jobs_seen_;
  const bool changed = v.history.empty() || v.history.back().state != job.state || v.history.back().phase != job.phase;
  if (changed) {
    v.history.push_back({job.state, job.phase, job.tick});
    if (v.history.size() > limits_.job_history) v.history.erase(v.history.begin());
  }
  v.latest = job;
  if (added && jobs_.size() > limits_.max_jobs) forget_oldest_ended_job();
  ++state_version_;
}

void WorldView::forget_oldest_ended_job() {
  auto oldest = jobs_.end();
  for (auto it = jobs_.begin(); it != jobs_.end(); ++it) {
    if (job_ended(it->second.latest.state) && (oldest == jobs_.end() || it->second.first_seen < oldest->second.first_seen))
      oldest = it;
  }
  if (oldest != jobs_.end()) jobs_.erase(oldest);
}

}  // namespace autonomy::viewer
