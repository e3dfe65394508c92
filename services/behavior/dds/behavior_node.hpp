#pragma once
// The behavior controller's thin DDS shell for one robot. It attaches the robot (spawn request),
// takes goals from autonomy/nav/goal, and on every tick of the simulator's clock turns the robot's
// state into one velocity command through GoalTracker and GoToController, then acknowledges the
// tick. Runs on the service's event-loop thread.
#include "common/dds/reader.hpp"
#include "common/dds/topics.hpp"
#include "common/dds/writer.hpp"
#include "common/service/lockstep_client.hpp"
#include "common/service/service.hpp"
#include "services/behavior/core/go_to_controller.hpp"
#include "services/behavior/core/goal_tracker.hpp"

#include <chrono>
#include <memory>
#include <optional>
#include <string>

namespace autonomy::behavior {

struct BehaviorNodeOptions {
  std::string robot_id;
  std::optional<geometry::Pose2> start;  // spawn pose; unset: the scenario's configured start
  std::optional<msg::NavGoal> initial_goal;  // pursued as soon as the robot is ready
  double grid_resolution_m = 0.1;
  GoalTrackerConfig tracker;
  GoToConfig go_to;
};

class BehaviorNode {
 public:
  BehaviorNode(service::Service& service, BehaviorNodeOptions options);

 private:
  void request_spawn();
  void on_spawn_replies(std::vector<dds::Sample<msg::SpawnReply>> samples);
  void on_states(std::vector<dds::Sample<msg::RobotState>> samples);
  void on_map(std::vector<dds::Sample<msg::WorldMap>> samples);
  void on_goals(std::vector<dds::Sample<msg::NavGoal>> samples);
  void on_tick(const msg::SimClock& clock);
  void become_ready_when_possible();
  void accept_goal(const msg::NavGoal& goal);
  // Computes and sends the command for pending_tick_ once the state of that tick is here.
  void control_pending_tick();
  void publish(const GoalReport& report);
  void send_command(const VelocityCommand& command, int64_t tick);

  service::Service& service_;
  BehaviorNodeOptions options_;
  std::string participant_name_;
  std::string spawn_request_id_;
  bool spawned_ = false;
  std::optional<msg::RobotState> state_;
  std::optional<msg::WorldMap> map_;
  std::optional<GoalTracker> tracker_;
  std::optional<GoToController> controller_;
  std::optional<msg::NavGoal> queued_goal_;  // arrived before the robot was ready
  std::optional<int64_t> pending_tick_;
  bool stopped_robot_ = true;  // the last command sent was zero (or none was sent)
  std::chrono::steady_clock::time_point last_spawn_request_;

  dds::Topic<msg::RobotState> state_topic_;
  dds::Topic<msg::WorldMap> map_topic_;
  dds::Topic<msg::NavGoal> goal_topic_;
  dds::Topic<msg::GoalStatus> goal_status_topic_;
  dds::Topic<msg::VelocityCommand> cmd_topic_;
  dds::Topic<msg::SpawnRequest> spawn_request_topic_;
  dds::Topic<msg::SpawnReply> spawn_reply_topic_;
  dds::Reader<msg::RobotState> state_reader_;
  dds::Reader<msg::WorldMap> map_reader_;
  dds::Reader<msg::NavGoal> goal_reader_;
  dds::Reader<msg::SpawnReply> spawn_reply_reader_;
  dds::Writer<msg::GoalStatus> goal_status_writer_;
  dds::Writer<msg::VelocityCommand> cmd_writer_;
  dds::Writer<msg::SpawnRequest> spawn_request_writer_;
  service::LockstepClient lockstep_;
};

}  // namespace autonomy::behavior
