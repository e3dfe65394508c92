#include "services/behavior/dds/behavior_node.hpp"

#include "services/behavior/dds/map_conversion.hpp"

#include "common/msg/text_limits.hpp"

#include "services/behavior/core/mission/plan_library.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <unistd.h>

namespace autonomy::behavior {

namespace {

constexpr auto kSpawnRetryPeriod = std::chrono::milliseconds(500);
constexpr auto kLateStatePeriod = std::chrono::milliseconds(10);

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
      // A tick's control (a few tens of µs) runs in the receive thread that delivered the clock.
      lockstep_(service, participant_name_, [this](const msg::SimClock& c) { on_tick(c); },
                service::TickHandling::AtArrival) {
  spawn_request_id_ = options_.robot_id + "@" + std::to_string(getpid());
  contact_ = ContactJudge(options_.contact);
  doors_ = DoorKnowledge(options_.doors);
  if (options_.mission) {
    for (const ConstraintLayerSpec& l : options_.mission->layers) options_.layers[l.name] = l.areas;
  }
  if (!options_.journal_path.empty()) {
    journal_ = std::make_unique<BehaviorJournal>(options_.journal_path, options_.robot_id,
                                                 options_.mission ? options_.mission->name : "");
    // An earlier run attached the robot, and the world keeps it after its behavior died: it is
    // taken back where it stands (a spawn at --start would be refused: already present).
    reattach_first_ = journal_->run() > 1 && options_.start.has_value();
    journalled_goals_ = journal_->goals();
    journalled_mission_ = journal_->mission();
    if (journalled_mission_) {
      const auto& states = options_.mission->states;
      if (std::none_of(states.begin(), states.end(), [&](const StateSpec& st) { return st.name == journalled_mission_->state; }))
        throw std::runtime_error("journal " + options_.journal_path + ": mission state '" + journalled_mission_->state +
                                 "' is not a state of mission " + options_.mission->name +
                                 " (the mission file changed?); name another journal file or remove this one");
    }
    spdlog::info("journal {} (run {}): {}", options_.journal_path, journal_->run(),
                 journalled_mission_ ? "mission in state " + journalled_mission_->state
                 : journalled_goals_.empty() ? std::string("nothing to resume")
                                             : std::to_string(journalled_goals_.size()) + " goals journalled");
  }
  auto& loop = service.loop();
  loop.on_samples<msg::SpawnReply>(spawn_reply_reader_, [this](auto s) { on_spawn_replies(std::move(s)); });
  // Robot states wake nobody: the simulator writes a tick's states before its clock, so they are
  // taken when the clock is (on_tick), and whenever a decision needs them (spawn reply, map,
  // goals); waking the loop for them as well cost a sleep and wake-up per tick. A state that comes
  // after its clock (retransmitted after a loss) is taken by the timer below within 10 ms.
  loop.every(kLateStatePeriod, [this] {
    if (pending_tick_) control_pending_tick();
  });
  loop.on_samples<msg::WorldMap>(map_reader_, [this](auto s) { on_map(std::move(s)); });
  loop.on_samples<msg::NavGoal>(goal_reader_, [this](auto s) { on_goals(std::move(s)); });
  loop.on_samples<msg::NavCancel>(cancel_reader_, [this](auto s) { on_cancels(std::move(s)); });
  loop.on_samples<msg::DoorObservation>(door_reader_, [this](auto samples) {
    for (const auto& s : samples) {
      if (!s.valid || s.value.robot_id != options_.robot_id || options_.mission) continue;
      for (const auto& d : s.value.doors) door_sightings_[d.door_id] = d.angle_estimate;
    }
  });

  if (!options_.mission && options_.traffic) open_traffic_topics();

  // The range scan: the mission's perception, and the avoid schema beside a planned path.
  const bool follows_paths = !options_.mission && options_.path.planner == GoToPlanner::Ompl;
  if (options_.mission || follows_paths) {
    const auto& p = service.participant();
    const std::string me = options_.robot_id;
    scan_topic_ = std::make_unique<dds::Topic<msg::RangeScan>>(p, dds::topics::range_scan);
    scan_reader_ = std::make_unique<dds::Reader<msg::RangeScan>>(p, *scan_topic_);
    loop.on_samples<msg::RangeScan>(*scan_reader_, [this, me](auto samples) {
      for (auto& s : samples)
        if (s.valid && s.value.robot_id == me && (!scan_ || s.value.tick >= scan_->tick)) scan_ = std::move(s.value);
    });
  }
  if (follows_paths) {
    // Reproducible runs: OMPL takes a seed only before its first plan in the process.
    seed_ompl(static_cast<std::uint32_t>(std::hash<std::string>{}(options_.robot_id)));
  }
  if (options_.mission) {
    const auto& p = service.participant();
    pose_topic_ = std::make_unique<dds::Topic<msg::PoseEstimate>>(p, dds::topics::pose_estimate);
    link_topic_ = std::make_unique<dds::Topic<msg::RadioLink>>(p, dds::topics::radio_link);
    inbox_topic_ = std::make_unique<dds::Topic<msg::TeamDelivery>>(p, dds::topics::team_inbox);
    pose_reader_ = std::make_unique<dds::Reader<msg::PoseEstimate>>(p, *pose_topic_);
    link_reader_ = std::make_unique<dds::Reader<msg::RadioLink>>(p, *link_topic_);
    inbox_reader_ = std::make_unique<dds::Reader<msg::TeamDelivery>>(p, *inbox_topic_);
    const std::string me = options_.robot_id;
    loop.on_samples<msg::PoseEstimate>(*pose_reader_, [this, me](auto samples) {
      for (auto& s : samples)
        if (s.valid && s.value.robot_id == me && (!pose_estimate_ || s.value.tick >= pose_estimate_->tick))
          pose_estimate_ = std::move(s.value);
    });
    loop.on_samples<msg::RadioLink>(*link_reader_, [this, me](auto samples) {
      for (auto& s : samples) {
        if (!s.valid) continue;
        radio_links_seen_ = true;
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
  if (options_.start && !reattach_first_) {
    r.has_pose = true;
    r.x = options_.start->x;
    r.y = options_.start->y;
    r.theta = options_.start->theta;
  }
  spawn_request_writer_.write(r);
}

void BehaviorNode::on_spawn_replies(std::vector<dds::Sample<msg::SpawnReply>> samples) {
  take_states();  // the simulator publishes a new robot's state before its reply
  for (const auto& s : samples) {
    if (!s.valid || s.value.request_id != spawn_request_id_ || spawned_) continue;
    if (s.value.status == msg::RequestStatus::Accepted) {
      spawned_ = true;
      spdlog::info("robot {} attached to the simulator", options_.robot_id);
      become_ready_when_possible();
    } else if (reattach_first_) {
      // No robot to take back (the world was restarted too): placed at --start as on a first run.
      spdlog::info("robot {}: nothing to re-attach ({}); spawning it at --start", options_.robot_id, s.value.reason);
      reattach_first_ = false;
      spawn_request_id_ += "-start";
      request_spawn();
    } else {
      service_.fail("simulator refused robot " + options_.robot_id + ": " + s.value.reason);
    }
  }
}

void BehaviorNode::take_states() {
  for (auto& s : state_reader_.take()) {
    if (!s.valid) continue;
    if (s.value.robot_id != options_.robot_id) {
      if (options_.mission || options_.traffic) teammate_states_[s.value.robot_id] = s.value;
      continue;
    }
    if (!state_ || s.value.tick >= state_->tick) state_ = std::move(s.value);
  }
}

void BehaviorNode::on_map(std::vector<dds::Sample<msg::WorldMap>> samples) {
  for (auto& s : samples)
    if (s.valid) map_ = std::move(s.value);
  take_states();
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
  // Open doors' leaves where the map says they stand (no door is known closed yet).
  OccupancyGrid grid(doors_.apply(world), options_.grid_resolution_m, inflation);
  tracker_.emplace(std::move(grid), options_.tracker);
  controller_.emplace(st.kinematics == msg::Kinematics::Holonomic ? Kinematics::Holonomic : Kinematics::Unicycle,
                      MotionLimits{st.max_speed, st.max_omega}, options_.go_to);
  if (options_.path.planner == GoToPlanner::Ompl) {
    options_.path.ompl.turn_in_place_at_start =
        options_.path.unicycle_turns_in_place && controller_->kinematics() == Kinematics::Unicycle;
    follower_.emplace(controller_->kinematics(), controller_->limits(), options_.path.follower);
    update_map_obstacles();
    spdlog::info("robot {}: go-to paths by OMPL {} in {} (turning radius {:.2f} m, budget {:.0f} ms{})",
                 options_.robot_id, options_.path.ompl.planner, to_string(options_.path.ompl.curve),
                 options_.path.ompl.turning_radius_m, options_.path.budget_s * 1e3,
                 options_.path.ompl.turn_in_place_at_start ? ", turning in place at the start" : "");
  }
  if (options_.traffic) start_traffic(st.radius);
  spdlog::info("robot {} ready at ({:.2f}, {:.2f}) on map '{}'", options_.robot_id, st.x, st.y, map_->name);
  service_.set_ready();
  // A journal with goals: the --goal was taken by an earlier run (respawned with the same flags).
  // A goal from the journal starts at the next tick (control_pending_tick).
  const bool journalled = resume_journalled_goals();
  if (!journalled && options_.initial_goal && !queued_goal_) {
    if (journal_) journal_->goal_arrived(*options_.initial_goal);
    queued_goal_ = options_.initial_goal;
  }
  if (queued_goal_ && !journalled) {
    accept_goal(*queued_goal_);
    queued_goal_.reset();
  }
  control_pending_tick();
}

void BehaviorNode::on_goals(std::vector<dds::Sample<msg::NavGoal>> samples) {
  take_states();  // a goal's statuses carry the tick of the latest state
  for (const auto& s : samples) {
    if (!s.valid || s.value.robot_id != options_.robot_id) continue;
    if (options_.mission) {
      spdlog::warn("goal {} ignored: robot {} runs mission '{}'", msg::clipped_for_log(s.value.goal_id), options_.robot_id,
                   options_.mission->name);
      continue;
    }
    // Journalled before anything is done with it. A goal whose id is too long is rejected with
    // nothing else done: not journalled (the journal could not match its clipped status).
    if (queued_goal_ && !resuming_goal_.empty() && queued_goal_->goal_id == resuming_goal_) {
      // Replaced below before it was taken on again: it was active before the restart, so its
      // end is published like any preemption.
      publish_outside_tracker(resuming_goal_, GoalState::Preempted, "preempted by goal " + msg::clipped_id(s.value.goal_id));
      resuming_goal_.clear();
    } else if (journal_ && queued_goal_) {  // replaced below, never started
      journal_->goal_state(queued_goal_->goal_id, GoalState::Preempted,
                           "replaced by goal " + msg::clipped_id(s.value.goal_id) + " before it started");
    }
    if (journal_) {
      if (!msg::length_problem("goal_id", s.value.goal_id, msg::kMaxIdLength)) journal_->goal_arrived(s.value);
    }
    if (tracker_ && (lockstep_.quiet() || queued_goal_)) {
      // The world runs on without us: the goal starts at the next tick we see, not at the old
      // tick our clock still shows (its progress would be judged over the ticks we skipped).
      // A later goal before that tick replaces it, as it would replace a goal being pursued.
      queued_goal_ = s.value;
      lockstep_.wake();
    } else if (tracker_) {
      accept_goal(s.value);
    } else {
      queued_goal_ = s.value;  // the newest goal waits for the map and the robot
    }
  }
}

void BehaviorNode::on_cancels(std::vector<dds::Sample<msg::NavCancel>> samples) {
  take_states();
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
    // Not ready yet, or the goal came while quiet: a queued goal it names never starts.
    if (queued_goal_ && (s.value.goal_id.empty() || s.value.goal_id == queued_goal_->goal_id)) {
      if (!resuming_goal_.empty() && queued_goal_->goal_id == resuming_goal_) {  // active before the restart: its end is published
        publish_outside_tracker(resuming_goal_, GoalState::Cancelled, s.value.reason.empty() ? "cancelled" : s.value.reason);
        resuming_goal_.clear();
      } else if (journal_) {
        journal_->goal_state(queued_goal_->goal_id, GoalState::Cancelled, s.value.reason);
      }
      queued_goal_.reset();
    }
    if (!tracker_) continue;
    const GoalReport report = tracker_->cancel(s.value.goal_id, s.value.reason);
    if (report.changes.empty()) spdlog::info("cancel of {}: not being pursued, nothing to do", what);
    publish(report);
  }
}

void BehaviorNode::on_tick(const msg::SimClock& clock) {
  // Until the robot is attached and the map known, the tick stays unanswered: the world waits
  // (up to the ack timeout) so that a run starts identically however slow this process is.
  pending_tick_ = clock.tick;
  control_pending_tick();
}

void BehaviorNode::control_pending_tick() {
  const auto tick_due = [this] { return pending_tick_ && ready() && state_ && state_->tick >= *pending_tick_; };
  if (!pending_tick_ || service_.loop().draining()) return;  // a handler run by the drain below: looked at after it
  // The tick's states came before its clock and wait in their reader (they wake nobody).
  take_states();
  become_ready_when_possible();  // returns at once when ready; calls this again when it becomes so
  if (!tick_due()) return;
  // The simulator writes a tick's scans, pose estimates, links, team messages and states before
  // its clock: they have arrived, but some may still sit in their readers. Taking them first makes
  // the tick's control the same whatever order the waitset reports the readers in (lockstep runs
  // repeat exactly).
  service_.loop().drain();
  take_states();  // a clock the drain took brings its tick's states too
  if (!tick_due()) return;
  const int64_t tick = *pending_tick_;
  pending_tick_.reset();
  if (queued_goal_ && tracker_) {  // came while this process was quiet (on_goals), or from the journal
    accept_goal(*queued_goal_);
    queued_goal_.reset();
    resuming_goal_.clear();
  }
  const uint32_t sent = executor_ ? control_mission(tick) : control_goal(tick);
  lockstep_.acknowledge(tick, sent, sent == 0 && waiting_for_a_goal() ? std::numeric_limits<int64_t>::max() : 0);
}

bool BehaviorNode::waiting_for_a_goal() const {
  return !executor_ && !options_.mission && tracker_ && !tracker_->active() && !queued_goal_ && stopped_robot_;
}

void BehaviorNode::send_command(const VelocityCommand& command, int64_t tick) {
  cmd_writer_.write({options_.robot_id, participant_name_, tick, command.vx, command.vy, command.omega});
  stopped_robot_ = command.is_zero();
}

void BehaviorNode::publish(const GoalReport& report) {
  for (const GoalStatus& change : report.changes) {
    msg::GoalStatus s{options_.robot_id, change.goal_id, to_msg(change.state), change.reason,
                      state_ ? state_->tick : 0, change.distance_to_goal};
    if (journal_) journal_->goal_state(change.goal_id, change.state, change.reason);
    if (change.state == GoalState::Blocked || change.state == GoalState::Rejected)
      spdlog::warn("goal {} {}: {}", change.goal_id, to_string(change.state), change.reason);
    else
      spdlog::info("goal {} {} ({:.2f} m to go){}{}", change.goal_id, to_string(change.state), change.distance_to_goal,
                   change.reason.empty() ? "" : ": ", change.reason);
    goal_status_writer_.write(s);
  }
}

}  // namespace autonomy::behavior
