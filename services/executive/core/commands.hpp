#pragma once
// Token starts become device commands through a small mapping declared beside the model
// (camera == picture(?target) -> camera take_image(target)); each command sent is awaited in
// telemetry until a timeout. Devices the executive stopped commanding are remembered here.
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "dispatchable_network.hpp"

namespace autonomy::executive {

struct DeviceCommand {
  std::string device, command;
  std::vector<std::string> arguments;
  std::size_t token = SIZE_MAX;  // the plan token it serves
  Time sent = 0;
};

// timeline == predicate(...) -> device command(arguments). An argument "?N" is the token's
// N-th parameter. end_mode: the device mode whose report ends the token (the world controls
// the end, e.g. a turn; a report before the end's window opens is held until it opens: the
// plan's bound includes settling); empty: the executive ends the token by time. expect_mode: the mode
// the device should report while the token executes (what monitoring compares). A rule with
// no command only declares that expectation (camera == ready).
struct CommandRule {
  std::string timeline, predicate;
  std::string device, command;
  std::string expect_mode;
  std::vector<std::string> arguments;
  Time confirm_timeout = 5;
  std::string end_mode;
  // Sent to `device` when the token ends, unless the next token of its timeline has begun by
  // then (it commands the device itself): engine standby after the last thrust arc.
  std::string end_command;
};

class CommandMap {
 public:
  // Checks the rule (names given, "?N" indices numeric); false with a reason otherwise.
  bool add(CommandRule rule, std::string* error);
  const CommandRule* rule_for(const planner::PlanToken& token) const;
  // The command for a token start, or nullopt when no rule applies (or a "?N" is missing).
  std::optional<DeviceCommand> command_for(const planner::PlanToken& token, std::size_t index,
                                           Time now, std::string* error) const;

 private:
  const CommandRule* rule_for_key(const std::string& timeline, const std::string& predicate) const;
  std::vector<CommandRule> rules_;
};

// Sent commands awaiting confirmation. A command not confirmed by its deadline is returned
// once by expire(); its device is then disabled (no further commands to it).
class CommandTracker {
 public:
  void sent(const DeviceCommand& command, Time timeout);
  // A confirmation from telemetry; false when nothing was awaited for that device/command.
  bool confirm(const std::string& device, const std::string& command);
  std::vector<DeviceCommand> expire(Time now);
  void disable(const std::string& device) { disabled_.insert(device); }
  bool disabled(const std::string& device) const { return disabled_.count(device) > 0; }
  const std::set<std::string>& disabled_devices() const { return disabled_; }
  std::size_t awaiting() const { return pending_.size(); }
  bool awaiting(const std::string& device) const;

 private:
  struct Pending {
    DeviceCommand command;
    Time deadline;
  };
  std::vector<Pending> pending_;
  std::set<std::string> disabled_;
};

}  // namespace autonomy::executive
