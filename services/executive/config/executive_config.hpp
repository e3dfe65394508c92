#pragma once
// The executive's configuration file (idl/executive_config.proto, protobuf text format): the
// model and problem to fly, the command rules beside the model, safing and the fault table.
// Every field is checked; each problem is reported with file:line:column.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "commands.hpp"
#include "common/config/file_error.hpp"
#include "fault_responses.hpp"
#include "mode_identification.hpp"

namespace autonomy::executive {

struct TimelineValue {
  std::string timeline, predicate;
  std::vector<std::string> parameters;
};

struct FaultTableSpec {
  int stuck_samples = 2;
  int max_resets = 2;
  std::vector<ComponentModel> components;
  std::vector<ModeResponseRule> mode_rules;
  int mode_samples = 2;
  std::vector<RedundantEvidence> sensors;
  std::vector<ActuatorFallback> actuators;
};

// A robot commanded through its behavior controller (idl/executive_config.proto, Robot).
struct RobotSpec {
  struct Site {
    std::string name;
    double x = 0, y = 0;
  };
  std::string device, robot_id;
  std::vector<Site> sites;
  double tolerance = 0;
  std::string radio_device, base;

  const Site* site(const std::string& name) const;
};

struct ExecutiveConfig {
  std::string source;  // the file it came from
  std::string name;
  std::string model_path, problem_path;  // resolved against the file's folder
  std::vector<CommandRule> rules;
  std::vector<DeviceCommand> safing;
  std::vector<TimelineValue> safe_values;
  FaultTableSpec faults;
  Time horizon_s = 0;  // 0: the problem's horizon
  Time request_lead_s = 600;
  std::string planner_engine;
  std::int64_t planner_budget_ms = 0;
  std::string optional_engine = "discrepancy";
  std::vector<RobotSpec> robots;

  CommandMap command_map() const;  // the rules, already checked
  // A fresh table (the parts keep state per plan run): stuck devices, resets, mode
  // identification, redundant sensors, stuck actuators, unconfirmed commands.
  std::vector<std::unique_ptr<FaultResponse>> fault_table() const;
  // The device a timeline's tokens command, or "" (for goals a disabled device makes impossible).
  std::vector<std::string> devices_of(const std::string& timeline) const;
};

// Reads and checks `path`; nullopt with every problem in `errors` otherwise.
std::optional<ExecutiveConfig> load_executive_config(const std::string& path,
                                                     std::vector<configfile::FileError>& errors);
// The same for text already read (`source` names it in errors and resolves relative paths).
std::optional<ExecutiveConfig> parse_executive_config(const std::string& text,
                                                      const std::string& source,
                                                      std::vector<configfile::FileError>& errors);

}  // namespace autonomy::executive
