#pragma once
// The courier's thin DDS shell: commands in (autonomy/courier/command) through the CommandDesk,
// robot poses, door sightings, goal and handover statuses in, navigation goals and handover
// requests out, job states, schedules and reports published. A lockstep participant: on every
// tick it steps the executive once with what arrived, carries out the orders (journal first, then
// the wire), and acknowledges the tick. It never reads autonomy/truth/*.
// The fleet follows the behavior processes' heartbeats (FleetRoster): a courier robot joins when
// its behavior is ready and leaves when it stops or its heartbeat is lost.
#include "common/dds/reader.hpp"
#include "common/dds/topics.hpp"
#include "common/dds/writer.hpp"
#include "common/service/lockstep_client.hpp"
#include "common/service/service.hpp"
#include "services/courier/core/bridge/engine_schedule_source.hpp"
#include "services/courier/core/execution/fleet_roster.hpp"
#include "services/courier/dds/command_desk.hpp"
#include "services/courier/dds/office_file.hpp"
#include "services/courier/journal/journal.hpp"

#include <chrono>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <string>

namespace autonomy::courier {

struct CourierNodeOptions {
  CourierOffice office;
  // Couriers declared (the scenario's robots of kind courier, or --robot): each joins the fleet
  // when its behavior's heartbeat says ready. Robots whose behavior announces the courier
  // capability join too, with attach_defaults' capacity unless declared.
  std::vector<CourierRobotSpec> robots;
  CourierRobotSpec attach_defaults;
  double robot_lost_after_s = 5.0;  // wall-clock seconds without a heartbeat: the robot is lost
  std::string journal_path;
  std::string events_path;  // JSON lines of what happened, for pictures; "" = none
  std::string engine = "exact";  // for small job sets; "large" takes over above exact_max_jobs
  int exact_max_jobs = 8;
  double budget_ms = 50.0;
  double grid_resolution_m = 0.1;
  // Learn from experience (handover times, presence, door habits, travel times), keep it in the
  // journal across runs and schedule with it; false: the office file's nominal values only.
  bool learning = true;
  // false: doors are not watched; a robot blocked by a closed door waits there and tries again
  // (the paper's heuristic without its monitoring; what Open-RMF does).
  bool monitor_doors = true;
};

class CourierNode {
 public:
  CourierNode(service::Service& service, CourierNodeOptions options);
  ~CourierNode();
  CourierNode(const CourierNode&) = delete;
  CourierNode& operator=(const CourierNode&) = delete;

 private:
  void on_tick(const msg::SimClock& clock);
  // Quiet ticks (idl/clock.idl): the first tick the executive needs again (0: this one's next).
  std::int64_t quiet_until_tick() const;
  // After an input: the world must not stay quiet when it gave the executive work.
  void wake_if_needed();
  void carry_out(Orders orders, int64_t tick);
  void save_experience();
  msg::CourierJobStatus status_of(const Job& job, int64_t tick) const;
  double now_sim_s() const;
  double now_day_s() const;
  // The time of day of a sample stamped `tick` (now_day_s() for ticks up to ours).
  double day_s_of(std::int64_t tick) const;
  std::int64_t vote_day() const;
  // Heartbeats of behavior processes: robots join and leave the executive's fleet.
  void on_heartbeats(std::vector<dds::Sample<msg::Heartbeat>> samples);
  void apply(const std::vector<RosterChange>& changes);
  const CourierRobotSpec& spec_of(const std::string& robot) const;

  service::Service& service_;
  CourierNodeOptions options_;
  std::unique_ptr<EngineScheduleSource> scheduler_;
  std::unique_ptr<CourierExecutive> executive_;
  std::unique_ptr<Journal> journal_;
  double experience_saved_at_s_ = 0.0;  // simulated time of the last save of what was learned
  std::unique_ptr<CommandDesk> desk_;
  std::ofstream events_file_;
  std::vector<std::pair<std::string, std::string>> answers_;  // handover answers since the last tick
  std::map<std::string, std::pair<double, double>> poses_;  // latest of every robot (members or not)
  std::unique_ptr<FleetRoster> roster_;
  std::chrono::steady_clock::time_point started_ = std::chrono::steady_clock::now();
  int64_t tick_ = 0;
  bool have_clock_ = false;
  double step_s_ = 0.0;

  dds::Topic<msg::CourierCommand> command_topic_;
  dds::Topic<msg::CourierReply> reply_topic_;
  dds::Topic<msg::CourierJobStatus> job_topic_;
  dds::Topic<msg::CourierSchedule> schedule_topic_;
  dds::Topic<msg::CourierReport> report_topic_;
  dds::Topic<msg::RobotState> state_topic_;
  dds::Topic<msg::DoorObservation> door_topic_;
  dds::Topic<msg::NavGoal> goal_topic_;
  dds::Topic<msg::NavCancel> cancel_topic_;
  dds::Topic<msg::GoalStatus> goal_status_topic_;
  dds::Topic<msg::HandoverRequest> handover_request_topic_;
  dds::Topic<msg::HandoverStatus> handover_status_topic_;
  dds::Reader<msg::CourierCommand> command_reader_;
  dds::Reader<msg::RobotState> state_reader_;
  dds::Reader<msg::DoorObservation> door_reader_;
  dds::Reader<msg::GoalStatus> goal_status_reader_;
  dds::Reader<msg::HandoverStatus> handover_status_reader_;
  dds::Topic<msg::Heartbeat> heartbeat_topic_;
  dds::Reader<msg::Heartbeat> heartbeat_reader_;
  dds::Writer<msg::CourierReply> reply_writer_;
  dds::Writer<msg::CourierJobStatus> job_writer_;
  dds::Writer<msg::CourierSchedule> schedule_writer_;
  dds::Writer<msg::CourierReport> report_writer_;
  dds::Writer<msg::NavGoal> goal_writer_;
  dds::Writer<msg::NavCancel> cancel_writer_;
  dds::Writer<msg::HandoverRequest> handover_writer_;
  service::LockstepClient lockstep_;
};

}  // namespace autonomy::courier
