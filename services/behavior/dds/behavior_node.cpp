#include "services/behavior/dds/behavior_node.hpp"

#include "common/msg/text_limits.hpp"

#include "services/behavior/core/mission/plan_library.hpp"

#include <spdlog/spdlog.h>

#include <cmath>
#include <functional>
#include <unistd.h>

namespace autonomy::behavior {

namespace {

constexpr auto kSpawnRetryPeriod = std::chrono::milliseconds(500);

msg::GoalState to_msg(GoalState s) {
  switch (s) {
    case GoalState::Accepted: return msg::GoalState::Accepted;
    case GoalState::Active: return msg::GoalState::Active;
    case GoalState::Reached: return msg::GoalState::Reached;
    case GoalState::Blocked: return msg::GoalState::Blocked;
    case GoalState::Preempted: return msg::GoalState::Preempted;
    case GoalState::Rejected: return msg::GoalState::Rejected;
    case GoalState::Cancelled: return msg::GoalState::Cancelled;
  }
  return msg::GoalState::Blocked;
}

const char* event_name(MissionEvent::Kind k) {
  switch (k) {
    case MissionEvent::Kind::Started: return "started";
    case MissionEvent::Kind::Transition: return "transition";
    case MissionEvent::Kind::PlanChosen: return "plan_chosen";
    case MissionEvent::Kind::NoViablePlan: return "no_viable_plan";
    case MissionEvent::Kind::Finished: return "finished";
  }
  return "?";
}

// The map sample as the planner's world. Shapes another process got wrong (a crossing polygon,
// a raster whose cells do not add up) are left out with a warning rather than stopping the robot.
WorldMap world_of(const msg::WorldMap& m) {
  WorldMap w{m.width, m.height, {}, {}, {}, {}};
  for (const auto& r : m.obstacles) {
    if (r.valid() && std::isfinite(r.min_x) && std::isfinite(r.min_y) && std::isfinite(r.max_x) &&
        std::isfinite(r.max_y)) {
      w.obstacles.push_back(r);
    } else {
      spdlog::warn("map '{}': obstacle rectangle ({}, {})-({}, {}) is not valid; ignored", m.name, r.min_x, r.min_y,
                   r.max_x, r.max_y);
    }
  }
  for (const auto& p : m.polygons) {
    geometry::Polygon polygon{p.name, {}};
    for (const auto& v : p.vertices) polygon.vertices.emplace_back(v.x, v.y);
    if (const auto problem = geometry::polygon_problem(polygon.vertices)) {
      spdlog::warn("map '{}': polygon '{}' ignored: {}", m.name, p.name, *problem);
      continue;
    }
    w.polygons.push_back(std::move(polygon));
  }
  for (const auto& r : m.rasters) {
    const std::size_t cells = static_cast<std::size_t>(r.cols) * r.rows;
    if (cells == 0 || r.blocked.size() != cells || !std::isfinite(r.resolution) || r.resolution <= 0.0 ||
        !std::isfinite(r.origin_x) || !std::isfinite(r.origin_y)) {
      spdlog::warn("map '{}': raster '{}' ignored: {} x {} cells at {} m, {} cell values", m.name, r.name, r.cols,
                   r.rows, r.resolution, r.blocked.size());
      continue;
    }
    auto raster = std::make_shared<grid::OccupancyRaster>(static_cast<int>(r.cols), static_cast<int>(r.rows),
                                                          r.resolution, grid::RasterOrigin{r.origin_x, r.origin_y, 0.0});
    for (int row = 0; row < raster->height(); ++row) {
      for (int col = 0; col < raster->width(); ++col) {
        if (r.blocked[raster->index({col, row})] != 0) raster->set_blocked({col, row}, true);
      }
    }
    w.rasters.push_back(std::move(raster));
  }
  for (const auto& d : m.doors) {
    if (d.id.empty() || !std::isfinite(d.x) || !std::isfinite(d.y) || !std::isfinite(d.width) || d.width <= 0.0 ||
        !std::isfinite(d.heading)) {
      spdlog::warn("map '{}': door '{}' ignored: doorway ({}, {}) width {} heading {}", m.name, d.id, d.x, d.y, d.width,
                   d.heading);
      continue;
    }
    w.doors.push_back({d.id, geometry::Vec2(d.x, d.y), d.width, d.heading});
  }
  return w;
}

}  // namespace

BehaviorNode::BehaviorNode(service::Service& service, BehaviorNodeOptions options)
    : service_(service),
      options_(std::move(options)),
      participant_name_("behavior/" + options_.robot_id),
      state_topic_(service.participant(), dds::topics::robot_state),
      map_topic_(service.participant(), dds::topics::world_map),
      goal_topic_(service.participant(), dds::topics::nav_goal),
      cancel_topic_(service.participant(), dds::topics::nav_cancel),
      goal_status_topic_(service.participant(), dds::topics::goal_status),
      mission_status_topic_(service.participant(), dds::topics::mission_status),
      cmd_topic_(service.participant(), dds::topics::cmd_vel),
      spawn_request_topic_(service.participant(), dds::topics::spawn_request),
      spawn_reply_topic_(service.participant(), dds::topics::spawn_reply),
      state_reader_(service.participant(), state_topic_),
      map_reader_(service.participant(), map_topic_),
      goal_reader_(service.participant(), goal_topic_),
      cancel_reader_(service.participant(), cancel_topic_),
      spawn_reply_reader_(service.participant(), spawn_reply_topic_),
      door_topic_(service.participant(), dds::topics::door_observation),
      door_reader_(service.participant(), door_topic_),
      goal_status_writer_(service.participant(), goal_status_topic_),
      mission_status_writer_(service.participant(), mission_status_topic_),
      cmd_writer_(service.participant(), cmd_topic_),
      spawn_request_writer_(service.participant(), spawn_request_topic_),
      lockstep_(service.participant(), service.loop(), participant_name_,
                [this](const msg::SimClock& c) { on_tick(c); }) {
  spawn_request_id_ = options_.robot_id + "@" + std::to_string(getpid());
  contact_ = ContactJudge(options_.contact);
  doors_ = DoorKnowledge(options_.doors);
  if (options_.mission) {
    for (const ConstraintLayerSpec& l : options_.mission->layers) options_.layers[l.name] = l.areas;
  }
  auto& loop = service.loop();
  loop.on_samples<msg::SpawnReply>(spawn_reply_reader_, [this](auto s) { on_spawn_replies(std::move(s)); });
  loop.on_samples<msg::RobotState>(state_reader_, [this](auto s) { on_states(std::move(s)); });
  loop.on_samples<msg::WorldMap>(map_reader_, [this](auto s) { on_map(std::move(s)); });
  loop.on_samples<msg::NavGoal>(goal_reader_, [this](auto s) { on_goals(std::move(s)); });
  loop.on_samples<msg::NavCancel>(cancel_reader_, [this](auto s) { on_cancels(std::move(s)); });
  loop.on_samples<msg::DoorObservation>(door_reader_, [this](auto samples) {
    for (const auto& s : samples) {
      if (!s.valid || s.value.robot_id != options_.robot_id || options_.mission) continue;
      for (const auto& d : s.value.doors) door_sightings_[d.door_id] = d.angle_estimate;
    }
  });

  if (options_.mission) {
    const auto& p = service.participant();
    pose_topic_ = std::make_unique<dds::Topic<msg::PoseEstimate>>(p, dds::topics::pose_estimate);
    scan_topic_ = std::make_unique<dds::Topic<msg::RangeScan>>(p, dds::topics::range_scan);
    link_topic_ = std::make_unique<dds::Topic<msg::RadioLink>>(p, dds::topics::radio_link);
    inbox_topic_ = std::make_unique<dds::Topic<msg::TeamDelivery>>(p, dds::topics::team_inbox);
    pose_reader_ = std::make_unique<dds::Reader<msg::PoseEstimate>>(p, *pose_topic_);
    scan_reader_ = std::make_unique<dds::Reader<msg::RangeScan>>(p, *scan_topic_);
    link_reader_ = std::make_unique<dds::Reader<msg::RadioLink>>(p, *link_topic_);
    inbox_reader_ = std::make_unique<dds::Reader<msg::TeamDelivery>>(p, *inbox_topic_);
    const std::string me = options_.robot_id;
    loop.on_samples<msg::PoseEstimate>(*pose_reader_, [this, me](auto samples) {
      for (auto& s : samples)
        if (s.valid && s.value.robot_id == me && (!pose_estimate_ || s.value.tick >= pose_estimate_->tick))
          pose_estimate_ = std::move(s.value);
    });
    loop.on_samples<msg::RangeScan>(*scan_reader_, [this, me](auto samples) {
      for (auto& s : samples)
        if (s.valid && s.value.robot_id == me && (!scan_ || s.value.tick >= scan_->tick)) scan_ = std::move(s.value);
    });
    loop.on_samples<msg::RadioLink>(*link_reader_, [this, me](auto samples) {
      for (auto& s : samples) {
        if (!s.valid) continue;
        if (s.value.robot_a == me) link_connected_[s.value.robot_b] = s.value.connected;
        if (s.value.robot_b == me) link_connected_[s.value.robot_a] = s.value.connected;
      }
    });
    loop.on_samples<msg::TeamDelivery>(*inbox_reader_, [this, me](auto samples) {
      for (auto& s : samples)
        if (s.valid && s.value.recipient == me)
          last_heard_s_[s.value.from] = static_cast<double>(s.value.delivered_time_ns) * 1e-9;
    });
  }
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
    if (!s.valid) continue;
    if (s.value.robot_id != options_.robot_id) {
      if (options_.mission) teammate_states_[s.value.robot_id] = s.value;
      continue;
    }
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
  if (ready() || !spawned_ || !state_ || !map_) return;
  const msg::RobotState& st = *state_;
  world_ = world_of(*map_);
  const WorldMap& world = world_;
  // The grid keeps the robot's centre one resolution step further from obstacles than its
  // radius, so that rounding to cells never plans a path that grazes a wall.
  const double inflation = st.radius + options_.grid_resolution_m;
  if (options_.mission) {
    const auto t0 = std::chrono::steady_clock::now();
    PlanLibrary plans;
    try {
      plans = build_plan_library(*options_.mission, world, options_.grid_resolution_m, inflation);
    } catch (const std::exception& e) {
      service_.fail("mission " + options_.mission->name + ": cannot build its plans on map '" + map_->name +
                    "': " + e.what());
      return;
    }
    MissionExecutorOptions eo;
    eo.noise_seed = std::hash<std::string>{}(options_.robot_id);
    executor_.emplace(*options_.mission, std::move(plans), eo);
    spdlog::info("robot {} ready at ({:.2f}, {:.2f}) on map '{}', mission '{}' ({} plan sets built in {:.0f} ms)",
                 options_.robot_id, st.x, st.y, map_->name, options_.mission->name,
                 options_.mission->plan_sets.size(),
                 std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    service_.set_ready();
    control_pending_tick();
    return;
  }
  OccupancyGrid grid(world, options_.grid_resolution_m, inflation);
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
    if (options_.mission) {
      spdlog::warn("goal {} ignored: robot {} runs mission '{}'", msg::clipped_for_log(s.value.goal_id), options_.robot_id,
                   options_.mission->name);
    } else if (tracker_) {
      accept_goal(s.value);
    } else {
      queued_goal_ = s.value;  // the newest goal waits for the map and the robot
    }
  }
}

void BehaviorNode::on_cancels(std::vector<dds::Sample<msg::NavCancel>> samples) {
  for (const auto& s : samples) {
    if (!s.valid || s.value.robot_id != options_.robot_id) continue;
    const std::string what =
        s.value.goal_id.empty() ? std::string("the current goal") : "goal " + msg::clipped_for_log(s.value.goal_id);
    // A cancel has no reply of its own: an unusable one is logged and changes nothing.
    auto problem = msg::length_problem("goal_id", s.value.goal_id, msg::kMaxIdLength);
    if (!problem) problem = msg::length_problem("reason", s.value.reason, msg::kMaxTextLength);
    if (problem) {
      spdlog::warn("cancel of {} ignored: {}", what, *problem);
      continue;
    }
    if (options_.mission) {
      spdlog::warn("cancel of {} ignored: robot {} runs a mission", what, options_.robot_id);
      continue;
    }
    if (!tracker_) {
      // Not ready yet: a queued goal it names never starts.
      if (queued_goal_ && (s.value.goal_id.empty() || s.value.goal_id == queued_goal_->goal_id)) queued_goal_.reset();
      continue;
    }
    const GoalReport report = tracker_->cancel(s.value.goal_id, s.value.reason);
    if (report.changes.empty()) spdlog::info("cancel of {}: not being pursued, nothing to do", what);
    publish(report);
  }
}

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

void BehaviorNode::pursue(const msg::NavGoal& goal, const ConstraintSet& set, const GoalReport& report) {
  // A rejected goal leaves the pursued one running, and with it that goal's constraint set.
  if (const auto target = tracker_->target(); target && target->id == goal.goal_id) pursued_constraints_ = set;
  publish(report);
}

std::optional<CostToGoField> BehaviorNode::field_for(const geometry::Vec2& target, const ConstraintSet& set,
                                                     std::string* error) const {
  const OccupancyGrid& grid = tracker_->grid();  // the obstacles and the doors known closed
  if (set.layers.empty()) return CostToGoField(grid, target);
  const auto world = apply_constraints(doors_.apply(world_), set, options_.layers, error);
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
  const std::vector<std::string> closed = doors_.closed();
  const std::string closures = closed.empty() ? "" : describe_closed_doors(closed);
  spdlog::info("robot {}: {}; replanning", options_.robot_id, describe_closed_doors(closed));
  const OccupancyGrid& old = tracker_->grid();
  tracker_->set_grid(OccupancyGrid(doors_.apply(world_), old.geometry().resolution_m(), old.inflation_radius_m()),
                     closures);
  const auto target = tracker_->target();
  if (!target || !pursued_constraints_) return;
  std::string error;
  auto field = field_for(target->goal, *pursued_constraints_, &error);
  if (!field) {  // the layers were known when the goal was accepted; keep the current route
    spdlog::warn("goal {}: cannot replan: {}", target->id, error);
    return;
  }
  publish(tracker_->replan(std::move(*field), now_s));
}

void BehaviorNode::on_tick(const msg::SimClock& clock) {
  // Until the robot is attached and the map known, the tick stays unanswered: the world waits
  // (up to the ack timeout) so that a run starts identically however slow this process is.
  pending_tick_ = clock.tick;
  control_pending_tick();
}

void BehaviorNode::control_pending_tick() {
  if (!pending_tick_ || !ready() || !state_ || state_->tick < *pending_tick_) return;
  const int64_t tick = *pending_tick_;
  pending_tick_.reset();
  const uint32_t sent = executor_ ? control_mission(tick) : control_goal(tick);
  lockstep_.acknowledge(tick, sent);
}

uint32_t BehaviorNode::control_goal(int64_t tick) {
  const geometry::Pose2 pose{state_->x, state_->y, state_->theta};
  const double now_s = static_cast<double>(state_->sim_time_ns) * 1e-9;
  // What the robot saw this tick first, so that a goal is judged on the doors as they are now.
  update_door_knowledge(now_s);
  publish(tracker_->update(pose, now_s, state_->in_collision));

  if (tracker_->active()) {
    const GoToDecision decision = controller_->command(pose, *tracker_->field(), tracker_->tolerance_m());
    send_command(decision.command, tick);
    return 1;
  }
  if (!stopped_robot_) {
    send_command({}, tick);  // the goal ended: stop now rather than when the command expires
    return 1;
  }
  return 0;
}

Perception BehaviorNode::perceive() const {
  const msg::RobotState& st = *state_;
  Perception p;
  p.time_s = static_cast<double>(st.sim_time_ns) * 1e-9;
  p.pose = {st.x, st.y, st.theta};
  // The robot's own estimate when its pose sensor publishes one for this tick (or the previous).
  if (pose_estimate_ && pose_estimate_->tick >= st.tick - 1)
    p.pose = {pose_estimate_->x, pose_estimate_->y, pose_estimate_->theta};
  p.kinematics = st.kinematics == msg::Kinematics::Holonomic ? Kinematics::Holonomic : Kinematics::Unicycle;
  p.velocity = p.kinematics == Kinematics::Holonomic
                   ? geometry::Vec2(st.vx, st.vy)
                   : geometry::Vec2(st.vx * std::cos(st.theta), st.vx * std::sin(st.theta));
  p.limits = {st.max_speed, st.max_omega};
  if (scan_) {
    p.rays.reserve(scan_->ranges.size());
    for (std::size_t i = 0; i < scan_->ranges.size(); ++i) {
      p.rays.push_back({scan_->angle_min + static_cast<double>(i) * scan_->angle_increment,
                        static_cast<double>(scan_->ranges[i]), scan_->max_range});
    }
  }
  for (const std::string& id : options_.mission->teammates) {
    TeammateState t;
    t.id = id;
    if (const auto link = link_connected_.find(id); link != link_connected_.end()) {
      t.in_contact = link->second;
    } else if (!last_heard_s_.empty()) {
      const auto heard = last_heard_s_.find(id);
      t.in_contact = heard != last_heard_s_.end() && p.time_s - heard->second <= options_.contact_freshness_s;
    } else {
      t.in_contact = true;  // no radio model running: everyone is in contact
    }
    if (const auto pos = last_known_position_.find(id); pos != last_known_position_.end()) t.position = pos->second;
    p.teammates.push_back(std::move(t));
  }
  return p;
}

uint32_t BehaviorNode::control_mission(int64_t tick) {
  // Teammates' positions are known while in contact (as if they reported them), kept when lost.
  Perception p = perceive();
  for (TeammateState& t : p.teammates) {
    t.in_contact = contact_.update(t.id, p.time_s, t.in_contact);
    const auto st = teammate_states_.find(t.id);
    if (t.in_contact && st != teammate_states_.end()) {
      last_known_position_[t.id] = geometry::Vec2(st->second.x, st->second.y);
      t.position = last_known_position_[t.id];
    }
  }
  const bool was_finished = executor_->finished();
  const MissionStep step = executor_->step(p);
  for (const MissionEvent& e : step.events) {
    spdlog::info("mission {}: {}", options_.mission->name, e.to_string());
    publish_mission(e, tick);
  }
  if (!was_finished || !stopped_robot_) {
    send_command(step.finished ? VelocityCommand{} : step.command, tick);
    return 1;
  }
  return 0;
}

void BehaviorNode::send_command(const VelocityCommand& command, int64_t tick) {
  cmd_writer_.write({options_.robot_id, participant_name_, tick, command.vx, command.vy, command.omega});
  stopped_robot_ = command.is_zero();
}

void BehaviorNode::publish(const GoalReport& report) {
  for (const GoalStatus& change : report.changes) {
    msg::GoalStatus s{options_.robot_id, change.goal_id, to_msg(change.state), change.reason,
                      state_ ? state_->tick : 0, change.distance_to_goal};
    if (change.state == GoalState::Blocked || change.state == GoalState::Rejected)
      spdlog::warn("goal {} {}: {}", change.goal_id, to_string(change.state), change.reason);
    else
      spdlog::info("goal {} {} ({:.2f} m to go){}{}", change.goal_id, to_string(change.state), change.distance_to_goal,
                   change.reason.empty() ? "" : ": ", change.reason);
    goal_status_writer_.write(s);
  }
}

void BehaviorNode::publish_mission(const MissionEvent& e, int64_t tick) {
  msg::MissionStatus s;
  s.robot_id = options_.robot_id;
  s.mission = options_.mission->name;
  s.state = e.state;
  s.event = event_name(e.kind);
  s.reason = e.kind == MissionEvent::Kind::Transition ? e.from + " -> " + e.state + ": " + e.reason : e.reason;
  s.finished = e.kind == MissionEvent::Kind::Finished || executor_->finished();
  s.tick = tick;
  mission_status_writer_.write(s);
}

}  // namespace autonomy::behavior
