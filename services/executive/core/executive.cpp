#include "executive.hpp"

namespace autonomy::executive {
namespace {

bool is_initial(const planner::PlanToken& t) {
  return t.origin.rfind("initial", 0) == 0;
}
bool is_goal(const planner::PlanToken& t) {
  return t.origin.find("goal") != std::string::npos;
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

std::unique_ptr<Executive> Executive::create(planner::FlexiblePlan plan, CommandMap commands,
                                             std::vector<std::unique_ptr<FaultResponse>> faults,
                                             ExecutiveOptions options, Time start,
                                             std::string* error) {
  auto net = make_dispatchable(plan, error);
  if (!net) return nullptr;
  Dispatcher dispatcher(std::move(plan), std::move(*net), start);
  // Token ends the world controls are observed, not forced.
  const auto& tokens = dispatcher.plan().tokens;
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    const CommandRule* r = commands.rule_for(tokens[i]);
    if (r && !r->end_mode.empty()) dispatcher.set_observed(i, false, true);
  }
  return std::unique_ptr<Executive>(new Executive(std::move(dispatcher), std::move(commands),
                                                  std::move(faults), std::move(options)));
}

Executive::Executive(Dispatcher dispatcher, CommandMap commands,
                     std::vector<std::unique_ptr<FaultResponse>> faults, ExecutiveOptions options)
    : dispatcher_(std::move(dispatcher)),
      commands_(std::move(commands)),
      faults_(std::move(faults)),
      options_(std::move(options)) {}

bool Executive::confirm(const std::string& device, const std::string& command) {
  return tracker_.confirm(device, command);
}

void Executive::stop_commanding(const std::string& device) {
  tracker_.disable(device);
  // Its tokens can no longer be observed ending: they end by time, so the plan goes on.
  const auto& tokens = dispatcher_.plan().tokens;
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    const CommandRule* r = commands_.rule_for(tokens[i]);
    if (r && r->device == device) dispatcher_.set_observed(i, false, false);
  }
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
  if (aborted_) return tick;  // safe and waiting for a new plan: nothing to dispatch
  const Time now = input.time;
  Observations seen = input;
  for (const std::string& s : ignored_sensors_) seen.readings.erase(s);
  for (const DeviceCommand& late : tracker_.expire(now))
    seen.unconfirmed_devices.push_back(late.device);

  // Token ends the world controls: the device reports the mode that ends them.
  const auto& tokens = dispatcher_.plan().tokens;
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    if (!dispatcher_.executing(i) || !dispatcher_.observed(i, false)) continue;
    const CommandRule* r = commands_.rule_for(tokens[i]);
    auto mode = seen.device_modes.find(r->device);
    if (mode != seen.device_modes.end() && mode->second == r->end_mode)
      dispatcher_.observe(i, false, now);
  }

  std::string broken;
  for (const DispatchEvent& e : dispatcher_.step(now)) {
    if (e.kind == DispatchEvent::Kind::kViolation) {
      tick.events.push_back({"violation", e.time, e.reason});
      if (broken.empty()) broken = "plan broke: " + e.reason;
      continue;
    }
    const planner::PlanToken& t = tokens[e.token];
    bool start = e.kind == DispatchEvent::Kind::kStarted;
    tick.events.push_back({start ? "started" : "ended", e.time, describe(t)});
    if (!start || is_initial(t)) continue;  // initial values hold already
    std::string error;
    auto c = commands_.command_for(t, e.token, now, &error);
    if (!error.empty()) tick.events.push_back({"violation", now, error});
    if (!c) continue;
    if (tracker_.disabled(c->device)) {
      tick.events.push_back({"skipped", now, describe(*c) + ": device no longer commanded"});
      continue;
    }
    tracker_.sent(*c, commands_.rule_for(t)->confirm_timeout);
    tick.events.push_back({"command", now, describe(*c)});
    tick.commands.push_back(std::move(*c));
  }

  PlanState state = plan_state(now);
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
  if (!broken.empty()) abort(seen, broken, &tick);
  return tick;
}

}  // namespace autonomy::executive
