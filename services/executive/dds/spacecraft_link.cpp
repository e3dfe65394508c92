#include "spacecraft_link.hpp"

#include <spdlog/spdlog.h>

namespace autonomy::executive {

SpacecraftLink::SpacecraftLink(const dds::Participant& participant, std::string source,
                               std::string spacecraft)
    : source_(std::move(source)),
      spacecraft_(std::move(spacecraft)),
      telemetry_topic_(participant, dds::topics::spacecraft_telemetry),
      command_topic_(participant, dds::topics::spacecraft_command),
      status_topic_(participant, dds::topics::spacecraft_command_status),
      telemetry_reader_(participant, telemetry_topic_),
      status_reader_(participant, status_topic_),
      command_writer_(participant, command_topic_) {}

std::optional<msg::SpacecraftTelemetry> SpacecraftLink::take_telemetry() {
  std::optional<msg::SpacecraftTelemetry> newest;
  for (auto& s : telemetry_reader_.take()) {
    if (!s.valid) continue;
    if (spacecraft_.empty()) {
      spacecraft_ = s.value.spacecraft;
      spdlog::warn("no --spacecraft given: following spacecraft '{}', the first one heard; any other is ignored",
                   spacecraft_);
    }
    if (s.value.spacecraft != spacecraft_ || spacecraft_ == kNoSpacecraft) {
      // Telemetry arrives every tick: a few warnings say what happens, the count says how much.
      if (++ignored_telemetry_ <= 5 || ignored_telemetry_ % 1000 == 0)
        spdlog::warn("telemetry of spacecraft '{}' ignored ({} so far): this executive commands '{}'",
                     s.value.spacecraft, ignored_telemetry_, spacecraft_);
      continue;
    }
    if (!newest || s.value.tick >= newest->tick) newest = std::move(s.value);
  }
  return newest;
}

std::vector<Confirmation> SpacecraftLink::confirmations(const msg::SpacecraftTelemetry& t) {
  std::vector<Confirmation> out;
  for (const msg::DeviceReport& d : t.devices) {
    auto it = unconfirmed_.find(d.confirmed_command_id);
    if (it == unconfirmed_.end()) continue;
    out.push_back({it->second.device, it->second.command, it->first});
    unconfirmed_.erase(it);
  }
  return out;
}

std::vector<std::pair<DeviceCommand, std::string>> SpacecraftLink::take_rejections() {
  std::vector<std::pair<DeviceCommand, std::string>> out;
  for (auto& s : status_reader_.take()) {
    if (!s.valid || s.value.source != source_ || s.value.accepted) continue;
    auto it = unconfirmed_.find(s.value.command_id);
    if (it == unconfirmed_.end()) continue;  // not ours any more (or a repeat)
    out.emplace_back(it->second, s.value.reason);
    unconfirmed_.erase(it);
  }
  return out;
}

std::uint32_t SpacecraftLink::send(const std::vector<DeviceCommand>& commands, std::int64_t tick) {
  std::uint32_t sent = 0;
  for (const DeviceCommand& c : commands) {
    msg::SpacecraftCommand m;
    m.command_id = source_ + "-" + std::to_string(next_id_++);
    m.source = source_;
    m.tick = tick;
    m.device = c.device;
    m.command = c.command;
    m.arguments = c.arguments;
    unconfirmed_[m.command_id] = c;
    command_writer_.write(m);
    ++sent;
  }
  return sent;
}

Observations observations_of(const msg::SpacecraftTelemetry& t, Time now) {
  Observations o;
  o.time = now;
  for (const msg::DeviceReport& d : t.devices) o.device_modes[d.device] = d.mode;
  for (const msg::SensorReading& r : t.readings) o.readings[r.sensor] = r.value;
  return o;
}

}  // namespace autonomy::executive
