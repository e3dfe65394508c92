#include "simulator/dds/simulator_node.hpp"

#include "simulator/report/run_svg.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace autonomy::sim {

namespace {

constexpr auto kHousekeepingPeriod = std::chrono::milliseconds(10);
constexpr auto kStatusPeriod = std::chrono::milliseconds(200);

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

int64_t to_ns(double seconds) { return static_cast<int64_t>(std::llround(seconds * 1e9)); }

}  // namespace

SimulatorNode::SimulatorNode(service::Service& service, World world, SimulatorRunOptions options)
    : service_(service),
      world_(std::move(world)),
      options_(std::move(options)),
      last_advance_(std::chrono::steady_clock::now()),
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
      clock_writer_(service.participant(), clock_topic_),
      state_writer_(service.participant(), state_topic_),
      rejection_writer_(service.participant(), rejection_topic_),
      spawn_reply_writer_(service.participant(), spawn_reply_topic_),
      map_writer_(service.participant(), map_topic_),
      status_writer_(service.participant(), status_topic_),
      cmd_reader_(service.participant(), cmd_topic_),
      ack_reader_(service.participant(), ack_topic_),
      registration_reader_(service.participant(), registration_topic_),
      spawn_request_reader_(service.participant(), spawn_request_topic_) {
  if (!options_.trajectory_csv.empty()) {
    trajectory_.open(options_.trajectory_csv);
    if (!trajectory_) throw std::runtime_error("cannot write trajectory file " + options_.trajectory_csv);
    trajectory_ << "tick,time_s,robot,x,y,theta\n";
  }

  const WorldSpec& spec = world_.spec();
  map_writer_.write({spec.name, spec.width, spec.height, spec.obstacles});

  auto& loop = service.loop();
  loop.on_samples<msg::VelocityCommand>(cmd_reader_, [this](auto s) { on_commands(std::move(s)); });
  loop.on_samples<msg::TickAck>(ack_reader_, [this](auto s) { on_acks(std::move(s)); });
  loop.on_samples<msg::LockstepRegistration>(registration_reader_, [this](auto s) { on_registrations(std::move(s)); });
  loop.on_samples<msg::SpawnRequest>(spawn_request_reader_, [this](auto s) { on_spawn_requests(std::move(s)); });
  loop.every(kHousekeepingPeriod, [this] { on_timer(); });
  loop.every(kStatusPeriod, [this] { publish_status(); });

  open_tick();
  spdlog::info("world '{}' {}x{} m, {} obstacles, {} robots, {} mode, step {} s", spec.name, spec.width, spec.height,
               spec.obstacles.size(), world_.robots().size(), lockstep() ? "lockstep" : "paced",
               options_.settings.step_s);
  service.set_ready();
}

SimulatorNode::~SimulatorNode() {
  try {
    publish_status();
    write_picture();
    spdlog::info("stopped at tick {}: {} commands applied, {} rejected, {} participants dropped", tick_,
                 commands_applied_, commands_rejected_, participants_dropped_);
  } catch (const std::exception& e) {
    spdlog::warn("final status not published: {}", e.what());
  }
}

void SimulatorNode::on_commands(std::vector<dds::Sample<msg::VelocityCommand>> samples) {
  for (auto& s : samples) {
    if (!s.valid) continue;
    msg::VelocityCommand& c = s.value;
    const auto members = barrier_.participants();
    const bool synchronised = lockstep() && c.tick >= tick_ &&
                              std::binary_search(members.begin(), members.end(), c.source);
    if (synchronised && barrier_.on_command(c.source, c.tick)) {
      commands_by_tick_[c.tick].push_back(std::move(c));
    } else {
      unsynchronised_commands_.push_back(std::move(c));
    }
  }
  advance_while_complete();
}

void SimulatorNode::on_acks(std::vector<dds::Sample<msg::TickAck>> samples) {
  if (!lockstep()) return;
  for (const auto& s : samples) {
    if (!s.valid) continue;
    if (barrier_.on_ack(s.value.participant, s.value.tick, s.value.commands_sent) ==
        LockstepBarrier::AckOutcome::Rejoined)
      spdlog::info("participant {} answered again at tick {} and rejoined lockstep", s.value.participant, s.value.tick);
  }
  advance_while_complete();
}

void SimulatorNode::on_registrations(std::vector<dds::Sample<msg::LockstepRegistration>> samples) {
  for (const auto& s : samples) {
    const std::string& name = s.value.participant;
    if (s.valid && s.value.active && s.instance_state == dds::InstanceState::Alive) {
      if (barrier_.add(name)) spdlog::info("participant {} joined lockstep at tick {}", name, tick_);
    } else {
      barrier_.remove(name);
      spdlog::info("participant {} left lockstep at tick {}", name, tick_);
    }
  }
  advance_while_complete();
}

void SimulatorNode::on_spawn_requests(std::vector<dds::Sample<msg::SpawnRequest>> samples) {
  for (auto& s : samples)
    if (s.valid) spawn_requests_.push_back(std::move(s.value));
  handle_spawns();
}

bool SimulatorNode::holding_start() const {
  if (!lockstep() || tick_ != 0) return false;
  const auto members = barrier_.participants();
  return std::any_of(options_.wait_for_participants.begin(), options_.wait_for_participants.end(),
                     [&](const std::string& p) { return !std::binary_search(members.begin(), members.end(), p); });
}

void SimulatorNode::on_timer() {
  const auto now = std::chrono::steady_clock::now();
  const auto period = std::chrono::duration<double>(options_.settings.step_s / options_.settings.warp);
  if (lockstep()) {
    const double now_s = std::chrono::duration<double>(now.time_since_epoch()).count();
    for (const auto& p : barrier_.expire(tick_, now_s, options_.settings.ack_timeout_s)) {
      ++participants_dropped_;
      spdlog::warn("participant {} did not acknowledge tick {} within {} s: dropped from lockstep", p, tick_,
                   options_.settings.ack_timeout_s);
    }
    // Nobody to wait for: the world idles forward in real time instead of spinning.
    if (barrier_.participants().empty() && !holding_start() && now - last_advance_ >= period) advance();
    advance_while_complete();
  } else if (now - last_advance_ >= period) {
    advance();
  }
}

void SimulatorNode::advance_while_complete() {
  if (!lockstep()) return;
  while (!finished_ && !barrier_.participants().empty() && !holding_start() && barrier_.complete(tick_)) advance();
}

void SimulatorNode::advance() {
  if (finished_) return;
  const auto started = std::chrono::steady_clock::now();

  std::vector<msg::VelocityCommand> commands = std::move(unsynchronised_commands_);
  unsynchronised_commands_.clear();
  if (auto it = commands_by_tick_.find(tick_); it != commands_by_tick_.end()) {
    // Arrival order across participants depends on the network; the application order must not.
    std::stable_sort(it->second.begin(), it->second.end(), [](const auto& a, const auto& b) {
      return std::tie(a.robot_id, a.source) < std::tie(b.robot_id, b.source);
    });
    commands.insert(commands.end(), it->second.begin(), it->second.end());
  }
  commands_by_tick_.erase(commands_by_tick_.begin(), commands_by_tick_.upper_bound(tick_));
  apply_commands(commands);
  world_.step(options_.settings.step_s);
  barrier_.end_tick(tick_);
  ++tick_;
  step_compute_us_total_ += std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - started).count();
  last_advance_ = started;

  open_tick();
  if (options_.max_ticks && tick_ >= *options_.max_ticks) {
    finished_ = true;
    spdlog::info("reached tick {}, the configured end of the run", tick_);
    service_.stop();
  }
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
  spdlog::warn("rejected velocity command for robot '{}' from '{}' at tick {}: {}", c.robot_id, c.source, c.tick, reason);
  rejection_writer_.write({c.robot_id, c.source, c.tick, reason});
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
      if (!result.already_present) publish_robot_state(*world_.robot(r.robot_id));
    }
    else
      spdlog::warn("spawn of robot '{}' for {} rejected: {}", r.robot_id, r.requester, result.reason);
    spawn_reply_writer_.write(reply);
    spawn_replies_.emplace(r.request_id, std::move(reply));
  }
  spawn_requests_.clear();
}

void SimulatorNode::open_tick() {
  const int64_t now_ns = to_ns(static_cast<double>(tick_) * options_.settings.step_s);
  for (const auto& r : world_.robots()) publish_robot_state(r);
  const double now_s = std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
  barrier_.begin_tick(tick_, now_s);
  clock_writer_.write({tick_, now_ns, to_ns(options_.settings.step_s),
                       lockstep() ? msg::ClockMode::Lockstep : msg::ClockMode::Paced, options_.settings.warp});
}

void SimulatorNode::publish_robot_state(const RobotStatus& r) {
  const int64_t now_ns = to_ns(static_cast<double>(tick_) * options_.settings.step_s);
  state_writer_.write(to_msg(r, tick_, now_ns));
  if (!options_.picture_svg.empty()) paths_.record(r.id, r.pose.position());
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
  picture.caption = world_.spec().name + ", tick " + std::to_string(tick_) + " (" +
                    std::to_string(static_cast<int>(world_.time_s())) + " s simulated)";
  std::ofstream out(options_.picture_svg);
  out << render_run_svg(picture);
  if (!out) throw std::runtime_error("cannot write " + options_.picture_svg);
  spdlog::info("picture of the run written to {}", options_.picture_svg);
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
  status_writer_.write(s);
}

}  // namespace autonomy::sim
