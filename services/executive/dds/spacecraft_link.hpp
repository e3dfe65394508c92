#pragma once
// The executive's view of the spacecraft: telemetry turned into the core's Observations, the
// confirmations it carries, command statuses, and device commands out (stamped with the tick
// they answer, counted for the lockstep ack).
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "common/dds/reader.hpp"
#include "common/dds/topics.hpp"
#include "common/dds/writer.hpp"
#include "executive.hpp"

namespace autonomy::executive {

struct Confirmation {
  std::string device, command, command_id;
};

class SpacecraftLink {
 public:
  SpacecraftLink(const dds::Participant& participant, std::string source, std::string spacecraft);

  // The newest telemetry of `spacecraft` since the last call. Without a name (no --spacecraft)
  // the link follows the first spacecraft it hears, so that a second spacecraft on the domain
  // is never mixed into this one's observations. Another spacecraft's telemetry is ignored with
  // a warning and counted (ignored_telemetry()). The name kNoSpacecraft ("none": an executive of
  // robots only) reads no spacecraft at all.
  static constexpr const char* kNoSpacecraft = "none";
  std::optional<msg::SpacecraftTelemetry> take_telemetry();
  const std::string& spacecraft() const { return spacecraft_; }
  std::uint64_t ignored_telemetry() const { return ignored_telemetry_; }
  // The commands this link sent whose confirmation `t` shows for the first time.
  std::vector<Confirmation> confirmations(const msg::SpacecraftTelemetry& t);
  // Rejections of this link's commands since the last call: the command and the reason.
  std::vector<std::pair<DeviceCommand, std::string>> take_rejections();

  // Writes each command stamped with `tick`; returns how many were written.
  std::uint32_t send(const std::vector<DeviceCommand>& commands, std::int64_t tick);

  // Writes one command without awaiting its confirmation; safe from any thread (the watchdog).
  void write_unrecorded(const msg::SpacecraftCommand& command) const { command_writer_.write(command); }

 private:
  std::string source_, spacecraft_;
  std::uint64_t ignored_telemetry_ = 0;
  dds::Topic<msg::SpacecraftTelemetry> telemetry_topic_;
  dds::Topic<msg::SpacecraftCommand> command_topic_;
  dds::Topic<msg::SpacecraftCommandStatus> status_topic_;
  dds::Reader<msg::SpacecraftTelemetry> telemetry_reader_;
  dds::Reader<msg::SpacecraftCommandStatus> status_reader_;
  dds::Writer<msg::SpacecraftCommand> command_writer_;
  std::uint64_t next_id_ = 1;
  std::map<std::string, DeviceCommand> unconfirmed_;  // by command id
};

// Telemetry as the core reads it: each device's mode, each reading.
Observations observations_of(const msg::SpacecraftTelemetry& t, Time now);

}  // namespace autonomy::executive
