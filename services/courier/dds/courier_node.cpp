#include "services/courier/dds/courier_node.hpp"

#include "common/msg/text_limits.hpp"
#include "services/courier/core/bridge/engine_schedule_source.hpp"

#include <nlohmann/json.hpp>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>

namespace autonomy::courier {

namespace {

GoalOutcome outcome_of(msg::GoalState s) {
  switch (s) {
    case msg::GoalState::Accepted: return GoalOutcome::accepted;
    case msg::GoalState::Active: return GoalOutcome::active;
    case msg::GoalState::Reached: return GoalOutcome::reached;
    case msg::GoalState::Blocked: return GoalOutcome::blocked;
    case msg::GoalState::Preempted: return GoalOutcome::preempted;
    case msg::GoalState::Rejected: return GoalOutcome::rejected;
    case msg::GoalState::Cancelled: return GoalOutcome::cancelled;
  }
  return GoalOutcome::rejected;
}

HandoverOutcome outcome_of(msg::HandoverState s) {
  switch (s) {
    case msg::HandoverState::Accepted: return HandoverOutcome::accepted;
    case msg::HandoverState::Rejected: return HandoverOutcome::rejected;
    case msg::HandoverState::Completed: return HandoverOutcome::completed;
    case msg::HandoverState::Failed: return HandoverOutcome::failed;
  }
  return HandoverOutcome::rejected;
}

msg::JobState to_msg(JobState s) {
  switch (s) {
    case JobState::queued: return msg::JobState::Queued;
    case JobState::underway: return msg::JobState::Underway;
    case JobState::opportunistic: return msg::JobState::Opportunistic;
    case JobState::completed: return msg::JobState::Completed;
    case JobState::failed: return msg::JobState::Failed;
    case JobState::cancelled: return msg::JobState::Cancelled;
    case JobState::stranded: return msg::JobState::Stranded;
  }
  return msg::JobState::Queued;
}

}  // namespace

CourierNode::CourierNode(service::Service& service, CourierNodeOptions options)
    : service_(service),
      options_(std::move(options)),
      command_topic_(service.participant(), dds::topics::courier_command),
      reply_topic_(service.participant(), dds::topics::courier_reply),
      job_topic_(service.participant(), dds::topics::courier_job_status),
      schedule_topic_(service.participant(), dds::topics::courier_schedule),
      report_topic_(service.participant(), dds::topics::courier_report),
      state_topic_(service.participant(), dds::topics::robot_state),
      door_topic_(service.participant(), dds::topics::door_observation),
      goal_topic_(service.participant(), dds::topics::nav_goal),
      cancel_topic_(service.participant(), dds::topics::nav_cancel),
      goal_status_topic_(service.participant(), dds::topics::goal_status),
      handover_request_topic_(service.participant(), dds::topics::handover_request),
      handover_status_topic_(service.participant(), dds::topics::handover_status),
      command_reader_(service.participant(), command_topic_),
      state_reader_(service.participant(), state_topic_),
      door_reader_(service.participant(), door_topic_),
      goal_status_reader_(service.participant(), goal_status_topic_),
      handover_status_reader_(service.participant(), handover_status_topic_),
      heartbeat_topic_(service.participant(), dds::topics::heartbeat),
      heartbeat_reader_(service.participant(), heartbeat_topic_),
      reply_writer_(service.participant(), reply_topic_),
      job_writer_(service.participant(), job_topic_),
      schedule_writer_(service.participant(), schedule_topic_),
      report_writer_(service.participant(), report_topic_),
      goal_writer_(service.participant(), goal_topic_),
      cancel_writer_(service.participant(), cancel_topic_),
      handover_writer_(service.participant(), handover_request_topic_),
      lockstep_(service, "courier/" + service.options().instance,
                [this](const msg::SimClock& c) { on_tick(c); }) {
  // Travel times for the slowest and widest robot that may join.
  double speed = options_.attach_defaults.max_speed_mps;
  double radius = options_.attach_defaults.radius_m;
  for (const auto& r : options_.robots) {
    speed = std::min(speed, r.max_speed_mps);
    radius = std::max(radius, r.radius_m);
  }
  EngineSourceSettings settings;
  settings.speed_mps = 0.8 * speed;  // the behavior slows down near walls and doorways
  settings.robot_radius_m = radius;
  settings.resolution_m = options_.grid_resolution_m;
  settings.engine = options_.engine;
  settings.exact_max_jobs = options_.exact_max_jobs;
  settings.budget_ms = options_.budget_ms;
  scheduler_ = std::make_unique<EngineScheduleSource>(options_.office.knowledge, options_.office.floor,
                                                      options_.office.map, settings);
  if (!options_.events_path.empty()) {
    events_file_.open(options_.events_path, std::ios::app);
    if (!events_file_) throw std::runtime_error("cannot write the events file " + options_.events_path);
  }
  journal_ = std::make_unique<Journal>(options_.journal_path);
  ExecutiveSettings executive_settings;
  executive_settings.id_tag = "r" + std::to_string(journal_->run());
  executive_settings.day = journal_->run() * 100000;  // vote_day() before the first tick
  executive_settings.monitor_doors = options_.monitor_doors;
  executive_ = std::make_unique<CourierExecutive>(options_.office.floor, *scheduler_, executive_settings);
  if (options_.learning) {
    executive_->experience() = journal_->load_experience();
    scheduler_->use_experience(&executive_->experience());
    spdlog::info("learning: {} people, {} doors, {} place pairs known from earlier runs",
                 executive_->experience().handovers().size(), executive_->experience().doors().size(),
                 executive_->experience().travel().size());
  }
  std::set<std::string> declared;
  for (const auto& r : options_.robots) declared.insert(r.id);
  roster_ = std::make_unique<FleetRoster>(declared, options_.robot_lost_after_s);
  const Journal::Contents journalled = journal_->load();
  int unfinished = 0;
  for (const Job& job : journalled.jobs) {
    if (!job.finished()) {
      ++unfinished;
      executive_->restore_job(job);
    }
  }
  // Robots join later (their heartbeats): the executive keeps each order until its robot does,
  // then asks again with the same id before anything else is sent to that robot.
  for (const HandoverOrder& h : journalled.unanswered) executive_->restore_pending_handover(h);
  spdlog::info("journal {}: {} jobs ({} unfinished), {} handover requests to ask again", options_.journal_path,
               journalled.jobs.size(), unfinished, journalled.unanswered.size());
  // A restarted courier's job states are gone from the wire with its old writer: publish them again.
  for (const Job& job : journalled.jobs) job_writer_.write(status_of(job, 0));
  desk_ = std::make_unique<CommandDesk>(options_.office.knowledge, *executive_, *journal_, journalled.jobs_created);

  auto& loop = service.loop();
  loop.on_samples<msg::CourierCommand>(command_reader_, [this](auto samples) {
    for (const auto& s : samples) {
      if (!s.valid) continue;
      msg::CourierReply reply = desk_->handle(s.value, now_sim_s(), tick_);
      if (reply.accepted)
        spdlog::info("command {} accepted: {} {} ({} -> {})", reply.command_id, reply.action, reply.object,
                     reply.from, reply.to);
      else
        spdlog::warn("command {} rejected: {}: {}", msg::clipped_for_log(s.value.command_id), reply.reason,
                     reply.detail);
      reply_writer_.write(reply);
    }
    wake_if_needed();
  });
  loop.on_samples<msg::RobotState>(state_reader_, [this](auto samples) {
    for (const auto& s : samples) {
      if (!s.valid) continue;
      poses_[s.value.robot_id] = {s.value.x, s.value.y};  // a robot that joins later starts from it
      if (executive_->has_robot(s.value.robot_id)) executive_->on_pose(s.value.robot_id, s.value.x, s.value.y);
    }
    wake_if_needed();
  });
  loop.on_samples<msg::DoorObservation>(door_reader_, [this](auto samples) {
    for (const auto& s : samples) {
      if (!s.valid || !executive_->has_robot(s.value.robot_id)) continue;
      for (const auto& d : s.value.doors) executive_->on_door(s.value.robot_id, d.door_id, d.angle_estimate, day_s_of(s.value.tick));
    }
    wake_if_needed();
  });
  loop.on_samples<msg::GoalStatus>(goal_status_reader_, [this](auto samples) {
    for (const auto& s : samples) {
      if (!s.valid || !executive_->has_robot(s.value.robot_id)) continue;
      executive_->on_goal(s.value.robot_id, s.value.goal_id, outcome_of(s.value.state), s.value.reason,
                          day_s_of(s.value.tick));
    }
    wake_if_needed();
  });
  loop.on_samples<msg::HandoverStatus>(handover_status_reader_, [this](auto samples) {
    for (const auto& s : samples) {
      if (!s.valid || !executive_->has_robot(s.value.robot_id)) continue;
      const auto& h = s.value;
      // Journalled with the job states it leads to, at this tick's end (carry_out).
      if (h.state != msg::HandoverState::Accepted) answers_.emplace_back(h.request_id, msg::to_string(h.state));
      executive_->on_handover(h.request_id, outcome_of(h.state), h.reason, h.detail, day_s_of(h.tick));
    }
    wake_if_needed();
  });
  loop.on_samples<msg::Heartbeat>(heartbeat_reader_, [this](auto samples) { on_heartbeats(std::move(samples)); });
  // A killed process sends nothing more: its heartbeat goes silent (and, a lease later, its writer).
  // Heartbeats that came while a long tick ran are taken first, so a busy courier never takes its
  // own delay for a robot's silence.
  loop.every(std::chrono::milliseconds(250), [this] {
    on_heartbeats(heartbeat_reader_.take());
    apply(roster_->expire(std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count()));
  });
  lockstep_.register_participant();
  service_.set_ready();
  spdlog::info("courier ready: {} robots declared, others join with the courier capability, engine {}, journal {}",
               options_.robots.size(), options_.engine, options_.journal_path);
}

const CourierRobotSpec& CourierNode::spec_of(const std::string& robot) const {
  for (const auto& r : options_.robots)
    if (r.id == robot) return r;
  return options_.attach_defaults;
}

void CourierNode::on_heartbeats(std::vector<dds::Sample<msg::Heartbeat>> samples) {
  const double now = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
  for (const auto& s : samples) {
    if (s.value.service != "behavior") continue;
    BeatKind kind = BeatKind::ready;
    if (!s.valid || s.instance_state != dds::InstanceState::Alive)
      kind = s.instance_state == dds::InstanceState::NoWriters ? BeatKind::no_writers : BeatKind::disposed;
    else if (s.value.state == msg::ServiceState::Stopping)
      kind = BeatKind::stopping;
    else if (s.value.state == msg::ServiceState::Starting)
      kind = BeatKind::starting;
    apply(roster_->on_heartbeat(s.value.instance, kind, s.valid ? s.value.capabilities : std::vector<std::string>{}, now));
  }
}

void CourierNode::apply(const std::vector<RosterChange>& changes) {
  for (const RosterChange& c : changes) {
    if (c.joined) {
      const CourierRobotSpec& spec = spec_of(c.robot);
      spdlog::info("{} joins the fleet (capacity {})", c.robot, spec.capacity);
      executive_->add_robot(c.robot, spec.capacity);
      if (const auto pose = poses_.find(c.robot); pose != poses_.end())
        executive_->on_pose(c.robot, pose->second.first, pose->second.second);
    } else {
      spdlog::warn("{} leaves the fleet: {}", c.robot, c.why);
      executive_->remove_robot(c.robot, c.why, now_day_s());
    }
  }
  if (!changes.empty()) wake_if_needed();
}

double CourierNode::now_sim_s() const { return lockstep_.clock().now_s(); }
// Each run of the service is a new day of learning (the experiment runs a day per run), and so
// is each midnight a long run passes.
std::int64_t CourierNode::vote_day() const {
  return journal_->run() * 100000 + options_.office.knowledge.clock.day_of(now_sim_s());
}

double CourierNode::now_day_s() const { return options_.office.knowledge.clock.time_of_day(now_sim_s()); }

double CourierNode::day_s_of(std::int64_t tick) const {
  // A sample of a tick our clock has not reached yet: the world ran quiet ticks meanwhile, and
  // its perception is written before its clock (a door seen closed now is not hours old).
  if (tick <= tick_ || step_s_ <= 0.0) return now_day_s();
  return options_.office.knowledge.clock.time_of_day(static_cast<double>(tick) * step_s_);
}

void CourierNode::on_tick(const msg::SimClock& clock) {
  tick_ = clock.tick;
  step_s_ = static_cast<double>(clock.step_ns) * 1e-9;
  have_clock_ = true;
  executive_->set_day(vote_day());
  carry_out(executive_->step(now_day_s()), clock.tick);
  lockstep_.acknowledge(clock.tick, 0, quiet_until_tick());
}

std::int64_t CourierNode::quiet_until_tick() const {
  const auto idle = executive_->idle_until_s(now_day_s());
  if (!idle || step_s_ <= 0.0) return 0;
  double until = *idle;
  if (options_.learning) {
    // Door habits get one vote per half hour from what the robots see: a tick in each.
    const double slot = HalfHourCounts::kSlotS;
    until = std::min(until, (std::floor(now_day_s() / slot) + 1.0) * slot + 3.0 * step_s_);
  }
  // Two ticks early: the robots' sightings of that tick come in before the change is due (a
  // closed door in view is seen again rather than assumed open).
  const double ticks = (until - now_day_s()) / step_s_ - 2.0;
  if (ticks >= 1e15) return std::numeric_limits<std::int64_t>::max();
  if (ticks < 2.0) return 0;
  return tick_ + static_cast<std::int64_t>(ticks);
}

void CourierNode::wake_if_needed() {
  // Something came while the world ran without us: work, or work sooner than announced.
  if (lockstep_.quiet() && quiet_until_tick() < lockstep_.quiet_until_tick()) lockstep_.wake();
}

msg::CourierJobStatus CourierNode::status_of(const Job& job, int64_t tick) const {
  msg::CourierJobStatus s;
  s.job_id = job.id;
  s.command_id = job.command_id;
  s.state = to_msg(job.state);
  s.phase = to_string(job.phase);
  s.robot_id = job.robot;
  s.object_id = job.object.id;
  s.object_kind = job.object.kind;
  s.object_colour = job.object.colour;
  s.from = job.pickup;
  s.to = job.destination;
  s.deadline = job.deadline_s ? clock_text(*job.deadline_s) : "";
  s.estimated_completion = job.estimated_completion_s ? clock_text(*job.estimated_completion_s) : "";
  s.reason = job.reason;
  s.allocation = job.allocation;
  s.tick = tick;
  return s;
}

CourierNode::~CourierNode() {
  try {
    save_experience();
  } catch (const std::exception& e) {
    spdlog::error("learning: what was learned in this run could not be saved: {}", e.what());
  }
}

void CourierNode::save_experience() {
  if (!options_.learning || !executive_ || executive_->experience().unsaved() == 0) return;
  journal_->save_experience(executive_->experience());
  executive_->experience().mark_saved();
  experience_saved_at_s_ = now_sim_s();
}

void CourierNode::carry_out(Orders orders, int64_t tick) {
  for (const auto& e : orders.events) {
    spdlog::info("{}", e.text);
    if (events_file_) {
      // One JSON object per line: when, where each robot was, and what happened.
      nlohmann::json line = {{"tick", tick},   {"sim_s", now_sim_s()},        {"time", clock_text(now_day_s())},
                             {"kind", to_string(e.kind)}, {"text", e.text}};
      for (const auto& [id, pose] : poses_) line["robots"][id] = {pose.first, pose.second};
      events_file_ << line.dump() << "\n";
    }
  }
  if (events_file_) events_file_.flush();
  // The journal first: what goes on the wire is never ahead of what a restart would know.
  std::vector<const Job*> changed;
  for (const auto& id : orders.changed_jobs)
    if (const Job* job = executive_->job(id)) changed.push_back(job);
  journal_->save_progress(changed, answers_);
  answers_.clear();
  // What was learned: at most once a simulated minute (and when the service stops).
  if (now_sim_s() - experience_saved_at_s_ >= 60.0) save_experience();
  for (const Job* job : changed) job_writer_.write(status_of(*job, tick));
  for (const auto& h : orders.handovers) {
    journal_->record_handover(h);
    handover_writer_.write({h.request_id, "courier", h.robot, h.load ? msg::HandoverKind::Load : msg::HandoverKind::Unload,
                            h.place, h.object_id});
  }
  for (const auto& c : orders.cancels) cancel_writer_.write({c.robot, c.goal_id, c.reason});
  for (const auto& g : orders.goals) goal_writer_.write({g.robot, g.goal_id, g.x, g.y, g.tolerance_m, ""});
  for (const auto& note : orders.schedules) {
    msg::CourierSchedule s;
    s.robot_id = note.robot;
    s.engine = note.engine;
    s.proved_optimal = note.proved_optimal;
    for (const PlanStop& stop : note.stops)
      s.stops.push_back({stop.job_id, stop.load ? "load" : "unload", stop.place, stop.room, stop.arrival_s,
                         stop.finish_s});
    s.assumptions = note.assumptions;
    s.late_jobs = note.late_jobs;
    s.total_lateness_s = note.total_lateness_s;
    s.tick = tick;
    schedule_writer_.write(s);
  }
  for (const auto& r : orders.reports) report_writer_.write({r.command_id, r.job_id, r.success, r.text, tick});
}

}  // namespace autonomy::courier
