#pragma once
// The simulator's thin DDS shell: turns samples into calls on sim::World and sim::LockstepBarrier
// and publishes the world back. All of it runs on the service's event-loop thread.
//
// Tick cycle: publish robot states of tick k, then the clock of tick k; wait (lockstep) for the
// barrier or (paced) for the wall-clock period; apply the commands stamped k in a fixed order
// (robot id, then source, then arrival), step the world, tick k+1. A robot spawned during tick k
// has its state published for tick k at once, so its controller can act on k before the step.
#include "common/dds/reader.hpp"
#include "common/dds/topics.hpp"
#include "common/dds/writer.hpp"
#include "common/service/service.hpp"
#include "simulator/core/lockstep_barrier.hpp"
#include "simulator/core/world.hpp"
#include "simulator/report/trajectory_recorder.hpp"
#include "simulator/scenario/simulation_settings.hpp"

#include <chrono>
#include <cstdint>
#include <fstream>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace autonomy::sim {

struct SimulatorRunOptions {
  SimulationSettings settings;
  // Lockstep: tick 0 is held until these participants registered, so a run is reproducible
  // from its first tick.
  std::vector<std::string> wait_for_participants;
  std::optional<int64_t> max_ticks;  // stop the service after this tick
  std::string trajectory_csv;         // tick,time_s,robot,x,y,theta per robot per tick, if set
  std::string picture_svg;            // an SVG picture of the run written at exit, if set
};

class SimulatorNode {
 public:
  SimulatorNode(service::Service& service, World world, SimulatorRunOptions options);
  ~SimulatorNode();

 private:
  void on_commands(std::vector<dds::Sample<msg::VelocityCommand>> samples);
  void on_acks(std::vector<dds::Sample<msg::TickAck>> samples);
  void on_registrations(std::vector<dds::Sample<msg::LockstepRegistration>> samples);
  void on_spawn_requests(std::vector<dds::Sample<msg::SpawnRequest>> samples);
  void on_timer();

  bool lockstep() const { return options_.settings.mode == ClockMode::Lockstep; }
  bool holding_start() const;
  void advance_while_complete();
  void advance();  // applies commands, steps the world, opens the next tick
  void apply_commands(const std::vector<msg::VelocityCommand>& commands);
  void handle_spawns();
  void open_tick();  // publishes state and clock of tick_, starts the barrier's tick
  void publish_robot_state(const RobotStatus& robot);
  void publish_status();
  void write_picture() const;
  void reject(const msg::VelocityCommand& command, const std::string& reason);

  service::Service& service_;
  World world_;
  SimulatorRunOptions options_;
  LockstepBarrier barrier_;
  int64_t tick_ = 0;
  std::chrono::steady_clock::time_point last_advance_;
  std::map<int64_t, std::vector<msg::VelocityCommand>> commands_by_tick_;  // lockstep, per tick
  std::vector<msg::VelocityCommand> unsynchronised_commands_;  // from outside lockstep: next step
  std::vector<msg::SpawnRequest> spawn_requests_;
  // Requesters repeat a request until its reply arrives; a repeat gets the first answer again.
  std::map<std::string, msg::SpawnReply> spawn_replies_;
  uint64_t commands_applied_ = 0;
  uint64_t commands_rejected_ = 0;
  uint64_t participants_dropped_ = 0;
  double step_compute_us_total_ = 0.0;
  std::ofstream trajectory_;
  TrajectoryRecorder paths_;
  bool finished_ = false;

  dds::Topic<msg::SimClock> clock_topic_;
  dds::Topic<msg::RobotState> state_topic_;
  dds::Topic<msg::VelocityCommand> cmd_topic_;
  dds::Topic<msg::CommandRejection> rejection_topic_;
  dds::Topic<msg::LockstepRegistration> registration_topic_;
  dds::Topic<msg::TickAck> ack_topic_;
  dds::Topic<msg::SpawnRequest> spawn_request_topic_;
  dds::Topic<msg::SpawnReply> spawn_reply_topic_;
  dds::Topic<msg::WorldMap> map_topic_;
  dds::Topic<msg::SimulatorStatus> status_topic_;
  dds::Writer<msg::SimClock> clock_writer_;
  dds::Writer<msg::RobotState> state_writer_;
  dds::Writer<msg::CommandRejection> rejection_writer_;
  dds::Writer<msg::SpawnReply> spawn_reply_writer_;
  dds::Writer<msg::WorldMap> map_writer_;
  dds::Writer<msg::SimulatorStatus> status_writer_;
  dds::Reader<msg::VelocityCommand> cmd_reader_;
  dds::Reader<msg::TickAck> ack_reader_;
  dds::Reader<msg::LockstepRegistration> registration_reader_;
  dds::Reader<msg::SpawnRequest> spawn_request_reader_;
};

}  // namespace autonomy::sim
