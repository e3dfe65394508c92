#include "executive_node.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "plan_message.hpp"

namespace autonomy::executive {
namespace {

using WallClock = PlannerLink::Clock;

std::chrono::nanoseconds seconds(double s) {
  return std::chrono::nanoseconds(static_cast<std::int64_t>(s * 1e9));
}

double wall_s(WallClock::duration d) { return std::chrono::duration<double>(d).count(); }

// Parameters a state value can carry: each one value, not a set or an interval.
bool single_values(const std::vector<std::string>& parameters) {
  return std::all_of(parameters.begin(), parameters.end(), [](const std::string& p) {
    return !p.empty() && p.find_first_of("[{, ") == std::string::npos;
  });
}

std::optional<msg::PlannerTimelineValue> value_of(const planner::PlanToken& t) {
  if (!single_values(t.parameters)) return std::nullopt;
  return msg::PlannerTimelineValue{t.timeline(), t.predicate, t.parameters};
}

std::string value_text(const msg::PlannerTimelineValue& v) {
  std::string text = v.predicate + "(";
  for (std::size_t i = 0; i < v.parameters.size(); ++i) text += (i ? ", " : "") + v.parameters[i];
  return text + ")";
}

bool usable(const msg::PlanningReply& r) {
  const bool status_has_plan = r.status == msg::PlanningStatus::Optimal ||
                               r.status == msg::PlanningStatus::PlanFound ||
                               r.status == msg::PlanningStatus::OutOfTime ||
                               r.status == msg::PlanningStatus::Cancelled;
  return status_has_plan && r.has_plan && r.violations.empty();
}

}  // namespace

ExecutiveNode::ExecutiveNode(service::Service& service, ExecutiveNodeOptions options,
                             ExecutiveConfig config, Mission mission)
    : service_(service),
      options_(std::move(options)),
      config_(std::move(config)),
      mission_(std::move(mission)),
      name_("executive/" + service.options().instance),
      spacecraft_(service.participant(), name_, options_.spacecraft),
      robots_(config_.robots.empty() ? nullptr
                                     : std::make_unique<RobotLink>(service.participant(), name_,
                                                                   config_.robots)),
      planner_(service.participant(), name_),
      event_topic_(service.participant(), dds::topics::executive_event),
      status_topic_(service.participant(), dds::topics::executive_status),
      event_writer_(service.participant(), event_topic_),
      status_writer_(service.participant(), status_topic_),
      lockstep_(service, name_,
                [this](const msg::SimClock& clock) { on_tick(clock); }),
      watchdog_(seconds(options_.watchdog_s),
                [this](WallClock::duration busy) { safe_from_watchdog(busy); },
                [this] { spdlog::info("watchdog: ticks are answered again"); }) {
  auto& loop = service.loop();
  loop.on_condition(planner_.reply_reader().data_condition(), [this] { on_reply(); });
  loop.every(std::chrono::milliseconds(20), [this] { on_timer(); });
  loop.every(std::chrono::seconds(1), [this] { publish_status(); });
  if (!options_.journal_path.empty()) {
    journal_ = std::make_unique<FlightJournal>(options_.journal_path, config_.problem_path);
    restore_from_journal();
  }
  lockstep_.register_participant();
  spdlog::info("executive {}: mission {} ({} goals, horizon {} s, plans of {} s), {} command rules",
               name_, config_.problem_path, mission_.goal_labels().size(), mission_.horizon(),
               config_.horizon_s > 0 ? config_.horizon_s : mission_.horizon(), config_.rules.size());
  service.set_ready();
}

const char* ExecutiveNode::state_name() const {
  switch (state_) {
    case State::kWaitingForPlan: return "waiting_for_plan";
    case State::kExecuting: return "executing";
    case State::kSafeWaiting: return "safe_waiting_for_plan";
    case State::kFinished: return "finished";
  }
  return "?";
}

void ExecutiveNode::event(const std::string& kind, Time now, const std::string& text) {
  msg::ExecutiveEvent e{name_, ++events_, last_tick_, now * 1000000000LL, kind, text, plan_id_};
  if (kind.rfind("fault", 0) == 0 || kind == "aborted" || kind == "violation" ||
      kind.rfind("plan_", 0) == 0 || kind == "goal_lost" || kind == "rejected")
    spdlog::info("{} at {} s: {}", kind, now, text);
  else
    spdlog::debug("{} at {} s: {}", kind, now, text);
  event_writer_.write(e);
  report_.add_event(now, kind, text);
}

void ExecutiveNode::on_tick(const msg::SimClock& clock) {
  if (clock.tick <= last_tick_) return;
  if (held_) {  // the world went on without our ack (we were dropped): answer the held one
    lockstep_.acknowledge(held_->clock.tick, held_commands_);
    held_.reset();
  }
  run_tick(clock);
}

void ExecutiveNode::run_tick(const msg::SimClock& clock) {
  watchdog_.tick_started();
  last_tick_ = clock.tick;
  watched_tick_.store(clock.tick);
  now_ = static_cast<Time>(std::floor(static_cast<double>(clock.sim_time_ns) * 1e-9 + 1e-6));
  if (auto t = spacecraft_.take_telemetry()) {
    for (const Confirmation& c : spacecraft_.confirmations(*t))
      if (executive_ && executive_->confirm(c.device, c.command))
        event("confirmed", now_, c.device + " " + c.command + " (" + c.command_id + ")");
    telemetry_ = std::move(t);
  }
  std::vector<std::pair<DeviceCommand, std::string>> rejections = spacecraft_.take_rejections();
  if (robots_) {
    for (const Confirmation& c : robots_->update())
      if (executive_ && executive_->confirm(c.device, c.command))
        event("confirmed", now_, c.device + " " + c.command + " (" + c.command_id + ")");
    for (auto& r : robots_->take_rejections()) rejections.push_back(std::move(r));
  }
  for (const auto& [command, reason] : rejections) {
    if (executive_) executive_->rejected(command, reason);
    event("rejected", now_, command.device + " " + command.command + " rejected: " + reason);
  }

  std::vector<DeviceCommand> out;
  if (journal_) journal_->alive(now_);
  if (resume_pending_) resume(out);
  ask_first();
  settle();
  reask();
  if (state_ == State::kExecuting) {
    dispatch(now_, out);
  } else if (state_ == State::kSafeWaiting && executive_) {
    // Safe and waiting: the aborted plan's executive still answers faults.
    step_plan(observed(now_), out);
  }
  if (state_ != State::kFinished && now_ >= mission_.horizon())
    end_mission("the mission ended before a plan had it (" + std::string(state_name()) + ")");
  finish_tick(clock, send(out, clock.tick));
  watchdog_.tick_ended();
}

std::uint32_t ExecutiveNode::send(const std::vector<DeviceCommand>& commands, std::int64_t tick) {
  // Robot commands go to behavior controllers, the rest to the spacecraft; only the latter are
  // counted in the simulator's TickAck (the controllers answer their own ticks).
  if (!robots_) return spacecraft_.send(commands, tick);
  std::vector<DeviceCommand> to_robots, to_spacecraft;
  for (const DeviceCommand& c : commands)
    (robots_->handles(c.device) ? to_robots : to_spacecraft).push_back(c);
  robots_->send(to_robots);
  return spacecraft_.send(to_spacecraft, tick);
}

Observations ExecutiveNode::observed(Time now) const {
  Observations seen = telemetry_ ? observations_of(*telemetry_, now) : Observations{};
  seen.time = now;
  if (robots_) robots_->observe(seen);
  return seen;
}

std::map<std::string, std::string> ExecutiveNode::device_modes() const {
  std::map<std::string, std::string> modes;
  if (telemetry_)
    for (const msg::DeviceReport& d : telemetry_->devices) modes[d.device] = d.mode;
  if (robots_) {
    Observations seen;
    robots_->observe(seen);
    for (auto& [device, mode] : seen.device_modes) modes[device] = mode;
  }
  return modes;
}

PlannerLink::Clock::duration ExecutiveNode::hold_limit() const { return seconds(options_.plan_hold_s); }

void ExecutiveNode::finish_tick(const msg::SimClock& clock, std::uint32_t sent) {
  lockstep_mode_ = clock.mode == msg::ClockMode::Lockstep;
  // In lockstep the world waits for the plan: planning takes no simulated time.
  const bool waiting = state_ == State::kWaitingForPlan || state_ == State::kSafeWaiting ||
                       (state_ == State::kExecuting && now_ >= horizon_end_ && !next_plan_ &&
                        horizon_end_ < mission_.horizon());
  // The hold is bounded per outage, not per request: requests asked again while the planner
  // stays silent or refuses do not renew it (a plan or a proof of infeasibility does).
  const bool may_hold = !hold_since_ || WallClock::now() - *hold_since_ < hold_limit();
  if (waiting && (state_ == State::kWaitingForPlan || planner_.waiting()) &&
      clock.mode == msg::ClockMode::Lockstep && may_hold) {
    if (!hold_since_) hold_since_ = WallClock::now();
    held_ = HeldTick{clock};
    held_commands_ = sent;
    spdlog::debug("tick {} held for a plan", clock.tick);
  } else {
    held_.reset();
    lockstep_.acknowledge(clock.tick, sent);
  }
}

void ExecutiveNode::ask_first() {
  // The first horizon is asked for at the first tick with a planner there to hear it.
  if (state_ != State::kWaitingForPlan || planner_.waiting() || !asked_purpose_.empty() ||
      last_tick_ < 0 || planner_.planners() == 0)
    return;
  // On the horizons' grid (a restart before any plan began joins it where it is).
  ask_for_plan(now_, horizon_end_for(now_), {}, "first horizon");
}

void ExecutiveNode::dispatch(Time now, std::vector<DeviceCommand>& out) {
  const Observations seen = observed(now);
  // The plan's own step first: at its horizon's end its last tokens end there.
  if (!step_plan(seen, out)) return;
  if (now >= horizon_end_ && next_plan_) {
    msg::PlanningReply next = std::move(*next_plan_);
    next_plan_.reset();
    const Time origin = horizon_end_;
    const Time end = std::min(origin + config_.horizon_s, mission_.horizon());
    ++horizons_;
    next_asked_ = false;
    start_plan(next, origin, end, next_goals_);
    event("horizon_joined", now, "plan " + plan_id_ + " for [" + std::to_string(origin) + ", " +
                                     std::to_string(end) + ") s joined at " + std::to_string(now) + " s");
    if (!step_plan(seen, out)) return;
  }
  if (now >= horizon_end_ && horizon_end_ >= mission_.horizon()) {
    end_mission("the mission ended before it was achieved");
    return;
  }
  if (!next_asked_ && horizon_end_ < mission_.horizon() &&
      now >= horizon_end_ - config_.request_lead_s && !planner_.waiting()) {
    next_asked_ = true;
    ask_for_plan(horizon_end_, std::min(horizon_end_ + config_.horizon_s, mission_.horizon()),
                 held_values(), "next horizon");
  }
}

bool ExecutiveNode::step_plan(const Observations& seen, std::vector<DeviceCommand>& out) {
  if (seen.time == stepped_at_) return true;  // a held tick finished later: stepped already
  stepped_at_ = seen.time;
  const auto t0 = WallClock::now();
  Tick result = executive_->step(seen);
  const double us = std::chrono::duration<double, std::micro>(WallClock::now() - t0).count();
  decision_us_sum_ += us;
  decision_us_max_ = std::max(decision_us_max_, us);
  ++decisions_;
  for (const ExecutiveEvent& e : result.events) {
    event(e.kind, e.time, e.text);
    note_goals(e);
  }
  for (DeviceCommand& c : result.commands) out.push_back(std::move(c));
  for (const std::string& d : executive_->disabled_devices())
    if (!disabled_.count(d)) disable(d, "no longer commanded (a command was not confirmed)");
  for (const std::string& s : executive_->ignored_sensors()) ignore_sensor(s);
  if (!result.replan) {
    const bool changed = std::any_of(result.events.begin(), result.events.end(), [](const ExecutiveEvent& e) {
      return e.kind == "started" || e.kind == "ended";
    });
    if (changed && !executive_->aborted()) journal_state(seen);
    return !executive_->aborted();
  }

  // Aborted: safing is in `out`; ask for the rest of the horizon from now.
  const ReplanRequest& r = *result.replan;
  fault_seen_ = WallClock::now();
  ++replans_;
  for (const auto& [device, mode] : r.known_faults)
    if (mode != "failed" && !disabled_.count(device)) disable(device, device + " " + mode);
  next_plan_.reset();
  next_asked_ = false;
  state_ = State::kSafeWaiting;
  planner_.forget();
  // A token the world ends (a turn) goes on after the abort: the new plan starts from where
  // it arrives, once it has (its report), not from a value no plan can start with.
  settle_target(r, settle_state_, settling_);
  settle_purpose_ = "replan: " + r.reason;
  if (journal_) journal_->plan(plan_id_, horizon_end_, settle_state_, settling_, executing_goals(), seen.time);
  settle_deadline_ = seen.time + kSettleLimit;
  if (settling_.empty()) {
    ask_for_plan(seen.time, horizon_end_for(seen.time), settle_state_, settle_purpose_);
  } else {
    std::string what;
    for (const auto& [device, s] : settling_) what += (what.empty() ? "" : ", ") + device + " " + s.end_mode;
    event("settling", seen.time, "replanning once " + what + " (at most " + std::to_string(kSettleLimit) + " s)");
  }
  return false;
}

void ExecutiveNode::settle_target(const ReplanRequest& r, std::vector<msg::PlannerTimelineValue>& values,
                                  std::map<std::string, SettlingRecord>& settling) const {
  values = current_values(r);
  settling.clear();
  const planner::FlexiblePlan& plan = executive_->dispatcher().plan();
  const CommandMap map = config_.command_map();
  for (const planner::PlanTimeline& line : plan.timelines)
    for (std::size_t k = 0; k + 1 < line.tokens.size(); ++k) {
      const std::size_t i = line.tokens[k];
      const CommandRule* rule = map.rule_for(plan.tokens[i]);
      if (!executive_->dispatcher().executing(i) || !rule || rule->end_mode.empty() || disabled_.count(rule->device))
        continue;
      auto after = value_of(plan.tokens[line.tokens[k + 1]]);
      if (!after) continue;
      for (auto& v : values)
        if (v.timeline == line.name) v = *after;
      Settling& s = settling[rule->device];
      s = {rule->end_mode, line.name, std::nullopt};
      if (k > 0) s.if_blocked = value_of(plan.tokens[line.tokens[k - 1]]);
    }
}

void ExecutiveNode::settle() {
  if (state_ != State::kSafeWaiting || settling_.empty()) return;
  for (const auto& [device, mode] : device_modes()) {
    auto it = settling_.find(device);
    if (it == settling_.end()) continue;
    if (it->second.end_mode == mode) {
      settling_.erase(it);
    } else if (mode == kBlockedMode) {
      const Settling& s = it->second;
      for (auto& v : settle_state_)
        if (v.timeline == s.timeline && s.if_blocked) v = *s.if_blocked;
      event("settling", now_,
            device + " blocked before its token ended: replanning from " +
                (s.if_blocked ? value_text(*s.if_blocked) : std::string("the state before it")));
      settling_.erase(it);
    }
  }
  if (!settling_.empty() && now_ < settle_deadline_) return;
  if (!settling_.empty()) event("settling", now_, "not settled in time: replanning anyway");
  settling_.clear();
  ask_for_plan(now_, horizon_end_for(now_), settle_state_, settle_purpose_);
}

std::vector<msg::PlannerTimelineValue> ExecutiveNode::held_values() const {
  std::vector<msg::PlannerTimelineValue> state;
  const std::set<std::string> carried = mission_.state_timelines();
  const planner::FlexiblePlan& plan = executive_->dispatcher().plan();
  for (const planner::PlanTimeline& line : plan.timelines) {
    if (line.tokens.empty() || !carried.count(line.name)) continue;
    const planner::PlanToken& last = plan.tokens[line.tokens.back()];
    // A last token that cannot last to the horizon (a thrust arc) leaves its timeline at rest.
    auto v = last.end_ub < plan.horizon ? mission_.initial_value(line.name) : value_of(last);
    if (v) state.push_back(*v);
  }
  return state;
}

std::vector<msg::PlannerTimelineValue> ExecutiveNode::current_values(const ReplanRequest& r) const {
  // The spacecraft's state timelines carry their current value; on the others (a ground
  // station's schedule) the goal under way is asked for again from now instead.
  std::vector<msg::PlannerTimelineValue> state;
  const std::set<std::string> carried = mission_.state_timelines();
  for (const ReplanRequest::TimelineValue& v : r.state) {
    if (!carried.count(v.timeline)) continue;
    if (single_values(v.parameters)) state.push_back({v.timeline, v.predicate, v.parameters});
  }
  apply_safe_values(state);
  return state;
}

void ExecutiveNode::apply_safe_values(std::vector<msg::PlannerTimelineValue>& state) const {
  for (const TimelineValue& safe : config_.safe_values) {
    auto it = std::find_if(state.begin(), state.end(),
                           [&](const auto& v) { return v.timeline == safe.timeline; });
    msg::PlannerTimelineValue v{safe.timeline, safe.predicate, safe.parameters};
    if (it != state.end()) *it = v;
    else state.push_back(v);
  }
}

void ExecutiveNode::ask_for_plan(Time origin, Time end, std::vector<msg::PlannerTimelineValue> state,
                                 const std::string& purpose, bool every_goal_optional) {
  std::map<std::string, std::string> impossible;
  for (const std::string& label : mission_.goal_labels()) {
    const std::string timeline = mission_.goal_timeline(label);
    for (const std::string& device : config_.devices_of(timeline))
      if (auto d = disabled_.find(device); d != disabled_.end()) impossible[timeline] = d->second;
  }
  std::set<std::string> settled;
  for (const auto& [label, how] : achieved_) settled.insert(label);
  for (const auto& [label, why] : lost_) settled.insert(label);
  std::set<std::string> executing;
  if (executive_ && purpose.rfind("replan", 0) == 0) executing = executing_goals();
  // After a restart: the goals the journal had under way.
  if (purpose.rfind("resume", 0) == 0 && journal_) executing = journal_->record().executing_goals;
  // With a device given up, some goals may be out of reach: the planner may leave goals out
  // (rather than search the infeasible problem to exhaustion first).
  if (!impossible.empty()) every_goal_optional = true;
  // The next horizon leaves the current plan's goals to it.
  const bool next_horizon = state_ == State::kExecuting;
  if (next_horizon) settled.insert(current_goals_.begin(), current_goals_.end());
  GoalWindowCut cut = mission_.request(origin, end, state, settled, impossible, executing, every_goal_optional);
  asked_goals_ = cut.goals;
  asked_optional_ = every_goal_optional;
  lose_goals(cut.lost, now_);
  cut.request.engine = every_goal_optional ? config_.optional_engine : config_.planner_engine;
  cut.request.budget_ms = config_.planner_budget_ms;
  asked_origin_ = origin;
  asked_end_ = end;
  asked_state_ = state;
  asked_purpose_ = purpose;
  std::string values;
  for (const auto& v : state) {
    values += (values.empty() ? "" : "; ") + v.timeline + " == " + v.predicate + "(";
    for (std::size_t i = 0; i < v.parameters.size(); ++i) values += (i ? ", " : "") + v.parameters[i];
    values += ")";
  }
  spdlog::debug("asking for [{}, {}) s from state {}", origin, end, values.empty() ? "(the problem's)" : values);
  const std::string id = planner_.ask(std::move(cut.request), purpose);
  event("plan_requested", now_, purpose + ": " + std::to_string(cut.goals.size()) +
                                    (every_goal_optional ? " goals, each optional, for [" : " goals for [") +
                                    std::to_string(origin) + ", " + std::to_string(end) + ") s as " + id);
}

std::set<std::string> ExecutiveNode::executing_goals() const {
  std::set<std::string> executing;
  const planner::FlexiblePlan& plan = executive_->dispatcher().plan();
  for (std::size_t i = 0; i < plan.tokens.size(); ++i) {
    const std::string label = goal_label(plan.tokens[i].origin);
    if (!label.empty() && executive_->dispatcher().executing(i)) executing.insert(label);
  }
  return executing;
}

void ExecutiveNode::ask_again() {
  const std::string why = "no reply within " + std::to_string(options_.plan_timeout_s) + " s (" +
                          std::to_string(planner_.planners()) + " planner(s) matched)";
  event("plan_late", now_, why + ": asking again");
  planner_.cancel();  // a planner still searching answers it with its best plan, then ignored
  planner_.forget();
  if (state_ == State::kExecuting) {  // the next horizon: its origin does not move
    ask_for_plan(asked_origin_, asked_end_, asked_state_, asked_purpose_, asked_optional_);
    return;
  }
  // A safe spacecraft plans from the tick it is at; a tick already answered is past, so the
  // request waits for the next one (which it then holds) unless one is held now.
  reask_ = true;
  if (held_) reask();
}

void ExecutiveNode::reask() {
  if (!reask_ || WallClock::now() < reask_after_) return;
  reask_ = false;
  const Time origin = std::max(asked_origin_, now_);
  ask_for_plan(origin, horizon_end_for(origin), asked_state_, asked_purpose_, asked_optional_);
}

Time ExecutiveNode::horizon_end_for(Time now) const {
  // After a long wait the horizon may be over: plan to the end of the one `now` lies in.
  const Time length = config_.horizon_s > 0 ? config_.horizon_s : mission_.horizon();
  Time end = std::max<Time>(horizon_end_, 0);
  while (end <= now && end < mission_.horizon()) end = std::min(end + length, mission_.horizon());
  return end;
}

void ExecutiveNode::on_timer() {
  ask_first();
  if (planner_.waiting() && planner_.waited() > seconds(options_.plan_timeout_s)) ask_again();
  // A refused request waits out its back-off here too while a tick is held: the world brings no
  // new tick to ask it at (it waited for the hold's end, and the hold was lost).
  if (held_) reask();
  if (held_ && hold_since_ && WallClock::now() - *hold_since_ > hold_limit()) {
    event("plan_late", now_, "no plan within " + std::to_string(wall_s(hold_limit())) +
                                 " s: the world goes on with the spacecraft safe");
    lockstep_.acknowledge(held_->clock.tick, held_commands_);
    held_.reset();
  }
}

void ExecutiveNode::on_reply() {
  auto reply = planner_.take_reply();
  if (!reply) return;
  if (state_ == State::kFinished) return;
  const bool for_next = state_ == State::kExecuting;
  if (!usable(*reply)) {
    std::string why = reply->reason.empty() ? "no usable plan" : reply->reason;
    if (!reply->detail.empty()) why += ": " + reply->detail;
    for (const std::string& v : reply->violations) why += "; " + v;
    event("plan_refused", now_, reply->request_id + ": " + why);
    // A proof of infeasibility is an answer (the next request may hold the world afresh); a
    // rejection or an invalid plan is not: asked again, it does not renew the outage's hold.
    if (reply->status == msg::PlanningStatus::Infeasible) hold_since_.reset();
    if (reply->status == msg::PlanningStatus::Infeasible && !asked_optional_) {
      // Not every goal can be had (a fault took what some need): the planner may leave goals
      // out and keeps the rest.
      ask_for_plan(asked_origin_, asked_end_, asked_state_, asked_purpose_, true);
    } else if (reply->status == msg::PlanningStatus::Infeasible) {
      std::map<std::string, std::string> lost;
      for (const std::string& g : asked_goals_) lost[g] = "the planner found no plan: " + reply->detail;
      lose_goals(lost, now_);
      ask_for_plan(asked_origin_, asked_end_, asked_state_, asked_purpose_ + " (without the lost goals)");
    } else {
      // Rejected (busy, stopping, ...) or a plan that does not validate: asked again in a moment.
      reask_later();
    }
    return;
  }
  refusals_ = 0;
  hold_since_.reset();  // a plan: a later wait may hold the world afresh
  if (for_next) {
    next_plan_ = std::move(*reply);
    next_goals_ = asked_goals_;
    event("plan_received", now_, next_plan_->request_id + ": next horizon from " +
                                     std::to_string(asked_origin_) + " s, " +
                                     std::to_string(next_plan_->plan.tokens.size()) + " tokens");
    finish_held_tick();  // a tick at the horizon's end waited for it
    return;
  }
  if (lockstep_mode_ && !held_ && now_ > asked_origin_) {
    // Its hold ran out and the world went on: a plan that should have begun in the past would
    // only break at once. Asked again from the next tick (which that request then holds).
    event("plan_refused", now_, reply->request_id + ": arrived " + std::to_string(now_ - asked_origin_) +
                                    " s after its origin; asking again from now");
    reask_ = true;
    return;
  }
  const bool replan = state_ == State::kSafeWaiting;
  start_plan(*reply, asked_origin_, asked_end_, asked_goals_);
  if (state_ != State::kExecuting) return;
  if (replan)
    event("plan_executing", now_, plan_id_ + ": new plan from " + std::to_string(asked_origin_) +
                                      " s executing " +
                                      std::to_string(wall_s(WallClock::now() - fault_seen_)) +
                                      " s (wall) after the fault was detected");
  else
    event("plan_executing", now_, plan_id_ + ": plan for [" + std::to_string(asked_origin_) + ", " +
                                      std::to_string(asked_end_) + ") s executing");
  finish_held_tick();  // with the new plan's first commands (or hold it again)
  publish_status();
}

void ExecutiveNode::finish_held_tick() {
  if (!held_) return;
  const msg::SimClock clock = held_->clock;
  watchdog_.tick_started();
  std::vector<DeviceCommand> out;
  if (state_ == State::kExecuting) dispatch(now_, out);
  finish_tick(clock, held_commands_ + send(out, clock.tick));
  watchdog_.tick_ended();
}

void ExecutiveNode::start_plan(const msg::PlanningReply& reply, Time origin, Time horizon_end,
                               const std::vector<std::string>& goals) {
  std::string error;
  // The fault table goes on from plan to plan (a thruster stuck closed is answered once).
  auto faults = executive_ ? executive_->release_fault_table() : config_.fault_table();
  auto next = Executive::create(planner::from_plan_message(reply.plan), config_.command_map(),
                                std::move(faults), ExecutiveOptions{config_.safing}, origin, &error);
  if (!next) {
    if (executive_) executive_->set_fault_table(config_.fault_table());  // the old plan goes on
    event("plan_refused", now_, reply.request_id + ": not dispatchable: " + error);
    reask_later();
    return;
  }
  if (executive_) report_.add_plan(plan_id_, executive_->dispatcher(), now_);
  for (const auto& [device, why] : disabled_) next->disable_device(device);
  for (const std::string& s : ignored_sensors_) next->ignore_sensor(s);
  executive_ = std::move(next);
  stepped_at_ = -1;
  current_goals_ = goals;
  plan_id_ = reply.request_id;
  plan_origin_ = origin;
  horizon_end_ = horizon_end;
  state_ = State::kExecuting;
  refusals_ = 0;
  if (journal_) journal_state(observed(now_));
  decision_us_sum_ = decision_us_max_ = 0;
  decisions_ = 0;
  std::map<std::string, std::string> omitted;
  for (const std::string& g : reply.plan.omitted_goals)
    omitted[g] = asked_optional_ ? std::string("left out by the planner: no plan has it") +
                                       (disabled_.empty() ? "" : " with the faults known")
                                 : "left out by the planner (optional)";
  lose_goals(omitted, now_);
  lost_while_down_.clear();  // what the first plan after a restart left out was the outage's cost
}

void ExecutiveNode::note_goals(const ExecutiveEvent& e) {
  if (e.kind != "goal_achieved" && e.kind != "goal_lost") return;
  const std::size_t colon = e.text.find(':');
  const std::string label = e.text.substr(0, colon);
  const std::string how = colon == std::string::npos ? "" : e.text.substr(colon + 2);
  if (journal_) journal_->goal(label, e.kind == "goal_achieved", how, now_);
  if (e.kind == "goal_achieved")
    achieved_[label] = how;
  else
    lost_[label] = how;
}

void ExecutiveNode::lose_goals(const std::map<std::string, std::string>& lost, Time now) {
  for (const auto& [label, reason] : lost) {
    if (achieved_.count(label) || lost_.count(label)) continue;
    // Windows that closed while no executive ran say so.
    const std::string why = lost_while_down_.empty() ? reason : lost_while_down_ + ": " + reason;
    if (journal_) journal_->goal(label, false, why, now);
    lost_[label] = why;
    event("goal_lost", now, label + ": " + why);
  }
}

void ExecutiveNode::end_mission(const std::string& why) {
  std::map<std::string, std::string> unsettled;
  for (const std::string& label : mission_.goal_labels())
    if (!achieved_.count(label) && !lost_.count(label)) unsettled[label] = why;
  lose_goals(unsettled, now_);
  state_ = State::kFinished;  // the tick being answered is acknowledged, never held again
  event("finished", now_, std::to_string(achieved_.size()) + " goals achieved, " + std::to_string(lost_.size()) + " lost");
  write_report();  // before the status says finished: whoever waits for it finds the report
  publish_status();
}

void ExecutiveNode::reask_later() {
  // 1, 2, 4 ... s after the refusal, never longer than a request waits for its reply.
  const double wait = std::min(options_.plan_timeout_s, std::ldexp(1.0, static_cast<int>(std::min(refusals_, 10u))));
  ++refusals_;
  reask_ = true;
  reask_after_ = WallClock::now() + seconds(wait);
}

void ExecutiveNode::write_report() {
  if (options_.report_dir.empty()) return;
  if (executive_) report_.add_plan(plan_id_, executive_->dispatcher(), now_);
  std::vector<std::string> achieved, lost;
  for (const auto& [label, how] : achieved_) achieved.push_back(label);
  for (const auto& [label, why] : lost_) lost.push_back(label + ": " + why);
  report_.set_goals(achieved, lost);
  std::error_code ec;
  std::filesystem::create_directories(options_.report_dir, ec);
  const std::string svg = options_.report_dir + "/plan.svg", md = options_.report_dir + "/report.md";
  std::ofstream(svg) << report_.svg(mission_.horizon());
  std::ofstream(md) << report_.markdown("Flight of " + config_.problem_path, mission_.horizon());
  spdlog::info("report: {} and {}", md, svg);
}

void ExecutiveNode::publish_status() {
  msg::ExecutiveStatus s;
  s.executive = name_;
  s.state = state_name();
  s.plan_id = plan_id_;
  s.tick = last_tick_;
  s.plan_origin_s = plan_origin_;
  s.horizon_end_s = horizon_end_;
  if (executive_ && state_ == State::kExecuting) s.executing = executive_->executing();
  for (const auto& [label, how] : achieved_) s.goals_achieved.push_back(label);
  for (const auto& [label, why] : lost_) s.goals_lost.push_back(label + ": " + why);
  for (const auto& [device, why] : disabled_) s.disabled_devices.push_back(device);
  s.ignored_sensors.assign(ignored_sensors_.begin(), ignored_sensors_.end());
  s.replans = replans_;
  s.horizons = horizons_;
  s.decision_us_mean = decisions_ ? decision_us_sum_ / static_cast<double>(decisions_) : 0;
  s.decision_us_max = decision_us_max_;
  s.watchdog_alarm = watchdog_.alarmed();
  status_writer_.write(s);
}

void ExecutiveNode::safe_from_watchdog(WallClock::duration busy) {
  // Runs on the watchdog's thread while the loop is stuck: only writes samples.
  spdlog::error("watchdog: a tick has been in progress for {:.2f} s: safing the spacecraft", wall_s(busy));
  std::uint64_t n = 0;
  for (const DeviceCommand& c : config_.safing) {
    msg::SpacecraftCommand m{name_ + "-watchdog-" + std::to_string(++n), name_ + "-watchdog", 0,
                             c.device, c.command, c.arguments};
    spacecraft_.write_unrecorded(m);
  }
  msg::ExecutiveEvent e{name_, 0, watched_tick_.load(), 0, "watchdog",
                        "dispatch stalled for " + std::to_string(wall_s(busy)) + " s: spacecraft safed", ""};
  event_writer_.write(e);
}

}  // namespace autonomy::executive
