#include "services/behavior/dds/behavior_node.hpp"

#include <spdlog/spdlog.h>

#include <cmath>
#include <unistd.h>

namespace autonomy::behavior {

namespace {

constexpr auto kSpawnRetryPeriod = std::chrono::milliseconds(500);

msg::GoalState to_msg(GoalState s) {
  switch (s) {
    case GoalState::Accepted: return msg::GoalState::Accepted;
    case GoalState::Active: return msg::GoalState::Active;
    case GoalState::Reached: return msg::GoalState::Reached;
    case GoalState::Failed: return msg::GoalState::Failed;
    case GoalState::Preempted: return msg::GoalState::Preempted;
    case GoalState::Rejected: return msg::GoalState::Rejected;
  }
  return msg::GoalState::Failed;
}

}  // namespace

BehaviorNode::BehaviorNode(service::Service& service, BehaviorNodeOptions options)
    : service_(service),
      options_(std::move(options)),
      participant_name_("behavior/" + options_.robot_id),
      state_topic_(service.participant(), dds::topics::robot_state),
      map_topic_(service.participant(), dds::topics::world_map),
      goal_topic_(service.participant(), dds::topics::nav_goal),
      goal_status_topic_(service.participant(), dds::topics::goal_status),
      cmd_topic_(service.participant(), dds::topics::cmd_vel),
      spawn_request_topic_(service.participant(), dds::topics::spawn_request),
      spawn_reply_topic_(service.participant(), dds::topics::spawn_reply),
      state_reader_(service.participant(), state_topic_),
      map_reader_(service.participant(), map_topic_),
      goal_reader_(service.participant(), goal_topic_),
      spawn_reply_reader_(service.participant(), spawn_reply_topic_),
      goal_status_writer_(service.participant(), goal_status_topic_),
      cmd_writer_(service.participant(), cmd_topic_),
      spawn_request_writer_(service.participant(), spawn_request_topic_),
      lockstep_(service.participant(), service.loop(), participant_name_,
                [this](const msg::SimClock& c) { on_tick(c); }) {
  spawn_request_id_ = options_.robot_id + "@" + std::to_string(getpid());
  auto& loop = service.loop();
  loop.on_samples<msg::SpawnReply>(spawn_reply_reader_, [this](auto s) { on_spawn_replies(std::move(s)); });
  loop.on_samples<msg::RobotState>(state_reader_, [this](auto s) { on_states(std::move(s)); });
  loop.on_samples<msg::WorldMap>(map_reader_, [this](auto s) { on_map(std::move(s)); });
  loop.on_samples<msg::NavGoal>(goal_reader_, [this](auto s) { on_goals(std::move(s)); });
  // Requests are volatile: one written before the simulator's reader matched is lost, so the
  // request is repeated until a reply comes (the simulator treats repeats as re-attaches).
  loop.every(kSpawnRetryPeriod, [this] {
    if (!spawned_) request_spawn();
  });
  lockstep_.register_participant();
  request_spawn();
}

void BehaviorNode::request_spawn() {
  if (spawn_request_writer_.matched_readers() == 0) return;
  msg::SpawnRequest r;
  r.request_id = spawn_request_id_;
  r.requester = participant_name_;
  r.robot_id = options_.robot_id;
  if (options_.start) {
    r.has_pose = true;
    r.x = options_.start->x;
    r.y = options_.start->y;
    r.theta = options_.start->theta;
  }
  spawn_request_writer_.write(r);
}

void BehaviorNode::on_spawn_replies(std::vector<dds::Sample<msg::SpawnReply>> samples) {
  for (const auto& s : samples) {
    if (!s.valid || s.value.request_id != spawn_request_id_ || spawned_) continue;
    if (s.value.status == msg::RequestStatus::Accepted) {
      spawned_ = true;
      spdlog::info("robot {} attached to the simulator", options_.robot_id);
      become_ready_when_possible();
    } else {
      service_.fail("simulator refused robot " + options_.robot_id + ": " + s.value.reason);
    }
  }
}

void BehaviorNode::on_states(std::vector<dds::Sample<msg::RobotState>> samples) {
  for (auto& s : samples) {
    if (!s.valid || s.value.robot_id != options_.robot_id) continue;
    if (!state_ || s.value.tick >= state_->tick) state_ = std::move(s.value);
  }
  become_ready_when_possible();
  control_pending_tick();
}

void BehaviorNode::on_map(std::vector<dds::Sample<msg::WorldMap>> samples) {
  for (auto& s : samples)
    if (s.valid) map_ = std::move(s.value);
  become_ready_when_possible();
}

void BehaviorNode::become_ready_when_possible() {
  if (tracker_ || !spawned_ || !state_ || !map_) return;
  const msg::RobotState& st = *state_;
  WorldMap world{map_->width, map_->height, map_->obstacles};
  // The grid keeps the robot's centre one resolution step further from obstacles than its
  // radius, so that rounding to cells never plans a path that grazes a wall.
  OccupancyGrid grid(world, options_.grid_resolution_m, st.radius + options_.grid_resolution_m);
  tracker_.emplace(std::move(grid), options_.tracker);
  controller_.emplace(st.kinematics == msg::Kinematics::Holonomic ? Kinematics::Holonomic : Kinematics::Unicycle,
                      MotionLimits{st.max_speed, st.max_omega}, options_.go_to);
  spdlog::info("robot {} ready at ({:.2f}, {:.2f}) on map '{}'", options_.robot_id, st.x, st.y, map_->name);
  service_.set_ready();
  if (options_.initial_goal) queued_goal_ = options_.initial_goal;
  if (queued_goal_) {
    accept_goal(*queued_goal_);
    queued_goal_.reset();
  }
  control_pending_tick();
}

void BehaviorNode::on_goals(std::vector<dds::Sample<msg::NavGoal>> samples) {
  for (const auto& s : samples) {
    if (!s.valid || s.value.robot_id != options_.robot_id) continue;
    if (tracker_)
      accept_goal(s.value);
    else
      queued_goal_ = s.value;  // the newest goal waits for the map and the robot
  }
}

void BehaviorNode::accept_goal(const msg::NavGoal& goal) {
  spdlog::info("goal {} for robot {}: ({:.2f}, {:.2f}) tolerance {}", goal.goal_id, goal.robot_id, goal.x, goal.y,
               goal.tolerance);
  publish(tracker_->set_goal(goal.goal_id, goal.x, goal.y, goal.tolerance, lockstep_.clock().now_s()));
}

void BehaviorNode::on_tick(const msg::SimClock& clock) {
  // Until the robot is attached and the map known, the tick stays unanswered: the world waits
  // (up to the ack timeout) so that a run starts identically however slow this process is.
  pending_tick_ = clock.tick;
  control_pending_tick();
}

void BehaviorNode::control_pending_tick() {
  if (!pending_tick_ || !tracker_ || !state_ || state_->tick < *pending_tick_) return;
  const int64_t tick = *pending_tick_;
  pending_tick_.reset();

  const geometry::Pose2 pose{state_->x, state_->y, state_->theta};
  const double now_s = static_cast<double>(state_->sim_time_ns) * 1e-9;
  publish(tracker_->update(pose, now_s));

  uint32_t sent = 0;
  if (tracker_->active()) {
    const GoToDecision decision = controller_->command(pose, *tracker_->field(), tracker_->tolerance_m());
    send_command(decision.command, tick);
    ++sent;
  } else if (!stopped_robot_) {
    send_command({}, tick);  // the goal ended: stop now rather than when the command expires
    ++sent;
  }
  lockstep_.acknowledge(tick, sent);
}

void BehaviorNode::send_command(const VelocityCommand& command, int64_t tick) {
  cmd_writer_.write({options_.robot_id, participant_name_, tick, command.vx, command.vy, command.omega});
  stopped_robot_ = command.is_zero();
}

void BehaviorNode::publish(const GoalReport& report) {
  for (const GoalStatus& change : report.changes) {
    msg::GoalStatus s{options_.robot_id, change.goal_id, to_msg(change.state), change.reason,
                      state_ ? state_->tick : 0, change.distance_to_goal};
    if (change.state == GoalState::Failed || change.state == GoalState::Rejected)
      spdlog::warn("goal {} {}: {}", change.goal_id, to_string(change.state), change.reason);
    else
      spdlog::info("goal {} {} ({:.2f} m to go)", change.goal_id, to_string(change.state), change.distance_to_goal);
    goal_status_writer_.write(s);
  }
}

}  // namespace autonomy::behavior
