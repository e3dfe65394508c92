#pragma once
// A DS1-like spacecraft as plain C++ (no DDS, threads, clocks or files): subsystems with modes,
// checked device commands confirmed in telemetry, a power balance, ground-station windows and
// the five faults of the Remote Agent Experiment (May 1999). The simulator node steps it with
// its tick, lockstep or paced alike; time is only what step() adds.
//
// Devices (names the executive's command rules use, services/executive/core/commands.hpp):
//   adcs      pointing | turning              turn(target), set_mode(control mode)
//   <thruster> ok | stuck_closed              (none)
//   ips       standby | thrusting             thrust(level 1..max), standby
//   camera    off | ready | imaging           power_on, off, take_image(target)
//   power     ok | deficit                    switch_on(switch), switch_off(switch)
//   telecom   idle | downlinking              downlink, stop
//   storage   ok | full                       (none)
//   <unit>    ok                              (none; e.g. "lpe")
// Every device also takes `reset` and reports "failed" while a Failed fault holds it.
//
// A command is checked in this order, and the first problem is its rejection reason: unknown
// device; unknown command for the device; argument count; the device has failed; the unit it is
// routed through has failed; the device is unpowered (its bus switch is open); argument range
// (unknown target, level out of range); invalid in the current mode. An accepted command is
// carried out at once and its device's confirmation (command, id, tick) shows in telemetry,
// unless a NeverConfirmed fault holds the device.
//
// Fault protection (fault_protection.hpp): when neither a command nor commander_heard() came for
// the spec's commander_timeout_s, step() safes the spacecraft: ion engine to standby, camera off,
// attitude held (a turn under way stops where it is); a device a StuckOn fault holds stays on and
// the event says so. Commands are not refused while safed: the next command or commander_heard()
// ends safe mode ("resumed") and the command is checked as always.
//
// Readings (telemetry sensor values): for each bus switch S "S_status" (1 closed, 0 open) and its
// two downstream voltage sensors "S_voltage_a", "S_voltage_b" (per unit of the bus voltage, 1
// when closed); "battery_soc", "solar_array_w", "load_w", "ips_power_w", "camera_power_w",
// "storage_used_mb", "downlink_rate_kbps", "pointing_error_deg", "turn_rate_deg_s". A
// FalseSensor fault replaces one reading and leaves the others true, so the redundant ones
// (the voltages of the same switch) tell a false status sensor from an open switch.
#include "common/msg/spacecraft.hpp"
#include "simulator/spacecraft/attitude.hpp"
#include "simulator/spacecraft/fault_protection.hpp"
#include "simulator/spacecraft/spacecraft_spec.hpp"

#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace autonomy::sim::spacecraft {

struct Command {
  std::string id;
  std::string source;
  std::string device;
  std::string command;
  std::vector<std::string> arguments;
};

struct [[nodiscard]] CommandResult {
  bool accepted = false;
  std::string reason;  // why it was rejected; empty when accepted
};

// A fault became active or ended (for the fault truth topic and the run's report).
struct FaultEvent {
  FaultSpec fault;
  bool active = false;
  std::string trigger;   // "at 3600 s", "on ips thrust", "injected"
  std::string ended_by;  // "reset", "cleared"
  double time_s = 0.0;
};

// Something the spacecraft did on its own (autonomy/spacecraft/event).
struct SpacecraftEventRecord {
  std::string kind;    // "safed", "resumed"
  std::string detail;  // what it did, or which sign of the commander ended safe mode
  double time_s = 0.0;
};

class Spacecraft {
 public:
  // Throws std::invalid_argument when the spec is inconsistent (the loader reports such
  // problems with file positions first; this guards programmatic specs).
  explicit Spacecraft(SpacecraftSpec spec);

  // Checks and carries out a command at the current time (the tick of step_count()).
  CommandResult submit(const Command& command);
  // Activates a fault now (scenario faults with a time or event are armed at construction);
  // rejected with a reason when its subject does not fit its kind or its id is in use.
  CommandResult inject(FaultSpec fault, const std::string& trigger = "injected");
  // Ends an active or armed fault; false when there is none with that id.
  bool clear_fault(const std::string& id);
  // A sign of life of the commander now (`sign`: "heartbeat of executive/ds1"): restarts the
  // command-loss timer and ends safe mode. submit() counts as one ("command c-1 from x").
  void commander_heard(const std::string& sign);
  bool safe_mode() const { return protection_.safe_mode(); }

  // Advances time: faults due by now activate, then the subsystems move (turns, exposures,
  // thrusting, downlink, power balance).
  void step(double dt_s);

  double time_s() const { return time_s_; }
  std::int64_t step_count() const { return steps_; }
  // tick and sim_time_ns are left for the caller (the node's clock).
  msg::SpacecraftTelemetry telemetry() const;
  std::string mode(const std::string& device) const;  // as telemetry reports it
  std::optional<double> reading(const std::string& sensor) const;
  std::vector<FaultEvent> take_fault_events();
  std::vector<SpacecraftEventRecord> take_events();
  const std::vector<std::string>& devices() const { return device_names_; }
  const SpacecraftSpec& spec() const { return spec_; }
  const Attitude& attitude() const { return attitude_; }
  std::uint64_t commands_accepted() const { return accepted_; }
  std::uint64_t commands_rejected() const { return rejected_; }

  // The names of every reading (false_sensor subjects), sorted.
  std::vector<std::string> reading_names() const;
  // Why `fault` cannot apply to this spacecraft, if it cannot (kind vs subject).
  std::optional<std::string> fault_problem(const FaultSpec& fault) const;

 private:
  struct Confirmation {
    std::string command, id;
    std::int64_t tick = -1;
  };
  struct ActiveFault {
    FaultSpec spec;
    std::string trigger;
  };

  std::optional<std::string> check(const Command& c) const;
  void execute(const Command& c);
  void arm_event_faults(const Command& c);
  void activate(FaultSpec fault, const std::string& trigger);
  void end_fault(std::size_t index, const std::string& ended_by);
  const ActiveFault* active(FaultKind kind, const std::string& subject) const;
  bool powered(const std::string& device) const;
  const BusSwitchSpec* switch_named(const std::string& name) const;
  std::string reported_mode(const std::string& device) const;
  std::set<std::string> stuck_thrusters() const;
  double ips_power_w(int level) const;
  double camera_power_w() const;
  double load_w() const;
  const StationWindowSpec* window_at(double t) const;
  std::map<std::string, double> true_readings() const;
  void unpower(const std::string& device);
  void enter_safe_mode();  // fault protection's safe configuration

  SpacecraftSpec spec_;
  std::vector<std::string> device_names_;  // sorted
  double time_s_ = 0.0;
  std::int64_t steps_ = 0;
  Attitude attitude_;

  std::string camera_mode_ = "ready";
  double exposure_left_s_ = 0.0;
  std::string image_target_;
  bool image_on_target_ = false;
  std::uint32_t images_taken_ = 0;
  std::uint32_t images_on_target_ = 0;
  std::string last_image_target_;

  int thrust_level_ = 0;  // 0: standby
  double thrust_time_s_ = 0.0;

  double battery_wh_ = 0.0;
  std::map<std::string, bool> switch_closed_;

  bool downlinking_ = false;
  double downlinked_mb_ = 0.0;
  double used_mb_ = 0.0;

  std::map<std::string, Confirmation> confirmations_;
  std::vector<ActiveFault> active_;
  std::vector<FaultSpec> armed_;  // scenario faults waiting for their time or command
  std::vector<FaultEvent> events_;
  std::uint64_t accepted_ = 0;
  std::uint64_t rejected_ = 0;

  CommandLossTimer protection_;
  std::vector<SpacecraftEventRecord> own_events_;
};

}  // namespace autonomy::sim::spacecraft
