#pragma once
// The simulator's thin DDS shell: turns samples into calls on sim::World and sim::LockstepBarrier
// and publishes the world back. All of it runs on the service's event-loop thread.
//
// Tick cycle: publish robot states of tick k, then the clock of tick k; wait (lockstep) for the
// barrier or (paced) for the wall-clock period; apply the commands stamped k in a fixed order
// (robot id, then source, then arrival), step the world, tick k+1. A robot spawned during tick k
// has its state published for tick k at once, so its controller can act on k before the step.
//
// What a tick publishes before its clock, in this order: radio links and team connectivity that
// changed (every radio_period_ticks), team messages due by now (autonomy/team/inbox), robot states
// (ground truth), perception of robots with sensors (range scan, pose estimate, door
// observations), door ground truth that changed, then the office: handovers that completed or
// failed by now (autonomy/office/handover_status) and objects that moved (autonomy/truth/object).
// Team messages from autonomy/team/outbox are decided (route, loss, delay) when they arrive, with
// the radio of the current tick; so are load/unload requests (autonomy/office/handover_request),
// against the robots' true positions and the simulated time of the current tick.
#include "common/dds/reader.hpp"
#include "common/dds/topics.hpp"
#include "common/dds/waitset.hpp"
#include "common/dds/writer.hpp"
#include "common/service/service.hpp"
#include "simulator/core/lockstep_barrier.hpp"
#include "simulator/dds/batched_writer.hpp"
#include "simulator/core/world.hpp"
#include "simulator/office/handover_desk.hpp"
#include "simulator/radio/connectivity.hpp"
#include "simulator/radio/link_changes.hpp"
#include "simulator/radio/message_relay.hpp"
#include "simulator/radio/radio_model.hpp"
#include "simulator/report/run_metrics.hpp"
#include "simulator/scenario/scenario_loader.hpp"
#include "simulator/report/trajectory_recorder.hpp"
#include "simulator/scenario/simulation_settings.hpp"

#include <chrono>
#include <cstdint>
#include <deque>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <random>
#include <utility>
#include <set>
#include <string>
#include <vector>

namespace autonomy::sim {

class SpacecraftArea;  // simulator/dds/spacecraft_area.hpp

struct SimulatorRunOptions {
  SimulationSettings settings;
  // Lockstep: tick 0 is held until these participants registered, so a run is reproducible
  // from its first tick.
  std::vector<std::string> wait_for_participants;
  std::optional<int64_t> max_ticks;  // stop the service after this tick
  // Stop the service once every robot in the world reports its mission finished (or its goal
  // reached), so that an experiment's run time is its mission time.
  bool stop_when_finished = false;
  std::string trajectory_csv;         // tick,time_s,robot,x,y,theta per robot per tick, if set
  std::string picture_svg;            // an SVG picture of the run written at exit, if set
  // Metrics (simulator/report/run_metrics.hpp) written at exit to PREFIX.csv and PREFIX.json.
  std::string metrics_prefix;
  // The radio link table is recomputed every this many ticks (and when robots join).
  int radio_period_ticks = 1;
  // Lockstep: ticks every participant declared it does not need, while nothing in the world
  // changes, are stepped without being published (idl/clock.idl, quiet_until_tick).
  bool quiet_ticks = true;
  // Carried by every clock sample: services follow this world only (dds/world_claim.hpp).
  uint64_t world_id = 0;
};

class SimulatorNode {
 public:
  // The world is built from scenario.world; its radio settings, places and areas are used too.
  SimulatorNode(service::Service& service, Scenario scenario, SimulatorRunOptions options);
  ~SimulatorNode();

 private:
  // Commands are taken when needed, not on arrival (see the constructor): take_commands() hands
  // what the reader holds to on_commands().
  void take_commands();
  void on_commands(std::vector<dds::Sample<msg::VelocityCommand>> samples);
  void on_acks(std::vector<dds::Sample<msg::TickAck>> samples);
  void on_registrations(std::vector<dds::Sample<msg::LockstepRegistration>> samples);
  void on_spawn_requests(std::vector<dds::Sample<msg::SpawnRequest>> samples);
  void on_door_commands(std::vector<dds::Sample<msg::DoorCommand>> samples);
  void on_outbox(std::vector<dds::Sample<msg::TeamMessage>> samples);
  void on_goal_status(std::vector<dds::Sample<msg::GoalStatus>> samples);
  void on_foreign_clocks(std::vector<dds::Sample<msg::SimClock>> samples);
  void on_mission_status(std::vector<dds::Sample<msg::MissionStatus>> samples);
  void on_handover_requests(std::vector<dds::Sample<msg::HandoverRequest>> samples);
  void on_timer();

  bool lockstep() const { return options_.settings.mode == ClockMode::Lockstep; }
  bool holding_start() const;
  void advance_while_complete();
  // Whether the world may step now (a lockstep tick every participant answered, or quiet ticks).
  bool may_advance() const;
  void advance();  // applies commands, steps the world, opens the next tick
  bool every_robot_finished() const;  // the world has robots and each reported finished
  void apply_commands(const std::vector<msg::VelocityCommand>& commands);
  void handle_spawns();
  void open_tick();  // publishes state and clock of tick_, starts the barrier's tick
  // The states of these robots at tick_, sent together (one datagram per reader process).
  void publish_robot_states(const std::vector<RobotStatus>& robots);
  void record_robot(const RobotStatus& robot);  // the trajectory file and picture, no DDS
  // Quiet ticks (simulator/dds/quiet_ticks.cpp).
  // The tick just stepped need not be published (`robots`: the world's, at this tick).
  bool may_stay_quiet(const std::vector<RobotStatus>& robots);
  void keep_quiet(const std::vector<RobotStatus>& robots);  // records it as a published tick would be
  void continue_quietly();  // the next batch of quiet ticks, after the loop looked at its readers
  bool doors_as_published() const;
  // The radio of the current positions: link table, connectivity; publishes what changed.
  void update_radio();
  void deliver_due_messages();
  void publish_perception(const std::vector<RobotStatus>& robots);
  void publish_door_changes();
  // The office at the current tick: completions and failures, then objects that moved.
  // Returns whether it published anything.
  bool update_office(const std::vector<RobotStatus>& robots);
  void publish_handover(const office::DeskAnswer& answer);
  void record_metrics(const std::vector<RobotStatus>& robots);
  bool connected_to_teammate(const std::string& robot) const;
  void write_metrics() const;
  void publish_status();
  void write_picture() const;
  void reject(const msg::VelocityCommand& command, const std::string& reason);
  // A participant dropped from lockstep or taken back: logged, kept in the status's list of
  // changes, and the status written at once (docs/topics.md, autonomy/sim/status).
  void lockstep_changed(const std::string& participant, bool dropped, const std::string& reason);

  service::Service& service_;
  Scenario scenario_;
  World world_;
  SimulatorRunOptions options_;
  LockstepBarrier barrier_;
  std::set<std::string> registered_once_;  // for --wait-for: who has registered since the start
  int64_t tick_ = 0;
  std::chrono::steady_clock::time_point last_advance_;
  // The open tick's clock sample and when it was last written: repeated every second while the
  // world waits for acks (one may have been lost while a participant and the simulator had lost
  // each other; participants write their ack of a repeated tick again).
  msg::SimClock last_clock_{};
  std::chrono::steady_clock::time_point clock_written_;
  std::map<int64_t, std::vector<msg::VelocityCommand>> commands_by_tick_;  // lockstep, per tick
  std::vector<msg::VelocityCommand> unsynchronised_commands_;  // from outside lockstep: next step
  std::vector<msg::SpawnRequest> spawn_requests_;
  // Requesters repeat a request until its reply arrives; a repeat gets the first answer again.
  std::map<std::string, msg::SpawnReply> spawn_replies_;
  uint64_t commands_applied_ = 0;
  uint64_t commands_rejected_ = 0;
  uint64_t participants_dropped_ = 0;
  std::deque<msg::LockstepChange> lockstep_changes_;  // the last kLockstepChangesKept
  uint64_t lockstep_changes_count_ = 0;
  // Participants whose registration ended without leaving (lease expired) and that have not
  // registered again: a drop says so.
  std::set<std::string> registration_ended_;
  double step_compute_us_total_ = 0.0;
  std::ofstream trajectory_;
  TrajectoryRecorder paths_;
  bool finished_ = false;

  // Quiet ticks: tick_ is stepped without being published while quiet_.
  bool quiet_ = false;
  // Something came from outside the handshake (a command, a spawn, a message): publish the next
  // tick whatever the participants declared.
  bool wake_ = false;
  uint64_t quiet_ticks_ = 0;
  std::map<std::string, geometry::Pose2> published_poses_;
  dds::GuardCondition quiet_continue_;
  // The acks that complete a tick are taken in the receive thread that delivers them (on_acks);
  // the world steps on the loop's thread, woken by this once per tick (docs/scale.md).
  dds::GuardCondition step_due_;

  // Radio: robots in id order are the table's indices; only connected links are held.
  radio::RadioModel radio_;
  radio::NearLinkTable links_;
  std::vector<std::string> radio_ids_;
  std::optional<radio::Connectivity> connectivity_;
  bool radio_dirty_ = true;  // robots joined since the last update
  radio::LinkChangeFilter link_changes_;  // which RadioLink samples to write
  std::optional<std::vector<std::vector<std::string>>> published_components_;
  std::mt19937_64 delivery_rng_;
  radio::MessageRelay<msg::TeamDelivery> relay_;
  uint64_t messages_delivered_ = 0;
  uint64_t messages_no_route_ = 0;
  uint64_t messages_lost_ = 0;
  uint64_t messages_invalid_ = 0;

  std::vector<std::optional<msg::DoorState>> published_doors_;  // parallel to world_.doors()
  std::optional<RunMetrics> metrics_;
  // A robot has finished when its goal is reached (autonomy/nav/goal_status) or its mission ended
  // (autonomy/mission/status); the metrics' mission time stops there.
  std::map<std::string, bool> goal_reached_;

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
  dds::Topic<msg::RangeScan> scan_topic_;
  dds::Topic<msg::PoseEstimate> pose_topic_;
  dds::Topic<msg::DoorObservation> door_observation_topic_;
  dds::Topic<msg::DoorState> door_truth_topic_;
  dds::Topic<msg::RadioLink> link_topic_;
  dds::Topic<msg::TeamConnectivity> team_topic_;
  dds::Topic<msg::TeamMessage> outbox_topic_;
  dds::Topic<msg::TeamDelivery> inbox_topic_;
  dds::Topic<msg::DoorCommand> door_command_topic_;
  dds::Topic<msg::GoalStatus> goal_status_topic_;
  dds::Topic<msg::MissionStatus> mission_status_topic_;
  dds::Writer<msg::SimClock> clock_writer_;
  BatchedWriter<msg::RobotState> state_writer_;  // flushed once per tick: publish_robot_states()
  dds::Writer<msg::CommandRejection> rejection_writer_;
  dds::Writer<msg::SpawnReply> spawn_reply_writer_;
  dds::Writer<msg::WorldMap> map_writer_;
  dds::Writer<msg::SimulatorStatus> status_writer_;
  dds::Writer<msg::RangeScan> scan_writer_;
  dds::Writer<msg::PoseEstimate> pose_writer_;
  dds::Writer<msg::DoorObservation> door_observation_writer_;
  dds::Writer<msg::DoorState> door_truth_writer_;
  dds::Writer<msg::RadioLink> link_writer_;
  dds::Writer<msg::TeamConnectivity> team_writer_;
  dds::Writer<msg::TeamDelivery> inbox_writer_;
  dds::Reader<msg::VelocityCommand> cmd_reader_;
  dds::Reader<msg::TickAck> ack_reader_;
  dds::Reader<msg::LockstepRegistration> registration_reader_;
  dds::Reader<msg::SpawnRequest> spawn_request_reader_;
  dds::Reader<msg::DoorCommand> door_command_reader_;
  dds::Reader<msg::TeamMessage> outbox_reader_;
  dds::Reader<msg::GoalStatus> goal_status_reader_;
  dds::Reader<msg::MissionStatus> mission_status_reader_;

  // The office (scenario people, objects, loading stations); absent without office content, when
  // every handover request is rejected (no_office).
  std::optional<office::HandoverDesk> office_;
  dds::Topic<msg::HandoverRequest> handover_request_topic_;
  dds::Topic<msg::HandoverStatus> handover_status_topic_;
  dds::Topic<msg::ObjectState> object_truth_topic_;
  dds::Writer<msg::HandoverStatus> handover_status_writer_;
  dds::Writer<msg::ObjectState> object_truth_writer_;
  dds::Reader<msg::HandoverRequest> handover_request_reader_;

  // The spacecraft, when the scenario has one (its topics, commands and telemetry).
  std::unique_ptr<SpacecraftArea> spacecraft_;

  // Clocks of another world on this domain (a simulator started within this one's listen window,
  // or a forger): reported as errors and counted in the heartbeat, never followed.
  dds::Reader<msg::SimClock> foreign_clock_reader_;
  uint64_t foreign_clock_samples_ = 0;
};

}  // namespace autonomy::sim
