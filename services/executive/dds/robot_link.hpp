#pragma once
// The executive's view of robots (the robot domain): a drive token's command go_to(site) becomes
// a go-to goal of the robot's behavior controller (autonomy/nav/goal), and the goal's status
// becomes the robot device's mode; report(site) becomes a team message to the base through the
// simulated radio, confirmed when the radio delivers it. Beside SpacecraftLink: the core sees
// devices, modes and confirmations either way.
#include <deque>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "common/dds/reader.hpp"
#include "common/dds/topics.hpp"
#include "common/dds/writer.hpp"
#include "executive_config.hpp"
#include "spacecraft_link.hpp"

namespace autonomy::executive {

class RobotLink {
 public:
  RobotLink(const dds::Participant& participant, std::string source, std::vector<RobotSpec> robots);

  bool handles(const std::string& device) const;

  // Reads goal statuses and deliveries; returns the commands confirmed for the first time.
  std::vector<Confirmation> update();
  // Commands refused since the last call (by the controller, or unknown sites), with the reason.
  std::vector<std::pair<DeviceCommand, std::string>> take_rejections();
  // Each robot device's mode: driving, stopped or blocked.
  void observe(Observations& seen) const;
  void send(const std::vector<DeviceCommand>& commands);

 private:
  struct Goal {  // the robot's latest goal from this executive
    std::string id;
    DeviceCommand command;
    bool confirmed = false;
  };
  struct Report {
    DeviceCommand command;
    std::string base;
  };
  const RobotSpec* robot_of(const std::string& device) const;
  void go_to(const RobotSpec& robot, const DeviceCommand& c);
  void report(const RobotSpec& robot, const DeviceCommand& c);

  std::string source_;
  std::vector<RobotSpec> robots_;
  dds::Topic<msg::NavGoal> goal_topic_;
  dds::Topic<msg::GoalStatus> status_topic_;
  dds::Topic<msg::TeamMessage> outbox_topic_;
  dds::Topic<msg::TeamDelivery> inbox_topic_;
  dds::Writer<msg::NavGoal> goal_writer_;
  dds::Reader<msg::GoalStatus> status_reader_;
  dds::Writer<msg::TeamMessage> outbox_writer_;
  dds::Reader<msg::TeamDelivery> inbox_reader_;
  std::uint64_t next_id_ = 1;
  std::map<std::string, Goal> goals_;                // by device
  std::map<std::string, std::string> modes_;         // by device
  std::map<std::string, Report> reports_;            // unconfirmed, by message id
  std::deque<std::string> report_order_;             // their ids, oldest first
  // Reports the radio lost are never confirmed; the oldest beyond this many are forgotten (the
  // executive has long declared their commands unconfirmed).
  static constexpr std::size_t kMaxUnconfirmedReports = 256;
  std::vector<std::pair<DeviceCommand, std::string>> rejections_;
};

}  // namespace autonomy::executive
