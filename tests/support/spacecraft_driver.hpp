#pragma once
// Integration tests of the simulated spacecraft: the test process as a lockstep participant that
// sends device commands on autonomy/spacecraft/command (as the executive does), and helpers that
// look into telemetry and command statuses.
#include "tests/support/dds_observer.hpp"

#include <algorithm>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace autonomy::test {

// Acknowledges every tick, and sends the commands queued since the last tick stamped with the new
// tick before the ack that announces them.
class LockstepDriver {
 public:
  explicit LockstepDriver(const dds::Participant& p, std::string name = "test")
      : name_(std::move(name)),
        clock_topic_(p, dds::topics::clock),
        registration_topic_(p, dds::topics::lockstep_registration),
        ack_topic_(p, dds::topics::tick_ack),
        command_topic_(p, dds::topics::spacecraft_command),
        clock_reader_(p, clock_topic_),
        registration_writer_(p, registration_topic_),
        ack_writer_(p, ack_topic_),
        command_writer_(p, command_topic_) {}

  ::testing::AssertionResult join() {
    if (!command_writer_.wait_for_readers(1, kDeadline))
      return ::testing::AssertionFailure() << "no reader of autonomy/spacecraft/command";
    registration_writer_.write({name_, true});
    return ::testing::AssertionSuccess();
  }
  void send(const std::string& id, const std::string& device, const std::string& command,
            std::vector<std::string> arguments = {}) {
    queued_.push_back({id, name_, 0, device, command, std::move(arguments)});
  }
  void send(msg::SpacecraftCommand c) { queued_.push_back(std::move(c)); }  // tick set on sending
  // Called at a new tick before its queued commands: writes whatever else the test sends for the
  // tick (e.g. velocity commands) and returns how many the ack must announce besides the queued.
  std::function<uint32_t(int64_t tick)> also_send;

  // Reacts to a new tick: the queued commands, then the ack. Returns the current tick.
  std::optional<int64_t> poll() {
    for (auto& s : clock_reader_.take()) {
      if (!s.valid || (tick_ && s.value.tick <= *tick_)) continue;
      tick_ = s.value.tick;
      uint32_t sent = also_send ? also_send(*tick_) : 0;
      for (auto& c : queued_) {
        c.tick = *tick_;
        sent_at_[c.command_id] = *tick_;
        command_writer_.write(c);
      }
      sent += static_cast<uint32_t>(queued_.size());
      ack_writer_.write({name_, *tick_, sent});
      queued_.clear();
    }
    return tick_;
  }
  int64_t sent_at(const std::string& id) const { return sent_at_.at(id); }
  bool sent(const std::string& id) const { return sent_at_.count(id) > 0; }
  const std::string& name() const { return name_; }

 private:
  std::string name_;
  dds::Topic<msg::SimClock> clock_topic_;
  dds::Topic<msg::LockstepRegistration> registration_topic_;
  dds::Topic<msg::TickAck> ack_topic_;
  dds::Topic<msg::SpacecraftCommand> command_topic_;
  dds::Reader<msg::SimClock> clock_reader_;
  dds::Writer<msg::LockstepRegistration> registration_writer_;
  dds::Writer<msg::TickAck> ack_writer_;
  dds::Writer<msg::SpacecraftCommand> command_writer_;
  std::optional<int64_t> tick_;
  std::vector<msg::SpacecraftCommand> queued_;
  std::map<std::string, int64_t> sent_at_;
};

inline const msg::DeviceReport* device(const msg::SpacecraftTelemetry& t, const std::string& name) {
  for (const auto& d : t.devices)
    if (d.device == name) return &d;
  return nullptr;
}

inline std::optional<double> reading(const msg::SpacecraftTelemetry& t, const std::string& sensor) {
  for (const auto& r : t.readings)
    if (r.sensor == sensor) return r.value;
  return std::nullopt;
}

// The first telemetry sample (in tick order) that satisfies `pred`.
inline std::optional<msg::SpacecraftTelemetry> first(
    const Recorder<msg::SpacecraftTelemetry>& r,
    const std::function<bool(const msg::SpacecraftTelemetry&)>& pred) {
  auto all = r.matching(pred);
  if (all.empty()) return std::nullopt;
  return *std::min_element(all.begin(), all.end(),
                           [](const auto& a, const auto& b) { return a.tick < b.tick; });
}

inline std::optional<msg::SpacecraftCommandStatus> status_of(
    const Recorder<msg::SpacecraftCommandStatus>& r, const std::string& id) {
  auto all = r.matching([&](const auto& s) { return s.command_id == id; });
  if (all.empty()) return std::nullopt;
  return all.front();
}

}  // namespace autonomy::test
