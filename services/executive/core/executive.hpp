#pragma once
// The executive's pure core: one step per tick turns the dispatcher's events into device
// commands, awaits their confirmations, monitors device modes against the plan and applies the
// fault table's responses. It never blocks and does bounded work per step; a broken plan or an
// abort yields a replan request built from the current state, never a wait.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "commands.hpp"
#include "dispatcher.hpp"
#include "fault_responses.hpp"

namespace autonomy::executive {

struct ExecutiveEvent {
  // "started", "ended", "command", "skipped", "violation", "fault <action kind>", "aborted",
  // "goal_achieved", "goal_lost"
  std::string kind;
  Time time = 0;
  std::string text;
};

// What the planner needs to plan again from now: each timeline's current value (the token
// executing, with the time it started), the goals not achieved yet, and the faults known
// (device -> reported mode) so the new plan treats them as facts.
struct ReplanRequest {
  struct TimelineValue {
    std::string timeline, predicate;
    std::vector<std::string> parameters;
    Time since = 0;
  };
  Time time = 0;
  std::string reason;
  std::vector<TimelineValue> state;
  std::vector<planner::PlanToken> remaining_goals;
  std::map<std::string, std::string> known_faults;
  std::vector<std::string> disabled_devices;
};

struct Tick {
  std::vector<DeviceCommand> commands;  // to send, in order
  std::vector<ExecutiveEvent> events;
  std::optional<ReplanRequest> replan;  // set once, on the tick the plan is abandoned
};

struct ExecutiveOptions {
  std::vector<DeviceCommand> safing;  // sent on abort (e.g. camera off, engine standby)
};

// The label of the goal a token achieves ("goal down1; containedBy of token 22" -> "down1"),
// "" when it achieves none.
std::string goal_label(const std::string& origin);

class Executive {
 public:
  // Checks the plan (its network must be consistent); nullptr with a reason otherwise.
  static std::unique_ptr<Executive> create(planner::FlexiblePlan plan, CommandMap commands,
                                           std::vector<std::unique_ptr<FaultResponse>> faults,
                                           ExecutiveOptions options, Time start,
                                           std::string* error);

  // seen.time is now; ticks must not go back in time. Once aborted it dispatches nothing but
  // still answers faults (reset, switch control mode, ignore a sensor, stop commanding; an
  // abort is no answer then: the replan is under way).
  Tick step(const Observations& seen);
  // What a replan from now would start from (the current value of each timeline, the goals
  // left, the faults seen), without aborting: the node journals it as tokens start and end.
  ReplanRequest state_now(const Observations& seen) const { return replan_request(seen, ""); }
  // A command confirmed in telemetry; false when none was awaited.
  bool confirm(const std::string& device, const std::string& command);
  // A command the device refused (its status gave `reason`, e.g. "lpe has failed"): no longer
  // awaited, so the device is not given up for a confirmation that cannot come; the token it
  // served was not carried out (a goal among them ends lost). False when none was awaited.
  bool rejected(const DeviceCommand& command, const std::string& reason);

  // Never command `device` again and stop comparing it with the plan (a fault known from an
  // earlier plan); its tokens end by time.
  void disable_device(const std::string& device) { stop_commanding(device); }

  bool aborted() const { return aborted_; }
  bool finished() const { return dispatcher_.finished(); }
  bool disabled(const std::string& device) const { return tracker_.disabled(device); }
  bool ignored(const std::string& sensor) const { return ignored_sensors_.count(sensor) > 0; }
  // The fault table, for the next plan: its parts remember what they answered (a control
  // mode switched once, resets used) across plans. The executive answers no faults after.
  std::vector<std::unique_ptr<FaultResponse>> release_fault_table() { return std::move(faults_); }
  void set_fault_table(std::vector<std::unique_ptr<FaultResponse>> faults) { faults_ = std::move(faults); }
  // A sensor judged false under an earlier plan stays ignored.
  void ignore_sensor(const std::string& sensor) { ignored_sensors_.insert(sensor); }
  const std::set<std::string>& ignored_sensors() const { return ignored_sensors_; }
  const std::set<std::string>& disabled_devices() const { return tracker_.disabled_devices(); }
  // "timeline == predicate(args) #id" of each token executing now.
  std::vector<std::string> executing() const;
  const Dispatcher& dispatcher() const { return dispatcher_; }

 private:
  Executive(Dispatcher dispatcher, CommandMap commands,
            std::vector<std::unique_ptr<FaultResponse>> faults, ExecutiveOptions options);
  PlanState plan_state(Time now) const;
  ReplanRequest replan_request(const Observations& seen, std::string reason) const;
  void stop_commanding(const std::string& device);
  std::size_t next_on_timeline(std::size_t token) const;  // SIZE_MAX for the last
  void abort(const Observations& seen, std::string reason, Tick* tick);
  // The fault table's answers to what is seen; an abort's reason goes to *broken.
  void respond_to_faults(const Observations& seen, Time now, Tick* tick, std::string* broken);
  // A goal token ended: achieved unless its device was not commanded for it.
  void goal_ended(std::size_t token, Time now, Tick* tick);

  Dispatcher dispatcher_;
  CommandMap commands_;
  CommandTracker tracker_;
  std::vector<std::unique_ptr<FaultResponse>> faults_;
  ExecutiveOptions options_;
  std::set<std::string> ignored_sensors_;
  // Tokens whose device was not commanded for them (skipped, or disabled while they ran), with
  // why: a goal among them ends lost, not achieved.
  std::map<std::size_t, std::string> uncommanded_;
  bool aborted_ = false;
};

}  // namespace autonomy::executive
