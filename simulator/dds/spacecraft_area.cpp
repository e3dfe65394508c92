#include "simulator/dds/spacecraft_area.hpp"

#include "common/msg/text_limits.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>

namespace autonomy::sim {
namespace {

constexpr std::size_t kMaxArguments = 8;

int64_t seconds_to_ns(double seconds) {
  return static_cast<int64_t>(std::llround(seconds * 1e9));
}

// Why a received command cannot even be looked at (overlong strings, too many arguments).
std::optional<std::string> malformed(const msg::SpacecraftCommand& c) {
  if (auto p = msg::first_length_problem({{"command_id", c.command_id, msg::kMaxIdLength},
                                          {"source", c.source, msg::kMaxNameLength},
                                          {"device", c.device, msg::kMaxNameLength},
                                          {"command", c.command, msg::kMaxNameLength}}))
    return p;
  if (c.arguments.size() > kMaxArguments)
    return "arguments has " + std::to_string(c.arguments.size()) + " entries, more than " +
           std::to_string(kMaxArguments);
  for (const std::string& a : c.arguments)
    if (auto p = msg::length_problem("argument", a, msg::kMaxNameLength)) return p;
  return std::nullopt;
}

}  // namespace

SpacecraftArea::SpacecraftArea(const dds::Participant& participant, service::EventLoop& loop,
                               spacecraft::SpacecraftSpec spec, Synchronised synchronised,
                               std::function<void()> after_samples)
    : craft_(std::move(spec)),
      synchronised_(std::move(synchronised)),
      after_samples_(std::move(after_samples)),
      command_topic_(participant, dds::topics::spacecraft_command),
      status_topic_(participant, dds::topics::spacecraft_command_status),
      telemetry_topic_(participant, dds::topics::spacecraft_telemetry),
      injection_topic_(participant, dds::topics::spacecraft_fault_injection),
      fault_topic_(participant, dds::topics::truth_spacecraft_fault),
      event_topic_(participant, dds::topics::spacecraft_event),
      heartbeat_topic_(participant, dds::topics::heartbeat),
      status_writer_(participant, status_topic_),
      telemetry_writer_(participant, telemetry_topic_),
      fault_writer_(participant, fault_topic_),
      event_writer_(participant, event_topic_),
      command_reader_(participant, command_topic_),
      // Keep-all on the reader's side: a burst of injections is not cut to the class's depth.
      injection_reader_(participant, injection_topic_, dds::QosClass::Queue),
      heartbeat_reader_(participant, heartbeat_topic_) {
  loop.on_samples<msg::SpacecraftCommand>(command_reader_,
                                          [this](auto s) { on_commands(std::move(s)); });
  loop.on_samples<msg::SpacecraftFaultInjection>(injection_reader_,
                                                 [this](auto s) { on_injections(std::move(s)); });
  loop.on_samples<msg::Heartbeat>(heartbeat_reader_,
                                  [this](auto s) { on_heartbeats(std::move(s)); });
  const spacecraft::SpacecraftSpec& s = craft_.spec();
  spdlog::info(
      "spacecraft '{}': {} devices, {} targets, {} ground-station windows, {} scenario faults",
      s.name, craft_.devices().size(), s.targets.size(), s.telecom.windows.size(), s.faults.size());
  if (s.fault_protection.commander_timeout_s > 0.0)
    spdlog::info("spacecraft '{}': safes itself after {} s without a sign of {}; queue of {} commands",
                 s.name, s.fault_protection.commander_timeout_s, s.fault_protection.commander,
                 s.command_queue_limit);
  else
    spdlog::info("spacecraft '{}': fault protection off; queue of {} commands", s.name,
                 s.command_queue_limit);
}

void SpacecraftArea::on_commands(std::vector<dds::Sample<msg::SpacecraftCommand>> samples) {
  for (auto& s : samples) {
    if (!s.valid) continue;
    msg::SpacecraftCommand& c = s.value;
    if (auto problem = malformed(c)) {
      ++malformed_;
      refuse(c, *problem, false);
      continue;
    }
    const std::size_t limit = craft_.spec().command_queue_limit;
    if (queued_ >= limit) {
      ++busy_;
      refuse(c,
             "busy: " + std::to_string(queued_) + " commands are waiting for their step (limit " +
                 std::to_string(limit) + "), send it again later",
             true);
      continue;
    }
    ++queued_;
    if (synchronised_(c.source, c.tick))
      by_tick_[c.tick].push_back(std::move(c));
    else
      unsynchronised_.push_back(std::move(c));
  }
  after_samples_();
}

void SpacecraftArea::refuse(const msg::SpacecraftCommand& c, const std::string& reason,
                            bool busy) {
  // Counted before the answer: the tick it was announced for must not wait for it. A source
  // over the name limit cannot be a participant (registrations are checked the same way).
  if (!msg::length_problem("source", c.source, msg::kMaxNameLength))
    (void)synchronised_(c.source, c.tick);
  const msg::SpacecraftCommand echo{msg::clipped_id(c.command_id),
                                    msg::clipped_id(c.source, msg::kMaxNameLength),
                                    c.tick,
                                    msg::clipped_id(c.device, msg::kMaxNameLength),
                                    msg::clipped_id(c.command, msg::kMaxNameLength),
                                    {}};
  if (busy)
    spdlog::debug("spacecraft command '{}' from '{}': {}", echo.command_id, echo.source, reason);
  else
    spdlog::warn("spacecraft command '{}' from '{}' rejected: {}",
                 msg::clipped_for_log(c.command_id), msg::clipped_for_log(c.source), reason);
  answer(echo, false, reason, tick_, busy);
}

void SpacecraftArea::on_heartbeats(std::vector<dds::Sample<msg::Heartbeat>> samples) {
  for (const auto& s : samples)
    if (s.valid && s.instance_state == dds::InstanceState::Alive &&
        s.value.service == craft_.spec().fault_protection.commander)
      craft_.commander_heard("heartbeat of " + s.value.service + "/" +
                             msg::clipped_for_log(s.value.instance));
}

bool SpacecraftArea::is_commander(const std::string& participant) const {
  const std::string& commander = craft_.spec().fault_protection.commander;
  return participant == commander || participant.rfind(commander + "/", 0) == 0;
}

void SpacecraftArea::on_ack(const std::string& participant) {
  if (is_commander(participant))
    craft_.commander_heard("lockstep ack of " + msg::clipped_for_log(participant));
}

void SpacecraftArea::on_injections(
    std::vector<dds::Sample<msg::SpacecraftFaultInjection>> samples) {
  for (auto& s : samples)
    if (s.valid) injections_.push_back(std::move(s.value));
}

void SpacecraftArea::step(std::int64_t tick, double dt_s) {
  std::vector<msg::SpacecraftFaultInjection> injections;
  injections.swap(injections_);
  for (const auto& f : injections) apply(f, tick);

  std::vector<msg::SpacecraftCommand> commands;
  commands.swap(unsynchronised_);
  // This tick's (and, should any be left, earlier ticks') commands: none is dropped unanswered.
  const auto due_end = by_tick_.upper_bound(tick);
  for (auto it = by_tick_.begin(); it != due_end; ++it) {
    // Arrival order across senders depends on the network; the application order must not.
    std::stable_sort(it->second.begin(), it->second.end(),
                     [](const auto& a, const auto& b) { return a.source < b.source; });
    commands.insert(commands.end(), it->second.begin(), it->second.end());
  }
  by_tick_.erase(by_tick_.begin(), due_end);
  queued_ -= std::min(queued_, commands.size());
  for (const auto& c : commands) apply(c, tick);
  craft_.step(dt_s);
}

void SpacecraftArea::apply(const msg::SpacecraftCommand& c, std::int64_t tick) {
  const spacecraft::CommandResult r =
      craft_.submit({c.command_id, c.source, c.device, c.command, c.arguments});
  if (r.accepted)
    spdlog::info("tick {}: {} {} [{}] from {} accepted ({})", tick, c.device, c.command,
                 msg::clipped_for_log(c.arguments.empty() ? "" : c.arguments[0]), c.source,
                 c.command_id);
  else
    spdlog::warn("tick {}: {} {} from {} rejected ({}): {}", tick, c.device, c.command, c.source,
                 c.command_id, r.reason);
  answer(c, r.accepted, r.reason, tick);
}

void SpacecraftArea::apply(const msg::SpacecraftFaultInjection& f, std::int64_t tick) {
  msg::SpacecraftCommand echo{msg::clipped_id(f.fault_id),
                              msg::clipped_id(f.source, msg::kMaxNameLength),
                              tick,
                              msg::clipped_id(f.subject, msg::kMaxNameLength),
                              "inject",
                              {}};
  if (auto problem = msg::first_length_problem({{"fault_id", f.fault_id, msg::kMaxIdLength},
                                                {"source", f.source, msg::kMaxNameLength},
                                                {"kind", f.kind, msg::kMaxNameLength},
                                                {"subject", f.subject, msg::kMaxNameLength}})) {
    answer(echo, false, *problem, tick);
    return;
  }
  if (f.clear) {
    echo.command = "clear";
    const bool cleared = craft_.clear_fault(f.fault_id);
    answer(echo, cleared, cleared ? "" : "no fault '" + f.fault_id + "'", tick);
    return;
  }
  const auto kind = spacecraft::fault_kind_from_string(f.kind);
  if (!kind) {
    answer(echo, false,
           "unknown fault kind '" + f.kind +
               "' (stuck_on, failed, false_sensor, stuck_closed, never_confirmed)",
           tick);
    return;
  }
  spacecraft::FaultSpec spec{f.fault_id,    *kind,        f.subject, f.value,
                             f.reset_cures, std::nullopt, ""};
  const spacecraft::CommandResult r = craft_.inject(
      std::move(spec), "injected by " + (f.source.empty() ? std::string("?") : f.source));
  if (r.accepted)
    spdlog::info("tick {}: fault '{}' ({} {}) injected by {}", tick, f.fault_id, f.kind, f.subject,
                 f.source);
  else
    spdlog::warn("tick {}: fault injection '{}' rejected: {}", tick, f.fault_id, r.reason);
  answer(echo, r.accepted, r.reason, tick);
}

void SpacecraftArea::answer(const msg::SpacecraftCommand& c, bool accepted,
                            const std::string& reason, std::int64_t tick, bool busy) {
  // Commands are applied in the step that ends the last published tick: its time is theirs.
  try {
    status_writer_.write(
        {c.command_id, c.source, c.device, c.command, accepted, reason, tick, tick_ns_, busy});
  } catch (const std::exception& e) {
    // A keep-all writer fails only after its readers stayed behind for the blocking time.
    if (statuses_lost_++ % 100 == 0)
      spdlog::warn("status of spacecraft command '{}' not written ({} so far): {}", c.command_id,
                   statuses_lost_, e.what());
  }
}

void SpacecraftArea::publish(std::int64_t tick, std::int64_t sim_time_ns) {
  tick_ = tick;
  tick_ns_ = sim_time_ns;
  msg::SpacecraftTelemetry t = craft_.telemetry();
  t.tick = tick;
  t.sim_time_ns = sim_time_ns;
  t.commands_rejected += malformed_ + busy_;
  t.commands_busy = busy_;
  telemetry_writer_.write(t);
  for (const spacecraft::SpacecraftEventRecord& e : craft_.take_events()) {
    if (e.kind == "safed")
      spdlog::warn("spacecraft '{}' safed at {} s: {}", t.spacecraft, e.time_s, e.detail);
    else
      spdlog::info("spacecraft '{}' {} at {} s: {}", t.spacecraft, e.kind, e.time_s, e.detail);
    event_writer_.write({t.spacecraft, tick, seconds_to_ns(e.time_s), e.kind, e.detail});
  }
  for (const spacecraft::FaultEvent& e : craft_.take_fault_events()) {
    spdlog::info("fault '{}' ({} {}) {} at {} s ({})", e.fault.id, to_string(e.fault.kind),
                 e.fault.subject, e.active ? "active" : "ended by " + e.ended_by, e.time_s,
                 e.trigger);
    fault_writer_.write({e.fault.id, to_string(e.fault.kind), e.fault.subject, e.fault.value,
                         e.active, e.trigger, e.ended_by, seconds_to_ns(e.time_s)});
  }
}

}  // namespace autonomy::sim
