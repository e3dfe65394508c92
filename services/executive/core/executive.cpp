#include "executive.hpp"

namespace autonomy::executive {
namespace {

bool is_initial(const planner::PlanToken& t) {
  return t.origin.rfind("initial", 0) == 0;
}
bool is_goal(const planner::PlanToken& t) {
  return !goal_label(t.origin).empty();
}

std::string describe(const planner::PlanToken& t) {
  std::string s = t.timeline() + " == " + t.predicate + "(";
  for (std::size_t i = 0; i < t.parameters.size(); ++i) s += (i ? ", " : "") + t.parameters[i];
  return s + ") #" + std::to_string(t.id);
}

std::string describe(const DeviceCommand& c) {
  std::string s = c.device + " " + c.command + "(";
  for (std::size_t i = 0; i < c.arguments.size(); ++i) s += (i ? ", " : "") + c.arguments[i];
  return s + ")";
}

}  // namespace

std::string goal_label(const std::string& origin) {
  // "goal <label>" first, then what merged into it ("; <relation> of token <id>").
  if (origin.rfind("goal", 0) != 0) return "";
  const std::string rest = origin.substr(4, origin.find(';') - 4);
  const std::size_t first = rest.find_first_not_of(' ');
  return first == std::string::npos ? "goal" : rest.substr(first);
}

std::unique_ptr<Executive> Executive::create(planner::FlexiblePlan plan, CommandMap commands,
                                             std::vector<std::unique_ptr<FaultResponse>> faults,
                                             ExecutiveOptions options, Time start,
                                             std::string* error) {
  // A plan comes over the wire: every index it holds must name a token.
  for (const planner::PlanTimeline& line : plan.timelines)
    for (std::uint32_t i : line.tokens)
      if (i >= plan.tokens.size()) {
        *error = "timeline " + line.name + " names token " + std::to_string(i) + " of " +
                 std::to_string(plan.tokens.size());
        return nullptr;
      }
  auto net = make_dispatchable(plan, error);
  if (!net) return nullptr;
  Dispatcher dispatcher(std::move(plan), std::move(*net), start);
  // Token ends the world controls are observed, not forced.
  const auto& tokens = dispatcher.plan().tokens;
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    const CommandRule* r = commands.rule_for(tokens[i]);
    if (r && !r->end_mode.empty()) dispatcher.set_observed(i, false, true);
  }
  dispatcher.start();
  return std::unique_ptr<Executive>(new Executive(std::move(dispatcher), std::move(commands),
                                                  std::move(faults), std::move(options)));
}

Executive::Executive(Dispatcher dispatcher, CommandMap commands,
                     std::vector<std::unique_ptr<FaultResponse>> faults, ExecutiveOptions options)
    : dispatcher_(std::move(dispatcher)),
      commands_(std::move(commands)),
      faults_(std::move(faults)),
      options_(std::move(options)) {}

std::size_t Executive::next_on_timeline(std::size_t token) const {
  for (const planner::PlanTimeline& line : dispatcher_.plan().timelines)
    for (std::size_t k = 0; k < line.tokens.size(); ++k)
      if (line.tokens[k] == token) return k + 1 < line.tokens.size() ? line.tokens[k + 1] : SIZE_MAX;
  return SIZE_MAX;
}

std::vector<std::string> Executive::executing() const {
  std::vector<std::string> out;
  const auto& tokens = dispatcher_.plan().tokens;
  for (std::size_t i = 0; i < tokens.size(); ++i)
    if (dispatcher_.executing(i)) out.push_back(describe(tokens[i]));
  return out;
}

bool Executive::rejected(const DeviceCommand& command, const std::string& reason) {
  if (!tracker_.confirm(command.device, command.command)) return false;
  if (command.token != SIZE_MAX)
    uncommanded_.emplace(command.token, command.device + " " + command.command + " rejected: " + reason);
  return true;
}

bool Executive::confirm(const std::string& device, const std::string& command) {
  return tracker_.confirm(device, command);
}

void Executive::stop_commanding(const std::string& device) {
  tracker_.disable(device);
  // Its tokens can no longer be observed ending: they end by time, so the plan goes on; those
  // running now were not carried out by the device.
  const auto& tokens = dispatcher_.plan().tokens;
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    const CommandRule* r = commands_.rule_for(tokens[i]);
    if (!r || r->device != device) continue;
    dispatcher_.set_observed(i, false, false);
    if (dispatcher_.executing(i) && !r->command.empty())
      uncommanded_.emplace(i, device + " no longer commanded");
  }
}

void Executive::goal_ended(std::size_t token, Time now, Tick* tick) {
  const planner::PlanToken& t = dispatcher_.plan().tokens[token];
  const std::string label = goal_label(t.origin);
  auto why = uncommanded_.find(token);
  if (why == uncommanded_.end())
    tick->events.push_back({"goal_achieved", now, label + ": " + describe(t)});
  else
    tick->events.push_back({"goal_lost", now, label + ": " + describe(t) + ": " + why->second});
}

PlanState Executive::plan_state(Time now) const {
  PlanState state;
  state.time = now;
  const auto& tokens = dispatcher_.plan().tokens;
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    if (!dispatcher_.executing(i)) continue;
    const CommandRule* r = commands_.rule_for(tokens[i]);
    // A device is compared with the plan once its command is confirmed (or none was sent).
    if (!r || r->expect_mode.empty() || tracker_.disabled(r->device) ||
        tracker_.awaiting(r->device))
      continue;
    state.expected_modes[r->device] = r->expect_mode;
  }
  return state;
}

ReplanRequest Executive::replan_request(const Observations& seen, std::string reason) const {
  ReplanRequest request;
  request.time = seen.time;
  request.reason = std::move(reason);
  const planner::FlexiblePlan& plan = dispatcher_.plan();
  for (const planner::PlanTimeline& line : plan.timelines) {
    // The current value: the last token started on the timeline.
    const planner::PlanToken* current = nullptr;
    Time since = 0;
    for (std::uint32_t i : line.tokens)
      if (i < plan.tokens.size() && dispatcher_.executed(i, true)) {
        current = &plan.tokens[i];
        since = dispatcher_.executed_at(i, true);
      }
    if (current)
      request.state.push_back({line.name, current->predicate, current->parameters, since});
  }
  for (std::size_t i = 0; i < plan.tokens.size(); ++i)
    if (is_goal(plan.tokens[i]) && !dispatcher_.executed(i, false))
      request.remaining_goals.push_back(plan.tokens[i]);
  PlanState expected = plan_state(seen.time);
  for (const auto& [device, mode] : seen.device_modes) {
    auto it = expected.expected_modes.find(device);
    bool faulty = mode == "failed" || mode == "stuck_closed" ||
                  (it != expected.expected_modes.end() && it->second != mode);
    if (faulty) request.known_faults[device] = mode;
  }
  for (const std::string& device : seen.unconfirmed_devices)
    request.disabled_devices.push_back(device);
  return request;
}

void Executive::abort(const Observations& seen, std::string reason, Tick* tick) {
  if (aborted_) return;
  aborted_ = true;
  for (DeviceCommand c : options_.safing) {
    if (tracker_.disabled(c.device)) continue;
    c.sent = seen.time;
    tick->commands.push_back(c);
  }
  tick->events.push_back({"aborted", seen.time, reason});
  tick->replan = replan_request(seen, std::move(reason));
}

Tick Executive::step(const Observations& input) {
  Tick tick;
  const Time now = input.time;
  Observations seen = input;
  for (const std::string& s : ignored_sensors_) seen.readings.erase(s);
  for (const DeviceCommand& late : tracker_.expire(now))
    seen.unconfirmed_devices.push_back(late.device);
  if (aborted_) {
    // Safe and waiting for a new plan: nothing to dispatch, but a fault that comes meanwhile
    // (a thruster sticking while the replan is made) is answered now, not by another abort.
    std::string ignored;
    respond_to_faults(seen, now, &tick, &ignored);
    return tick;
  }

  // Token ends the world controls: the device reports the mode that ends them.
  const auto& tokens = dispatcher_.plan().tokens;
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    if (!dispatcher_.executing(i) || !dispatcher_.observed(i, false)) continue;
    const CommandRule* r = commands_.rule_for(tokens[i]);
    // Before the end's window opens the report waits: the plan's bound covers settling.
    auto mode = seen.device_modes.find(r->device);
    if (mode != seen.device_modes.end() && mode->second == r->end_mode &&
        now >= dispatcher_.lower(i, false))
      dispatcher_.observe(i, false, now);
  }

  std::string broken;
  std::vector<std::size_t> ended_with_command;
  for (const DispatchEvent& e : dispatcher_.step(now)) {
    if (e.kind == DispatchEvent::Kind::kViolation) {
      tick.events.push_back({"violation", e.time, e.reason});
      if (broken.empty()) broken = "plan broke: " + e.reason;
      continue;
    }
    const planner::PlanToken& t = tokens[e.token];
    bool start = e.kind == DispatchEvent::Kind::kStarted;
    tick.events.push_back({start ? "started" : "ended", e.time, describe(t)});
    if (!start) {
      const CommandRule* r = commands_.rule_for(t);
      if (r && !r->end_command.empty()) ended_with_command.push_back(e.token);
      if (is_goal(t)) goal_ended(e.token, now, &tick);
      continue;
    }
    if (is_initial(t)) continue;  // initial values hold already
    std::string error;
    auto c = commands_.command_for(t, e.token, now, &error);
    if (!error.empty()) tick.events.push_back({"violation", now, error});
    if (!c) continue;
    if (tracker_.disabled(c->device)) {
      uncommanded_.emplace(e.token, c->device + " no longer commanded");
      tick.events.push_back({"skipped", now, describe(*c) + ": device no longer commanded"});
      continue;
    }
    tracker_.sent(*c, commands_.rule_for(t)->confirm_timeout);
    tick.events.push_back({"command", now, describe(*c)});
    tick.commands.push_back(std::move(*c));
  }

  // A token's end command (engine standby after a thrust arc, transmitter off after a
  // downlink) goes out unless the next token of its timeline has begun: that one commands.
  for (std::size_t i : ended_with_command) {
    const CommandRule* r = commands_.rule_for(tokens[i]);
    const std::size_t next = next_on_timeline(i);
    if (tracker_.disabled(r->device) || (next != SIZE_MAX && dispatcher_.executed(next, true))) continue;
    DeviceCommand end{r->device, r->end_command, {}, i, now};
    tracker_.sent(end, r->confirm_timeout);
    tick.events.push_back({"command", now, describe(end)});
    tick.commands.push_back(std::move(end));
  }

  respond_to_faults(seen, now, &tick, &broken);
  if (!broken.empty()) abort(seen, broken, &tick);
  return tick;
}

void Executive::respond_to_faults(const Observations& seen, Time now, Tick* tick_out, std::string* broken_out) {
  Tick& tick = *tick_out;
  std::string& broken = *broken_out;
  // Aborted, the plan expects nothing any more: comparing modes with it would judge a stuck
  // device's honest report false. Faults the world shows by itself (a failed unit, a stuck
  // actuator) are still answered.
  PlanState state = aborted_ ? PlanState{now, {}} : plan_state(now);
  for (auto& part : faults_)
    for (const FaultAction& a : part->assess(seen, state)) {
      tick.events.push_back({std::string("fault ") + to_string(a.kind), now, a.reason});
      switch (a.kind) {
        case FaultAction::Kind::kReset: {
          DeviceCommand reset{a.subject, "reset", {}, SIZE_MAX, now};
          tracker_.sent(reset, 5);
          tick.commands.push_back(reset);
          break;
        }
        case FaultAction::Kind::kIgnoreSensor:
          ignored_sensors_.insert(a.subject);
          break;
        case FaultAction::Kind::kSwitchControlMode: {
          DeviceCommand mode{a.control_device, "set_mode", {a.mode}, SIZE_MAX, now};
          tracker_.sent(mode, 5);
          tick.commands.push_back(mode);
          break;
        }
        case FaultAction::Kind::kStopCommanding:
          stop_commanding(a.subject);
          break;
        case FaultAction::Kind::kAbortAndReplan:
          if (broken.empty()) broken = a.reason;
          break;
      }
    }
}

}  // namespace autonomy::executive
