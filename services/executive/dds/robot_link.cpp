#include "robot_link.hpp"

#include <spdlog/spdlog.h>
#include <unistd.h>

namespace autonomy::executive {

RobotLink::RobotLink(const dds::Participant& participant, std::string source,
                     std::vector<RobotSpec> robots)
    // The process id keeps goal ids apart from an earlier run's (goal statuses are durable).
    : source_(std::move(source) + "-" + std::to_string(::getpid())),
      robots_(std::move(robots)),
      goal_topic_(participant, dds::topics::nav_goal),
      status_topic_(participant, dds::topics::goal_status),
      outbox_topic_(participant, dds::topics::team_outbox),
      inbox_topic_(participant, dds::topics::team_inbox),
      goal_writer_(participant, goal_topic_),
      status_reader_(participant, status_topic_),
      outbox_writer_(participant, outbox_topic_),
      inbox_reader_(participant, inbox_topic_) {
  for (const RobotSpec& r : robots_) modes_[r.device] = "stopped";
}

const RobotSpec* RobotLink::robot_of(const std::string& device) const {
  for (const RobotSpec& r : robots_)
    if (r.device == device || (!r.radio_device.empty() && r.radio_device == device)) return &r;
  return nullptr;
}

bool RobotLink::handles(const std::string& device) const { return robot_of(device) != nullptr; }

std::vector<Confirmation> RobotLink::update() {
  std::vector<Confirmation> out;
  for (auto& s : status_reader_.take()) {
    if (!s.valid) continue;
    const msg::GoalStatus& st = s.value;
    for (auto& [device, goal] : goals_) {
      const RobotSpec* robot = robot_of(device);
      if (robot->robot_id != st.robot_id || goal.id != st.goal_id) continue;  // not our latest
      switch (st.state) {
        case msg::GoalState::Accepted:
        case msg::GoalState::Active:
          modes_[device] = "driving";
          break;
        case msg::GoalState::Reached:
          modes_[device] = "stopped";
          break;
        case msg::GoalState::Rejected:
          if (!goal.confirmed) {
            rejections_.emplace_back(goal.command, st.reason);
            goal.confirmed = true;  // answered: nothing more to await
          }
          modes_[device] = "blocked";
          continue;
        default:  // blocked, preempted, cancelled: the controller gave the goal up
          modes_[device] = "blocked";
          spdlog::info("{}: goal {} {}: {}", device, goal.id,
                       st.state == msg::GoalState::Blocked ? "blocked" : "ended", st.reason);
          break;
      }
      if (!goal.confirmed) {
        goal.confirmed = true;
        out.push_back({device, goal.command.command, goal.id});
      }
    }
  }
  for (auto& s : inbox_reader_.take()) {
    if (!s.valid) continue;
    auto it = reports_.find(s.value.message_id);
    if (it == reports_.end() || s.value.recipient != it->second.base) continue;
    out.push_back({it->second.command.device, it->second.command.command, it->first});
    reports_.erase(it);
  }
  return out;
}

std::vector<std::pair<DeviceCommand, std::string>> RobotLink::take_rejections() {
  return std::exchange(rejections_, {});
}

void RobotLink::observe(Observations& seen) const {
  for (const auto& [device, mode] : modes_) seen.device_modes[device] = mode;
}

void RobotLink::send(const std::vector<DeviceCommand>& commands) {
  for (const DeviceCommand& c : commands) {
    const RobotSpec* robot = robot_of(c.device);
    if (!robot) continue;
    if (c.device == robot->device && c.command == "go_to") go_to(*robot, c);
    else if (c.device == robot->radio_device && c.command == "report") report(*robot, c);
    else rejections_.emplace_back(c, "robot device " + c.device + " has no command " + c.command);
  }
}

void RobotLink::go_to(const RobotSpec& robot, const DeviceCommand& c) {
  const RobotSpec::Site* site = c.arguments.size() == 1 ? robot.site(c.arguments[0]) : nullptr;
  if (!site) {
    rejections_.emplace_back(c, "no site '" + (c.arguments.empty() ? "" : c.arguments[0]) +
                                    "' for " + robot.device + " in the configuration");
    return;
  }
  Goal goal{source_ + "-" + std::to_string(next_id_++), c, false};
  goal_writer_.write(msg::NavGoal{robot.robot_id, goal.id, site->x, site->y, robot.tolerance, ""});
  // Driving from the command on: the controller's first status may come ticks later, and the
  // stop of the goal before it must not end this drive.
  modes_[robot.device] = "driving";
  goals_[robot.device] = std::move(goal);
}

void RobotLink::report(const RobotSpec& robot, const DeviceCommand& c) {
  const std::string id = source_ + "-" + std::to_string(next_id_++);
  const std::string what = c.arguments.empty() ? "" : c.arguments[0];
  outbox_writer_.write(msg::TeamMessage{robot.robot_id, robot.base, id, "sample " + what});
  reports_[id] = {c, robot.base};
  report_order_.push_back(id);
  while (report_order_.size() > kMaxUnconfirmedReports) {
    reports_.erase(report_order_.front());  // confirmed ones are gone from reports_ already
    report_order_.pop_front();
  }
}

}  // namespace autonomy::executive
