#pragma once
// The courier's thin DDS shell: commands in (autonomy/courier/command) through the CommandDesk,
// robot poses, door sightings, goal and handover statuses in, navigation goals and handover
// requests out, job states, schedules and reports published. A lockstep participant: on every
// tick it steps the executive once with what arrived, carries out the orders (journal first, then
// the wire), and acknowledges the tick. It never reads autonomy/truth/*.
#include "common/dds/reader.hpp"
#include "common/dds/topics.hpp"
#include "common/dds/writer.hpp"
#include "common/service/lockstep_client.hpp"
#include "common/service/service.hpp"
#include "services/courier/dds/command_desk.hpp"
#include "services/courier/dds/office_file.hpp"
#include "services/courier/journal/journal.hpp"

#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <string>

namespace autonomy::courier {

struct CourierNodeOptions {
  CourierOffice office;
  std::vector<CourierRobotSpec> robots;  // the couriers it drives
  std::string journal_path;
  std::string events_path;  // JSON lines of what happened, for pictures; "" = none
  std::string engine = "exact";  // for small job sets; "large" takes over above exact_max_jobs
  int exact_max_jobs = 8;
  double budget_ms = 50.0;
  double grid_resolution_m = 0.1;
};

class CourierNode {
 public:
  CourierNode(service::Service& service, CourierNodeOptions options);

 private:
  void on_tick(const msg::SimClock& clock);
  void carry_out(Orders orders, int64_t tick);
  msg::CourierJobStatus status_of(const Job& job, int64_t tick) const;
  double now_sim_s() const;
  double now_day_s() const;

  service::Service& service_;
  CourierNodeOptions options_;
  std::unique_ptr<ScheduleSource> scheduler_;
  std::unique_ptr<CourierExecutive> executive_;
  std::unique_ptr<Journal> journal_;
  std::unique_ptr<CommandDesk> desk_;
  std::ofstream events_file_;
  std::vector<std::pair<std::string, std::string>> answers_;  // handover answers since the last tick
  std::map<std::string, std::pair<double, double>> poses_;  // latest of each courier robot
  int64_t tick_ = 0;
  bool have_clock_ = false;

  dds::Topic<msg::CourierCommand> command_topic_;
  dds::Topic<msg::CourierReply> reply_topic_;
  dds::Topic<msg::CourierJobStatus> job_topic_;
  dds::Topic<msg::CourierSchedule> schedule_topic_;
  dds::Topic<msg::CourierReport> report_topic_;
  dds::Topic<msg::RobotState> state_topic_;
  dds::Topic<msg::DoorObservation> door_topic_;
  dds::Topic<msg::NavGoal> goal_topic_;
  dds::Topic<msg::GoalStatus> goal_status_topic_;
  dds::Topic<msg::HandoverRequest> handover_request_topic_;
  dds::Topic<msg::HandoverStatus> handover_status_topic_;
  dds::Reader<msg::CourierCommand> command_reader_;
  dds::Reader<msg::RobotState> state_reader_;
  dds::Reader<msg::DoorObservation> door_reader_;
  dds::Reader<msg::GoalStatus> goal_status_reader_;
  dds::Reader<msg::HandoverStatus> handover_status_reader_;
  dds::Writer<msg::CourierReply> reply_writer_;
  dds::Writer<msg::CourierJobStatus> job_writer_;
  dds::Writer<msg::CourierSchedule> schedule_writer_;
  dds::Writer<msg::CourierReport> report_writer_;
  dds::Writer<msg::NavGoal> goal_writer_;
  dds::Writer<msg::HandoverRequest> handover_writer_;
  service::LockstepClient lockstep_;
};

}  // namespace autonomy::courier
