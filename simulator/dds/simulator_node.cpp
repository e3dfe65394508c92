#include "simulator/dds/simulator_node.hpp"

#include "common/msg/text_limits.hpp"

#include "simulator/dds/map_message.hpp"

#include "simulator/dds/radio_setup.hpp"
#include "simulator/dds/spacecraft_area.hpp"
#include "simulator/report/run_svg.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <tuple>

namespace autonomy::sim {

namespace {

constexpr auto kHousekeepingPeriod = std::chrono::milliseconds(10);
constexpr auto kStatusPeriod = std::chrono::milliseconds(200);
// The status carries the last this many lockstep drops and rejoins.
constexpr size_t kLockstepChangesKept = 32;
// Readers of what others send the simulator (commands, acks, requests, team messages) keep all
// samples: the history kept on this side never drops one (docs/topics.md, "What can drop").
constexpr auto kInputQos = dds::QosClass::Queue;

// Every clock but this process's own: the simulator hears its own ticks not at all, so the reader
// costs nothing while its world is alone on the domain.
dds::Qos foreign_clock_qos() {
  dds::Qos q = dds::make_qos(dds::topics::clock.qos);
  dds_qset_ignorelocal(q.get(), DDS_IGNORELOCAL_PARTICIPANT);
  return q;
}

msg::RobotState to_msg(const RobotStatus& r, int64_t tick, int64_t sim_time_ns) {
  msg::RobotState s;
  s.robot_id = r.id;
  s.tick = tick;
  s.sim_time_ns = sim_time_ns;
  s.x = r.pose.x;
  s.y = r.pose.y;
  s.theta = r.pose.theta;
  s.vx = r.vx;
  s.vy = r.vy;
  s.omega = r.omega;
  s.kinematics = r.kinematics == Kinematics::Holonomic ? msg::Kinematics::Holonomic : msg::Kinematics::Unicycle;
  s.radius = r.radius;
  s.max_speed = r.max_speed;
  s.max_omega = r.max_omega;
  s.in_collision = r.in_collision;
  return s;
}

VelocityCommand from_msg(const msg::VelocityCommand& c) { return {c.robot_id, c.source, c.tick, c.vx, c.vy, c.omega}; }

// Stable: commands of one robot from one source keep their arrival order. A tick has a few
// commands: an insertion sort needs no buffer (std::stable_sort allocates one per call); many
// (a large fleet) go to std::stable_sort.
void sort_by_robot_and_source(std::vector<msg::VelocityCommand>& commands) {
  const auto before = [](const msg::VelocityCommand& a, const msg::VelocityCommand& b) {
    return std::tie(a.robot_id, a.source) < std::tie(b.robot_id, b.source);
  };
  constexpr size_t kInsertionSortUpTo = 16;
  if (commands.size() > kInsertionSortUpTo) {
    std::stable_sort(commands.begin(), commands.end(), before);
    return;
  }
  for (auto next = commands.begin(); next != commands.end(); ++next)
    std::rotate(std::upper_bound(commands.begin(), next, *next, before), next, std::next(next));
}

int64_t to_ns(double seconds) { return static_cast<int64_t>(std::llround(seconds * 1e9)); }

bool has_range_sensor(const RobotSpec& spec) {
  return spec.sensors.range.rays > 0 && spec.sensors.range.max_range_m > 0.0;
}
bool has_door_sensor(const RobotSpec& spec) { return spec.sensors.doors.range_m > 0.0; }
// SensorSpec has no presence flag for the pose sensor: a robot has one when its pose sensor is
// noisy or it has any other sensor (a robot that senses localises itself).
bool has_pose_sensor(const RobotSpec& spec) {
  return spec.sensors.pose.position_noise_m > 0.0 || spec.sensors.pose.heading_noise_rad > 0.0 ||
         has_range_sensor(spec) || has_door_sensor(spec);
}

msg::DoorState to_msg(const DoorStatus& d, int64_t tick) {
  return {d.id, tick, d.angle, d.target_angle, d.closed(), d.blocked};
}

bool same_door_state(const msg::DoorState& a, const msg::DoorState& b) {
  return a.angle == b.angle && a.target_angle == b.target_angle && a.blocked == b.blocked;
}

// Separate from the world's streams (door schedules, sensor noise), so sending messages does not
// change what robots sense.
constexpr uint64_t kDeliveryStreamSalt = 0x7465616d6d736773ull;  // "teammsgs"
// Handover durations: their own stream too.
constexpr uint64_t kOfficeStreamSalt = 0x6f66666963657321ull;  // "office!!"

msg::HandoverStatus to_msg(const office::DeskAnswer& a, int64_t tick) {
  msg::HandoverStatus s;
  s.request_id = a.request_id;
  s.robot_id = a.robot_id;
  s.kind = a.kind == office::HandoverKind::unload ? msg::HandoverKind::Unload : msg::HandoverKind::Load;
  s.place = a.place;
  s.object_id = a.object_id;
  switch (a.state) {
    case office::DeskAnswerState::accepted: s.state = msg::HandoverState::Accepted; break;
    case office::DeskAnswerState::rejected: s.state = msg::HandoverState::Rejected; break;
    case office::DeskAnswerState::completed: s.state = msg::HandoverState::Completed; break;
    case office::DeskAnswerState::failed: s.state = msg::HandoverState::Failed; break;
  }
  s.reason = a.reason;
  s.detail = a.detail;
  s.helper = a.helper;
  s.tick = tick;
  s.sim_time_ns = to_ns(a.time_s);
  s.completes_at_ns = a.state == office::DeskAnswerState::rejected ? 0 : to_ns(a.completes_at_s);
  return s;
}

msg::ObjectState to_msg(const office::ObjectItem& o, int64_t tick) {
  const bool carried = o.location.kind == office::ObjectLocation::Kind::carrier;
  return {o.id, o.kind, o.colour, carried ? "" : o.location.name, carried ? o.location.name : "", tick};
}

}  // namespace

SimulatorNode::SimulatorNode(service::Service& service, Scenario scenario, SimulatorRunOptions options)
    : service_(service),
      scenario_(std::move(scenario)),
      world_(scenario_.world),
      options_(std::move(options)),
      last_advance_(std::chrono::steady_clock::now()),
      quiet_continue_(service.participant()),
      step_due_(service.participant()),
      radio_(make_radio_model(scenario_)),
      clock_topic_(service.participant(), dds::topics::clock),
      state_topic_(service.participant(), dds::topics::robot_state),
      cmd_topic_(service.participant(), dds::topics::cmd_vel),
      rejection_topic_(service.participant(), dds::topics::command_rejected),
      registration_topic_(service.participant(), dds::topics::lockstep_registration),
      ack_topic_(service.participant(), dds::topics::tick_ack),
      spawn_request_topic_(service.participant(), dds::topics::spawn_request),
      spawn_reply_topic_(service.participant(), dds::topics::spawn_reply),
      map_topic_(service.participant(), dds::topics::world_map),
      status_topic_(service.participant(), dds::topics::sim_status),
      scan_topic_(service.participant(), dds::topics::range_scan),
      pose_topic_(service.participant(), dds::topics::pose_estimate),
      door_observation_topic_(service.participant(), dds::topics::door_observation),
      door_truth_topic_(service.participant(), dds::topics::truth_door),
      link_topic_(service.participant(), dds::topics::radio_link),
      team_topic_(service.participant(), dds::topics::radio_team),
      outbox_topic_(service.participant(), dds::topics::team_outbox),
      inbox_topic_(service.participant(), dds::topics::team_inbox),
      door_command_topic_(service.participant(), dds::topics::door_command),
      goal_status_topic_(service.participant(), dds::topics::goal_status),
      mission_status_topic_(service.participant(), dds::topics::mission_status),
      clock_writer_(service.participant(), clock_topic_),
      state_writer_(service.participant(), state_topic_),
      rejection_writer_(service.participant(), rejection_topic_),
      spawn_reply_writer_(service.participant(), spawn_reply_topic_),
      map_writer_(service.participant(), map_topic_),
      status_writer_(service.participant(), status_topic_),
      scan_writer_(service.participant(), scan_topic_),
      pose_writer_(service.participant(), pose_topic_),
      door_observation_writer_(service.participant(), door_observation_topic_),
      door_truth_writer_(service.participant(), door_truth_topic_),
      link_writer_(service.participant(), link_topic_),
      team_writer_(service.participant(), team_topic_),
      inbox_writer_(service.participant(), inbox_topic_),
      cmd_reader_(service.participant(), cmd_topic_, kInputQos),
      ack_reader_(service.participant(), ack_topic_, kInputQos),
      registration_reader_(service.participant(), registration_topic_),
      spawn_request_reader_(service.participant(), spawn_request_topic_, kInputQos),
      door_command_reader_(service.participant(), door_command_topic_, kInputQos),
      outbox_reader_(service.participant(), outbox_topic_, kInputQos),
      goal_status_reader_(service.participant(), goal_status_topic_),
      mission_status_reader_(service.participant(), mission_status_topic_),
      handover_request_topic_(service.participant(), dds::topics::handover_request),
      handover_status_topic_(service.participant(), dds::topics::handover_status),
      object_truth_topic_(service.participant(), dds::topics::truth_object),
      handover_status_writer_(service.participant(), handover_status_topic_),
      object_truth_writer_(service.participant(), object_truth_topic_),
      handover_request_reader_(service.participant(), handover_request_topic_, kInputQos),
      foreign_clock_reader_(service.participant(), clock_topic_, foreign_clock_qos().get()) {
  if (options_.radio_period_ticks < 1) throw std::invalid_argument("radio period must be at least 1 tick");
  delivery_rng_.seed(options_.settings.seed ^ kDeliveryStreamSalt);
  if (!options_.metrics_prefix.empty()) {
    const WorldSpec& w = world_.spec();
    metrics_.emplace(CoverageSettings{{0.0, 0.0, w.width, w.height}, 1.0, 3.0},
                     [this](const geometry::Vec2& a, const geometry::Vec2& b) { return world_.line_of_sight(a, b); });
  }
  if (!options_.trajectory_csv.empty()) {
    trajectory_.open(options_.trajectory_csv);
    if (!trajectory_) throw std::runtime_error("cannot write trajectory file " + options_.trajectory_csv);
    trajectory_ << "tick,time_s,robot,x,y,theta\n";
  }

  const WorldSpec& spec = world_.spec();
  map_writer_.write(map_message(spec));
  if (scenario_.office) {
    const office::OfficeSpec& o = *scenario_.office;
    office_.emplace(o, options_.settings.seed ^ kOfficeStreamSalt);
    spdlog::info("office: {} places, {} people, {} objects, {} loading stations; the day starts at {}",
                 o.places.size(), o.people.size(), o.objects.size(), o.stations.size(),
                 office::format_clock(o.clock.day_start_s));
  }

  auto& loop = service.loop();
  // Velocity commands wake nobody: a participant writes its commands before its tick ack, on the
  // same socket, so they are taken when the ack is (on_acks), and before every step (take_commands
  // in advance_while_complete and advance) for commands from outside lockstep. Waking the loop
  // for each command as well cost a wake-up per participant and tick.
  // Acks are counted in the receive thread that delivers them (a standalone process:
  // EventLoop::on_samples_at_arrival), and only the one that completes a tick wakes the loop's
  // thread (step_due_), instead of every ack. The world does not step in a receive thread: a
  // tick's writes (scans, radio links) can exceed what a reliable writer may have unacknowledged,
  // and the writer would then wait for acks that only that thread could take in (up to the
  // writer's max blocking time, then the write fails).
  loop.on_samples_at_arrival<msg::TickAck>(ack_reader_, [this](auto s) { on_acks(std::move(s)); });
  loop.on_condition(step_due_.handle(), [this] {
    step_due_.reset();
    advance_while_complete();
  });
  loop.on_samples<msg::LockstepRegistration>(registration_reader_, [this](auto s) { on_registrations(std::move(s)); });
  loop.on_samples<msg::SpawnRequest>(spawn_request_reader_, [this](auto s) { on_spawn_requests(std::move(s)); });
  loop.on_samples<msg::DoorCommand>(door_command_reader_, [this](auto s) { on_door_commands(std::move(s)); });
  loop.on_samples<msg::TeamMessage>(outbox_reader_, [this](auto s) { on_outbox(std::move(s)); });
  loop.on_samples<msg::GoalStatus>(goal_status_reader_, [this](auto s) { on_goal_status(std::move(s)); });
  loop.on_samples<msg::MissionStatus>(mission_status_reader_, [this](auto s) { on_mission_status(std::move(s)); });
  loop.on_samples<msg::SimClock>(foreign_clock_reader_, [this](auto s) { on_foreign_clocks(std::move(s)); });
  loop.on_samples<msg::HandoverRequest>(handover_request_reader_,
                                        [this](auto s) { on_handover_requests(std::move(s)); });
  loop.on_condition(quiet_continue_.handle(), [this] { continue_quietly(); });
  loop.every(kHousekeepingPeriod, [this] { on_timer(); });
  loop.every(kStatusPeriod, [this] { publish_status(); });
  if (scenario_.spacecraft)
    spacecraft_ = std::make_unique<SpacecraftArea>(
        service.participant(), loop, *scenario_.spacecraft,
        [this](const std::string& source, int64_t tick) { return lockstep() && barrier_.on_command(source, tick); },
        [this] { advance_while_complete(); });

  open_tick();
  spdlog::info("world '{}' {}x{} m, {} obstacles, {} polygons, {} doors, {} robots, {} mode, step {} s", spec.name,
               spec.width, spec.height, spec.obstacles.size(), spec.polygons.size(), spec.doors.size(),
               world_.robots().size(), lockstep() ? "lockstep" : "paced", options_.settings.step_s);
  spdlog::info("radio: {} attenuators ({} areas), link table every {} tick(s)", radio_.attenuators().size(),
               scenario_.radio.areas.size(), options_.radio_period_ticks);
  service.set_ready();
}

SimulatorNode::~SimulatorNode() {
  try {
    publish_status();
    write_picture();
    write_metrics();
    spdlog::info("stopped at tick {}: {} commands applied, {} rejected, {} participants dropped, {} ticks quiet",
                 tick_, commands_applied_, commands_rejected_, participants_dropped_, quiet_ticks_);
    if (spacecraft_)
      spdlog::info("spacecraft commands: {} accepted, {} rejected", spacecraft_->commands_accepted(),
                   spacecraft_->commands_rejected());
    spdlog::info("team messages: {} delivered, dropped {} without route, {} lost, {} invalid", messages_delivered_,
                 messages_no_route_, messages_lost_, messages_invalid_);
  } catch (const std::exception& e) {
    spdlog::warn("final status not published: {}", e.what());
  }
}

void SimulatorNode::take_commands() {
  auto samples = cmd_reader_.take();
  if (!samples.empty()) on_commands(std::move(samples));
}

void SimulatorNode::on_commands(std::vector<dds::Sample<msg::VelocityCommand>> samples) {
  for (auto& s : samples) {
    if (!s.valid) continue;
    msg::VelocityCommand& c = s.value;
    if (auto problem = msg::first_length_problem(
            {{"robot_id", c.robot_id, msg::kMaxNameLength}, {"source", c.source, msg::kMaxNameLength}})) {
      // Still counted when its source can be a participant: its tick must not wait for it.
      if (lockstep() && !msg::length_problem("source", c.source, msg::kMaxNameLength))
        (void)barrier_.on_command(c.source, c.tick);
      reject(c, *problem);
      continue;
    }
    // The barrier counts commands of its participants, including dropped ones that may be about
    // to rejoin; others (tools, unregistered processes) are applied at the next step.
    const bool synchronised = lockstep() && barrier_.on_command(c.source, c.tick);
    if (synchronised) {
      commands_by_tick_[c.tick].push_back(std::move(c));
    } else {
      unsynchronised_commands_.push_back(std::move(c));
      wake_ = true;
    }
  }
}

void SimulatorNode::on_acks(std::vector<dds::Sample<msg::TickAck>> samples) {
  if (!lockstep()) return;
  take_commands();  // written before these acks: counted before the acks complete a tick
  for (const auto& s : samples) {
    if (!s.valid) continue;
    if (spacecraft_) spacecraft_->on_ack(s.value.participant);  // the commander's sign of life
    if (barrier_.on_ack(s.value.participant, s.value.tick, s.value.commands_sent, s.value.quiet_until_tick) ==
        LockstepBarrier::AckOutcome::Rejoined) {
      spdlog::info("participant {} answered again at tick {} and rejoined lockstep", s.value.participant, s.value.tick);
      lockstep_changed(s.value.participant, false, "it acknowledged tick " + std::to_string(s.value.tick) + " again");
    }
  }
  if (!service_.loop().in_receive_thread())
    advance_while_complete();
  else if (may_advance())
    step_due_.trigger();
}

void SimulatorNode::on_registrations(std::vector<dds::Sample<msg::LockstepRegistration>> samples) {
  // A take returns the samples of one batch instance by instance (registrations are keyed by
  // participant), not in the order they were written: a replay that registers the recorded
  // participants and then itself had itself end the start hold before the last of them, which
  // then took part from tick 1 instead of 0. Written order it is.
  std::stable_sort(samples.begin(), samples.end(),
                   [](const auto& a, const auto& b) { return a.source_timestamp < b.source_timestamp; });
  for (const auto& s : samples) {
    const std::string& name = s.value.participant;
    if (auto problem = msg::length_problem("participant", name, msg::kMaxNameLength)) {
      spdlog::warn("lockstep registration of '{}' ignored: {}", msg::clipped_for_log(name), *problem);
      continue;
    }
    if (s.valid && s.value.active && s.instance_state == dds::InstanceState::Alive) {
      // Those who register while the start is held take part from tick 0: an executive that
      // holds a tick for its first plan must be waited for at the very first one.
      const bool before_start = holding_start();
      registered_once_.insert(name);
      registration_ended_.erase(name);
      const bool was_dropped = barrier_.is_dropped(name);
      if (barrier_.add(name, before_start))
        spdlog::info("participant {} joined lockstep at tick {}{}", name, tick_, before_start ? " (from this tick)" : "");
      if (was_dropped) lockstep_changed(name, false, "it registered again");
    } else if (s.valid && !s.value.active) {
      barrier_.remove(name);  // it said so (a leaving LockstepClient writes active=false first)
      registration_ended_.erase(name);
      // Left before this simulator read its registration (a test releasing the world while the
      // simulator still listened for another world): it was there, and holds the start no more.
      registered_once_.insert(name);
      spdlog::info("participant {} left lockstep at tick {}", name, tick_);
    } else {
      // The instance ended without a word: its writer's lease ran out (the process was killed,
      // is stopped or is cut off; Cyclone reports that as a disposal). It stays waited for, so
      // the world holds for a respawned or continued process, until the ack timeout drops it (a
      // later ack rejoins it).
      barrier_.silent(name);
      registration_ended_.insert(name);
      spdlog::warn("participant {} is silent at tick {} (its registration ended without leaving): waited for up to {} s",
                   name, tick_, options_.settings.ack_timeout_s);
    }
  }
  advance_while_complete();
}

void SimulatorNode::on_spawn_requests(std::vector<dds::Sample<msg::SpawnRequest>> samples) {
  for (auto& s : samples) {
    if (!s.valid) continue;
    const msg::SpawnRequest& r = s.value;
    if (auto problem = msg::first_length_problem({{"request_id", r.request_id, msg::kMaxIdLength},
                                                  {"requester", r.requester, msg::kMaxNameLength}})) {
      spdlog::warn("spawn request '{}' from '{}' rejected: {}", msg::clipped_for_log(r.request_id),
                   msg::clipped_for_log(r.requester), *problem);
      spawn_reply_writer_.write({msg::clipped_id(r.request_id), msg::clipped_id(r.robot_id, msg::kMaxNameLength),
                                 msg::RequestStatus::Rejected, *problem});
      continue;
    }
    spawn_requests_.push_back(std::move(s.value));
    wake_ = true;
  }
  handle_spawns();
}

bool SimulatorNode::holding_start() const {
  if (!lockstep() || tick_ != 0) return false;
  // Registered once is enough: a participant that held the start and then left (a test or a
  // script releasing the world) must not keep it held while the others come.
  return std::any_of(options_.wait_for_participants.begin(), options_.wait_for_participants.end(),
                     [&](const std::string& p) { return registered_once_.count(p) == 0; });
}

void SimulatorNode::on_timer() {
  const auto now = std::chrono::steady_clock::now();
  const auto period = std::chrono::duration<double>(options_.settings.step_s / options_.settings.warp);
  if (lockstep()) {
    const double now_s = std::chrono::duration<double>(now.time_since_epoch()).count();
    // Tick 0 starts for everybody when the start hold ends: while the world waits for its
    // --wait-for participants, those already there cannot be late, and the ack timeout counts
    // from the end of the hold (a participant registered seconds after the simulator started
    // was dropped at once, and a replay's recorded participants with it).
    const bool holding = holding_start();
    if (holding) barrier_.begin_tick(tick_, now_s);
    // A quiet tick waits for nobody's ack.
    for (const auto& p : quiet_ || holding ? std::vector<std::string>{}
                                           : barrier_.expire(tick_, now_s, options_.settings.ack_timeout_s)) {
      ++participants_dropped_;
      lockstep_changed(p, true,
                       fmt::format("it did not acknowledge tick {} within the ack timeout ({} s); {}", tick_,
                                   options_.settings.ack_timeout_s,
                                   registration_ended_.count(p)
                                       ? "its registration had ended without leaving (DDS lease expired: the "
                                         "process died, is stopped or is cut off)"
                                       : "it is still registered (slow, stopped for less than its lease, or its "
                                         "acks are lost)"));
    }
    if (!quiet_ && barrier_.current_tick() == tick_ && !barrier_.complete(tick_) &&
        now - clock_written_ >= std::chrono::seconds(1)) {
      clock_writer_.write(last_clock_);
      clock_written_ = now;
    }
    // Nobody to wait for: the world idles forward in real time instead of spinning.
    if (!barrier_.has_participants() && !holding_start() && now - last_advance_ >= period) advance();
    advance_while_complete();
  } else if (now - last_advance_ >= period) {
    // Paced: the next tick is due one period after this one was due, not after the housekeeping
    // timer noticed it (that would stretch every period by half a timer period on average: 9.5
    // instead of 10 ticks/s at 10 Hz). After a stall of more than a period the schedule restarts
    // from now instead of catching up in a burst.
    const auto due = last_advance_ + std::chrono::duration_cast<std::chrono::steady_clock::duration>(period);
    const bool on_schedule = now - due < period;
    advance();
    if (on_schedule) last_advance_ = due;
  }
}

bool SimulatorNode::may_advance() const {
  return !finished_ && barrier_.has_participants() && !holding_start() && (quiet_ || barrier_.complete(tick_));
}

void SimulatorNode::advance_while_complete() {
  if (!lockstep() || service_.loop().draining()) return;  // a handler run by the drain below: looked at after it
  take_commands();
  // Quiet ticks are stepped in batches: between two, the loop reads what arrived (a wake-up).
  constexpr int kQuietBatch = 50;
  int quiet_in_a_row = 0;
  while (may_advance()) {
    if (quiet_ && ++quiet_in_a_row > kQuietBatch) {
      quiet_continue_.trigger();
      return;
    }
    if (!quiet_) {
      // What a participant wrote before its ack (team messages, mission and goal status, door
      // commands) has arrived with the ack but may still sit in its reader: taken before the tick
      // is stepped, it counts at this tick whatever order the waitset reports the readers in.
      service_.loop().drain();
      if (!may_advance()) return;
    }
    advance();
  }
}

void SimulatorNode::advance() {
  if (finished_) return;
  take_commands();  // those from outside lockstep (tools, paced mode) are applied at this step
  const auto started = std::chrono::steady_clock::now();

  std::vector<msg::VelocityCommand> commands = std::move(unsynchronised_commands_);
  unsynchronised_commands_.clear();
  if (auto it = commands_by_tick_.find(tick_); it != commands_by_tick_.end()) {
    // Arrival order across participants depends on the network; the application order must not.
    sort_by_robot_and_source(it->second);
    commands.insert(commands.end(), std::make_move_iterator(it->second.begin()),
                    std::make_move_iterator(it->second.end()));
  }
  commands_by_tick_.erase(commands_by_tick_.begin(), commands_by_tick_.upper_bound(tick_));
  apply_commands(commands);
  if (spacecraft_) spacecraft_->step(tick_, options_.settings.step_s);
  world_.step(options_.settings.step_s);
  barrier_.end_tick(tick_);
  ++tick_;
  step_compute_us_total_ += std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - started).count();
  last_advance_ = started;

  if (const std::vector<RobotStatus> robots = world_.robots(); may_stay_quiet(robots))
    keep_quiet(robots);
  else
    open_tick();
  if (options_.max_ticks && tick_ >= *options_.max_ticks) {
    finished_ = true;
    spdlog::info("reached tick {}, the configured end of the run", tick_);
    service_.stop();
  } else if (options_.stop_when_finished && every_robot_finished()) {
    finished_ = true;
    spdlog::info("every robot finished at tick {}: end of the run", tick_);
    service_.stop();
  }
}

bool SimulatorNode::every_robot_finished() const {
  const std::vector<RobotStatus> robots = world_.robots();
  return !robots.empty() && std::all_of(robots.begin(), robots.end(), [&](const RobotStatus& r) {
    const auto reached = goal_reached_.find(r.id);
    return reached != goal_reached_.end() && reached->second;
  });
}

void SimulatorNode::apply_commands(const std::vector<msg::VelocityCommand>& commands) {
  for (const auto& c : commands) {
    const CommandResult result = world_.submit(from_msg(c));
    if (result.accepted)
      ++commands_applied_;
    else
      reject(c, result.reason);
  }
}

void SimulatorNode::reject(const msg::VelocityCommand& c, const std::string& reason) {
  ++commands_rejected_;
  spdlog::warn("rejected velocity command for robot '{}' from '{}' at tick {}: {}", msg::clipped_for_log(c.robot_id),
               msg::clipped_for_log(c.source), c.tick, reason);
  rejection_writer_.write({msg::clipped_id(c.robot_id, msg::kMaxNameLength), msg::clipped_id(c.source, msg::kMaxNameLength),
                           c.tick, reason});
}

void SimulatorNode::handle_spawns() {
  for (const auto& r : spawn_requests_) {
    if (auto answered = spawn_replies_.find(r.request_id); answered != spawn_replies_.end()) {
      spawn_reply_writer_.write(answered->second);
      continue;
    }
    std::optional<geometry::Pose2> pose;
    if (r.has_pose) pose = geometry::Pose2{r.x, r.y, r.theta};
    const SpawnResult result = world_.spawn(r.robot_id, pose);
    msg::SpawnReply reply{r.request_id, r.robot_id,
                          result.accepted ? msg::RequestStatus::Accepted : msg::RequestStatus::Rejected, result.reason};
    if (result.accepted) {
      spdlog::info("robot {} {} for {} at tick {}", r.robot_id, result.already_present ? "re-attached" : "spawned",
                   r.requester, tick_);
      // The robot is part of the current tick from now on: its controller must be able to act on
      // this tick's state before the world may step.
      if (!result.already_present) {
        publish_robot_states({*world_.robot(r.robot_id)});
        radio_dirty_ = true;
      }
    }
    else
      spdlog::warn("spawn of robot '{}' for {} rejected: {}", r.robot_id, r.requester, result.reason);
    spawn_reply_writer_.write(reply);
    spawn_replies_.emplace(r.request_id, std::move(reply));
  }
  spawn_requests_.clear();
}

void SimulatorNode::open_tick() {
  if (quiet_) radio_dirty_ = true;  // the link table was not kept up while quiet
  quiet_ = false;
  wake_ = false;
  const int64_t now_ns = to_ns(static_cast<double>(tick_) * options_.settings.step_s);
  const std::vector<RobotStatus> robots = world_.robots();
  if (radio_dirty_ || tick_ % options_.radio_period_ticks == 0) update_radio();
  deliver_due_messages();
  publish_robot_states(robots);
  publish_perception(robots);
  publish_door_changes();
  update_office(robots);
  if (tick_ > 0) record_metrics(robots);
  const double now_s = std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
  if (spacecraft_) spacecraft_->publish(tick_, now_ns);
  barrier_.begin_tick(tick_, now_s);
  last_clock_ = {tick_, now_ns, to_ns(options_.settings.step_s),
                 lockstep() ? msg::ClockMode::Lockstep : msg::ClockMode::Paced, options_.settings.warp,
                 options_.world_id};
  clock_writer_.write(last_clock_);
  clock_written_ = std::chrono::steady_clock::now();
}

void SimulatorNode::publish_robot_states(const std::vector<RobotStatus>& robots) {
  const int64_t now_ns = to_ns(static_cast<double>(tick_) * options_.settings.step_s);
  for (const RobotStatus& r : robots) {
    state_writer_.write(to_msg(r, tick_, now_ns));
    published_poses_[r.id] = r.pose;
    record_robot(r);
  }
  state_writer_.flush();
}

void SimulatorNode::record_robot(const RobotStatus& r) {
  const int64_t now_ns = to_ns(static_cast<double>(tick_) * options_.settings.step_s);
  if (!options_.picture_svg.empty()) paths_.record(r.id, r.pose.position(), connected_to_teammate(r.id));
  if (trajectory_.is_open())
    trajectory_ << tick_ << ',' << static_cast<double>(now_ns) * 1e-9 << ',' << r.id << ',' << r.pose.x << ','
                << r.pose.y << ',' << r.pose.theta << '\n';
}

void SimulatorNode::write_picture() const {
  if (options_.picture_svg.empty()) return;
  RunPicture picture;
  picture.world = &world_.spec();
  picture.paths = paths_.paths();
  picture.final_robots = world_.robots();
  picture.path_connected = paths_.connected_flags();
  for (const auto& p : world_.spec().polygons) picture.polygon_obstacles.push_back(p.vertices);
  for (const auto& d : world_.doors()) picture.doors.push_back({d.leaf.hinge, d.leaf.tip, !d.closed(), d.id});
  for (const auto& a : scenario_.radio.areas) picture.attenuating_areas.push_back({a.vertices, a.name});
  for (const auto& p : scenario_.places) picture.places.push_back({p.name, p.position, 0.3});
  for (const auto& w : scenario_.waypoints) picture.places.push_back({w.name, w.position, 0.0});
  picture.caption = world_.spec().name + ", tick " + std::to_string(tick_) + " (" +
                    std::to_string(static_cast<int>(world_.time_s())) + " s simulated)";
  std::ofstream out(options_.picture_svg);
  out << render_run_svg(picture);
  if (!out) throw std::runtime_error("cannot write " + options_.picture_svg);
  spdlog::info("picture of the run written to {}", options_.picture_svg);
}

void SimulatorNode::lockstep_changed(const std::string& participant, bool dropped, const std::string& reason) {
  if (dropped)
    spdlog::warn("participant {} dropped from lockstep at tick {}: {}", participant, tick_, reason);
  lockstep_changes_.push_back({++lockstep_changes_count_, tick_, participant, dropped, reason});
  while (lockstep_changes_.size() > kLockstepChangesKept) lockstep_changes_.pop_front();
  publish_status();
}

void SimulatorNode::publish_status() {
  msg::SimulatorStatus s;
  s.tick = tick_;
  s.sim_time_ns = to_ns(static_cast<double>(tick_) * options_.settings.step_s);
  s.robots = static_cast<uint32_t>(world_.robots().size());
  s.lockstep_participants = barrier_.participants();
  s.commands_applied = commands_applied_;
  s.commands_rejected = commands_rejected_;
  s.participants_dropped = participants_dropped_;
  s.mean_step_us = tick_ > 0 ? step_compute_us_total_ / static_cast<double>(tick_) : 0.0;
  s.team_messages_delivered = messages_delivered_;
  s.team_messages_dropped_no_route = messages_no_route_;
  s.team_messages_dropped_lost = messages_lost_;
  s.team_messages_dropped_invalid = messages_invalid_;
  s.lockstep_dropped = barrier_.dropped();
  s.lockstep_changes.assign(lockstep_changes_.begin(), lockstep_changes_.end());
  status_writer_.write(s);
}

// --- Door commands -----------------------------------------------------------------------------

void SimulatorNode::on_door_commands(std::vector<dds::Sample<msg::DoorCommand>> samples) {
  for (const auto& s : samples) {
    if (!s.valid) continue;
    const msg::DoorCommand& c = s.value;
    if (auto problem = msg::first_length_problem(
            {{"door_id", c.door_id, msg::kMaxNameLength}, {"source", c.source, msg::kMaxNameLength}})) {
      ++commands_rejected_;
      spdlog::warn("rejected door command from '{}' at tick {}: {}", msg::clipped_for_log(c.source), tick_, *problem);
      rejection_writer_.write({"", msg::clipped_id(c.source, msg::kMaxNameLength), tick_, *problem});
      continue;
    }
    const CommandResult result = world_.set_door(c.door_id, c.angle);
    wake_ = true;
    if (result.accepted) {
      spdlog::info("door '{}' told to take angle {} by '{}' at tick {}", c.door_id, c.angle, c.source, tick_);
      continue;
    }
    ++commands_rejected_;
    const std::string reason = "door '" + c.door_id + "': " + result.reason;
    spdlog::warn("rejected door command from '{}' at tick {}: {}", c.source, tick_, reason);
    rejection_writer_.write({"", c.source, tick_, reason});
  }
}

// --- Goal status (for the metrics' "finished") ------------------------------------------------

void SimulatorNode::on_foreign_clocks(std::vector<dds::Sample<msg::SimClock>> samples) {
  for (const auto& s : samples) {
    if (!s.valid || s.value.world_id == options_.world_id) continue;
    ++foreign_clock_samples_;
    // A second world ticks as fast as this one: a few errors say it, the count says how much.
    if (foreign_clock_samples_ <= 5 || foreign_clock_samples_ % 1000 == 0)
      spdlog::error("a clock of world {} (tick {}) is on this domain beside this world {} ({} such samples): one "
                    "world per domain; a simulator started at the same moment as this one, or a forged clock",
                    s.value.world_id, s.value.tick, options_.world_id, foreign_clock_samples_);
    service_.heartbeat().set_clock_samples_ignored(foreign_clock_samples_);
  }
}

void SimulatorNode::on_goal_status(std::vector<dds::Sample<msg::GoalStatus>> samples) {
  for (const auto& s : samples)
    if (s.valid) goal_reached_[s.value.robot_id] = s.value.state == msg::GoalState::Reached;
}

void SimulatorNode::on_mission_status(std::vector<dds::Sample<msg::MissionStatus>> samples) {
  for (const auto& s : samples)
    if (s.valid) goal_reached_[s.value.robot_id] = s.value.finished;
}

// --- Radio ------------------------------------------------------------------------------------

void SimulatorNode::update_radio() {
  radio_dirty_ = false;
  const std::vector<RobotStatus> robots = world_.robots();  // sorted by id: the table's indices
  radio_ids_.clear();
  std::vector<geometry::Vec2> positions;
  for (const auto& r : robots) {
    radio_ids_.push_back(r.id);
    positions.push_back(r.pose.position());
  }
  sync_door_leaves(world_.doors(), radio_);  // doors attenuate at their current angle
  links_.update(radio_, positions);
  connectivity_.emplace(links_);

  const auto exact = [&](size_t i, size_t j) { return radio_.link(positions[i], positions[j]); };
  for (const radio::LinkSample& l : link_changes_.update(radio_ids_, links_, exact)) {
    const radio::LinkQuality& q = l.quality;
    if (l.lost)
      spdlog::info("radio link {}-{} lost at tick {} ({:.1f} dBm, margin {:.1f} dB)", l.robot_a, l.robot_b, tick_,
                   q.signal_dbm, q.margin_db);
    link_writer_.write(msg::RadioLink{l.robot_a, l.robot_b, tick_, q.signal_dbm, q.margin_db, q.connected});
  }

  // Compared in place with what was published: the names are copied only when it changed.
  const auto& now = connectivity_->components();
  const auto same_names = [&](const std::vector<size_t>& c, const std::vector<std::string>& ids) {
    return c.size() == ids.size() &&
           std::equal(c.begin(), c.end(), ids.begin(), [&](size_t i, const std::string& id) { return radio_ids_[i] == id; });
  };
  if (!published_components_ || published_components_->size() != now.size() ||
      !std::equal(now.begin(), now.end(), published_components_->begin(), same_names)) {
    std::vector<std::vector<std::string>> components;
    for (const auto& c : now) {
      std::vector<std::string> ids;
      for (size_t i : c) ids.push_back(radio_ids_[i]);
      components.push_back(std::move(ids));
    }
    msg::TeamConnectivity team;
    team.tick = tick_;
    for (const auto& c : components) team.components.push_back({c});
    team.fully_connected = connectivity_->fully_connected();
    team_writer_.write(team);
    published_components_ = std::move(components);
  }
}

bool SimulatorNode::connected_to_teammate(const std::string& robot) const {
  if (!connectivity_) return false;
  const auto it = std::lower_bound(radio_ids_.begin(), radio_ids_.end(), robot);
  if (it == radio_ids_.end() || *it != robot) return false;
  return !connectivity_->neighbours(static_cast<size_t>(it - radio_ids_.begin())).empty();
}

void SimulatorNode::on_outbox(std::vector<dds::Sample<msg::TeamMessage>> samples) {
  if (!samples.empty()) wake_ = true;  // a quiet span ends: somebody is at work
  if (radio_dirty_) update_radio();
  const double now_s = static_cast<double>(tick_) * options_.settings.step_s;
  const auto index_of = [this](const std::string& id) -> std::optional<size_t> {
    const auto it = std::lower_bound(radio_ids_.begin(), radio_ids_.end(), id);
    if (it == radio_ids_.end() || *it != id) return std::nullopt;
    return static_cast<size_t>(it - radio_ids_.begin());
  };
  for (auto& s : samples) {
    if (!s.valid) continue;
    const msg::TeamMessage& m = s.value;
    if (auto problem = msg::first_length_problem({{"message_id", m.message_id, msg::kMaxIdLength},
                                                  {"payload", m.payload, msg::kMaxTextLength}})) {
      ++messages_invalid_;
      spdlog::debug("team message '{}' from '{}' dropped: {}", msg::clipped_for_log(m.message_id),
                    msg::clipped_for_log(m.from), *problem);
      continue;
    }
    const auto from = index_of(m.from);
    std::vector<size_t> recipients;
    if (m.to == msg::kBroadcast) {
      for (size_t i = 0; i < radio_ids_.size(); ++i)
        if (!from || i != *from) recipients.push_back(i);
    } else if (const auto to = index_of(m.to); to && (!from || *to != *from)) {
      recipients.push_back(*to);
    }
    if (!from || recipients.empty()) {
      ++messages_invalid_;
      spdlog::debug("team message '{}' from '{}' to '{}' dropped: {}", m.message_id, m.from, m.to,
                    !from ? "unknown sender" : "unknown recipient");
      continue;
    }
    for (size_t to : recipients) {
      const auto route = connectivity_->route(*from, to);
      if (!route) {
        ++messages_no_route_;
        spdlog::debug("team message '{}' from {} to {} dropped at tick {}: no route", m.message_id, m.from,
                      radio_ids_[to], tick_);
        continue;
      }
      const radio::DeliveryDecision d =
          radio::decide(radio_.parameters().delivery, radio::route_links(links_, *route), now_s, delivery_rng_);
      if (!d.delivered()) {
        ++(d.outcome == radio::DeliveryOutcome::kLost ? messages_lost_ : messages_no_route_);
        spdlog::debug("team message '{}' from {} to {} dropped at tick {}: {}", m.message_id, m.from, radio_ids_[to],
                      tick_, d.outcome == radio::DeliveryOutcome::kLost ? "lost on a weak hop" : "no route");
        continue;
      }
      relay_.push(d.deliver_at_s, msg::TeamDelivery{radio_ids_[to], m.from, m.to, m.message_id, m.payload,
                                                    to_ns(now_s), to_ns(d.deliver_at_s),
                                                    static_cast<uint32_t>(route->size() - 1)});
    }
  }
}

void SimulatorNode::deliver_due_messages() {
  const double now_s = static_cast<double>(tick_) * options_.settings.step_s;
  for (auto& due : relay_.take_due(now_s)) {
    ++messages_delivered_;
    inbox_writer_.write(due.payload);
  }
}

// --- Perception and ground truth ----------------------------------------------------------------

void SimulatorNode::publish_perception(const std::vector<RobotStatus>& robots) {
  for (const auto& r : robots) {
    const auto spec = world_.robot_spec(r.id);
    if (!spec) continue;
    if (has_range_sensor(*spec)) {
      if (auto scan = world_.sense(r.id)) {
        msg::RangeScan m;
        m.robot_id = r.id;
        m.tick = tick_;
        m.angle_min = scan->angle_min;
        m.angle_increment = scan->angle_increment;
        m.max_range = scan->max_range_m;
        m.ranges = std::move(scan->ranges);
        scan_writer_.write(m);
      }
    }
    if (has_door_sensor(*spec)) {
      const auto seen = world_.observe_doors(r.id);
      if (!seen.empty()) {
        msg::DoorObservation m;
        m.robot_id = r.id;
        m.tick = tick_;
        for (const auto& o : seen) m.doors.push_back({o.door_id, o.angle_estimate, o.distance_m, o.bearing_rad});
        door_observation_writer_.write(m);
      }
    }
    if (has_pose_sensor(*spec)) {
      if (const auto pose = world_.observe_pose(r.id))
        pose_writer_.write({r.id, tick_, pose->x, pose->y, pose->theta});
    }
  }
}

bool SimulatorNode::doors_as_published() const {
  const std::vector<DoorStatus> doors = world_.doors();
  if (doors.size() != published_doors_.size()) return false;
  for (size_t i = 0; i < doors.size(); ++i)
    if (!published_doors_[i] || !same_door_state(*published_doors_[i], to_msg(doors[i], tick_))) return false;
  return true;
}

void SimulatorNode::publish_door_changes() {
  const std::vector<DoorStatus> doors = world_.doors();
  published_doors_.resize(doors.size());
  for (size_t i = 0; i < doors.size(); ++i) {
    msg::DoorState now = to_msg(doors[i], tick_);
    if (published_doors_[i] && same_door_state(*published_doors_[i], now)) continue;
    if (published_doors_[i] && published_doors_[i]->closed != now.closed)
      spdlog::info("door '{}' {} at tick {}", now.door_id, now.closed ? "closed" : "open", tick_);
    door_truth_writer_.write(now);
    published_doors_[i] = std::move(now);
  }
}

// --- Office: load and unload ------------------------------------------------------------------

void SimulatorNode::on_handover_requests(std::vector<dds::Sample<msg::HandoverRequest>> samples) {
  if (!samples.empty()) wake_ = true;  // a quiet span ends: somebody is at work
  std::vector<msg::HandoverRequest> requests;
  for (auto& s : samples)
    if (s.valid) requests.push_back(std::move(s.value));
  // Arrival order within a batch depends on the network; the order of serving must not.
  std::stable_sort(requests.begin(), requests.end(), [](const auto& a, const auto& b) {
    return std::tie(a.robot_id, a.request_id) < std::tie(b.robot_id, b.request_id);
  });
  const double now_s = static_cast<double>(tick_) * options_.settings.step_s;
  for (const auto& r : requests) {
    office::DeskRequest request{r.request_id, r.robot_id, office::HandoverKind::load, r.place, r.object_id};
    if (r.kind == msg::HandoverKind::Unload)
      request.kind = office::HandoverKind::unload;
    else if (r.kind != msg::HandoverKind::Load)
      request.kind = static_cast<office::HandoverKind>(-1);  // the desk rejects it as malformed
    std::optional<office::RobotAtDesk> robot;
    if (const auto status = world_.robot(r.robot_id)) {
      const auto spec = world_.robot_spec(r.robot_id);
      const std::uint32_t capacity = spec ? spec->capacity : 0;
      robot = office::RobotAtDesk{status->pose.position(),
                                  static_cast<int>(std::min<std::uint32_t>(capacity, 1u << 30))};
    }
    const office::DeskAnswer answer =
        office_ ? office_->request(request, robot, now_s) : office::no_office_answer(request, now_s);
    spdlog::info("{} request '{}' from '{}' for robot '{}' ({} of '{}' at '{}') at tick {}: {}{}",
                 answer.state == office::DeskAnswerState::rejected ? "rejected" : "answered",
                 msg::clipped_for_log(r.request_id), msg::clipped_for_log(r.requester), msg::clipped_for_log(r.robot_id),
                 office::to_string(request.kind), msg::clipped_for_log(r.object_id), msg::clipped_for_log(r.place), tick_,
                 answer.reason.empty() ? "" : answer.reason + ": ", answer.detail);
    publish_handover(answer);
  }
}

bool SimulatorNode::update_office(const std::vector<RobotStatus>& robots) {
  if (!office_) return false;
  bool published = false;
  std::map<std::string, geometry::Vec2> positions;
  for (const auto& r : robots) positions.emplace(r.id, r.pose.position());
  for (const office::DeskAnswer& a : office_->advance(static_cast<double>(tick_) * options_.settings.step_s, positions)) {
    spdlog::info("handover '{}' of robot '{}' {} at tick {}: {}", a.request_id, a.robot_id, office::to_string(a.state),
                 tick_, a.detail);
    publish_handover(a);
    published = true;
  }
  for (const office::ObjectItem& o : office_->changed_objects()) {
    object_truth_writer_.write(to_msg(o, tick_));
    published = true;
  }
  return published;
}

void SimulatorNode::publish_handover(const office::DeskAnswer& answer) {
  handover_status_writer_.write(to_msg(answer, tick_));
}

// --- Metrics ----------------------------------------------------------------------------------

void SimulatorNode::record_metrics(const std::vector<RobotStatus>& robots) {
  if (!metrics_) return;
  TickSample sample;
  sample.dt_s = options_.settings.step_s;
  for (const auto& r : robots) {
    const auto reached = goal_reached_.find(r.id);
    sample.robots.push_back({r.id, r.pose.position(), reached != goal_reached_.end() && reached->second,
                             connected_to_teammate(r.id)});
  }
  sample.team_fully_connected = !connectivity_ || connectivity_->fully_connected();
  metrics_->add(sample);
}

void SimulatorNode::write_metrics() const {
  if (!metrics_) return;
  const RunMetricsReport report = metrics_->report();
  for (const auto& [suffix, text] : {std::pair<std::string, std::string>{".csv", metrics_csv(report)},
                                     std::pair<std::string, std::string>{".json", metrics_json(report)}}) {
    const std::string path = options_.metrics_prefix + suffix;
    std::ofstream out(path);
    out << text;
    if (!out) throw std::runtime_error("cannot write " + path);
  }
  spdlog::info("metrics of the run written to {}.csv and {}.json", options_.metrics_prefix, options_.metrics_prefix);
}

}  // namespace autonomy::sim
