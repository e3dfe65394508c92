#pragma once
// The spacecraft's part of the simulator node: device commands and fault injections from DDS
// into simulator/spacecraft, command status, telemetry and fault truth back out. The node calls
// step() inside its advance (after the robots' commands, before the world steps) and publish()
// when it opens a tick (before the clock), so the spacecraft keeps the robots' tick cycle,
// lockstep or paced.
//
// Lockstep: a command whose source is a lockstep participant is counted by the node's barrier
// (the `synchronised` callback) and applied at the step that ends its tick, in source order;
// any other command, and every fault injection, is applied at the next step.
//
// No command vanishes: every one gets a status on autonomy/spacecraft/command_status. A
// malformed one (strings over the limits, too many arguments) is rejected when it arrives and a
// command beyond the queue limit (the spec's command_queue_limit waiting for their step) is
// rejected "busy"; both are still counted by the barrier first, so the tick they were announced
// for does not wait for them. A status that cannot be written (its readers stayed behind for the
// writer's blocking time) is logged and counted (statuses_lost()).
//
// Fault protection: heartbeats of the commander service, lockstep acks of its participants
// (on_ack) and commands are signs of the commander for the spacecraft's command-loss timer;
// safing and resuming are written to autonomy/spacecraft/event.
#include "common/dds/participant.hpp"
#include "common/dds/reader.hpp"
#include "common/dds/topics.hpp"
#include "common/dds/writer.hpp"
#include "common/service/event_loop.hpp"
#include "simulator/spacecraft/spacecraft.hpp"

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace autonomy::sim {

class SpacecraftArea {
 public:
  using Synchronised = std::function<bool(const std::string& source, std::int64_t tick)>;

  // `after_samples` runs once commands were taken in (the node re-checks its barrier).
  SpacecraftArea(const dds::Participant& participant, service::EventLoop& loop,
                 spacecraft::SpacecraftSpec spec, Synchronised synchronised,
                 std::function<void()> after_samples);

  // Applies the injections and commands due at the end of `tick`, then steps dt_s.
  void step(std::int64_t tick, double dt_s);
  // Telemetry of `tick` and the fault changes since the last publish.
  void publish(std::int64_t tick, std::int64_t sim_time_ns);
  // A lockstep ack of `participant` arrived (the commander's "executive/..." ones count as its
  // heartbeat: in lockstep, simulated time may run far ahead of wall-clock heartbeats).
  void on_ack(const std::string& participant);

  std::uint64_t commands_accepted() const { return craft_.commands_accepted(); }
  std::uint64_t commands_rejected() const {
    return craft_.commands_rejected() + malformed_ + busy_;
  }
  std::uint64_t commands_busy() const { return busy_; }
  std::uint64_t statuses_lost() const { return statuses_lost_; }

 private:
  void on_commands(std::vector<dds::Sample<msg::SpacecraftCommand>> samples);
  void on_injections(std::vector<dds::Sample<msg::SpacecraftFaultInjection>> samples);
  void on_heartbeats(std::vector<dds::Sample<msg::Heartbeat>> samples);
  // Counts `c` for the barrier (when its source can be a participant) and answers it now.
  void refuse(const msg::SpacecraftCommand& c, const std::string& reason, bool busy);
  bool is_commander(const std::string& participant) const;
  void apply(const msg::SpacecraftCommand& c, std::int64_t tick);
  void apply(const msg::SpacecraftFaultInjection& f, std::int64_t tick);
  void answer(const msg::SpacecraftCommand& c, bool accepted, const std::string& reason,
              std::int64_t tick, bool busy = false);

  spacecraft::Spacecraft craft_;
  Synchronised synchronised_;
  std::function<void()> after_samples_;
  std::map<std::int64_t, std::vector<msg::SpacecraftCommand>> by_tick_;
  std::vector<msg::SpacecraftCommand> unsynchronised_;
  std::vector<msg::SpacecraftFaultInjection> injections_;
  std::size_t queued_ = 0;  // commands in by_tick_ and unsynchronised_
  std::uint64_t malformed_ = 0;
  std::uint64_t busy_ = 0;
  std::uint64_t statuses_lost_ = 0;
  std::int64_t tick_ = 0;     // the last tick published
  std::int64_t tick_ns_ = 0;  // its simulated time

  dds::Topic<msg::SpacecraftCommand> command_topic_;
  dds::Topic<msg::SpacecraftCommandStatus> status_topic_;
  dds::Topic<msg::SpacecraftTelemetry> telemetry_topic_;
  dds::Topic<msg::SpacecraftFaultInjection> injection_topic_;
  dds::Topic<msg::SpacecraftFaultState> fault_topic_;
  dds::Topic<msg::SpacecraftEvent> event_topic_;
  dds::Topic<msg::Heartbeat> heartbeat_topic_;
  dds::Writer<msg::SpacecraftCommandStatus> status_writer_;
  dds::Writer<msg::SpacecraftTelemetry> telemetry_writer_;
  dds::Writer<msg::SpacecraftFaultState> fault_writer_;
  dds::Writer<msg::SpacecraftEvent> event_writer_;
  dds::Reader<msg::SpacecraftCommand> command_reader_;
  dds::Reader<msg::SpacecraftFaultInjection> injection_reader_;
  dds::Reader<msg::Heartbeat> heartbeat_reader_;
};

}  // namespace autonomy::sim
