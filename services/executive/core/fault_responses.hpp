#pragma once
// Mode identification and fault responses behind one interface: given this tick's
// observations and the plan's state, what to do. The concrete parts are the Remote Agent
// Experiment's cases (DS1, May 1999); the executive consults them in table order.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "dispatchable_network.hpp"

namespace autonomy::executive {

// What telemetry says this tick: the mode each device reports, numeric sensor readings, and
// the commands whose confirmation timed out (from the CommandTracker).
struct Observations {
  Time time = 0;
  std::map<std::string, std::string> device_modes;  // device -> reported mode
  std::map<std::string, double> readings;           // sensor -> value
  std::vector<std::string> unconfirmed_devices;     // commands not confirmed in time
};

// What the plan says now: per device the mode the executing token implies.
struct PlanState {
  Time time = 0;
  std::map<std::string, std::string> expected_modes;  // device -> mode the plan expects
};

struct FaultAction {
  enum class Kind {
    kAbortAndReplan,     // safe the spacecraft, request a plan from the current state
    kReset,              // reset the unit and carry on, no replan
    kIgnoreSensor,       // the sensor is judged false: its readings are ignored from now on
    kSwitchControlMode,  // use a control mode that does not need the failed actuator
    kStopCommanding,     // never command the device again, carry on with the rest
  };
  Kind kind = Kind::kAbortAndReplan;
  std::string subject;  // the device or sensor
  std::string mode;     // for kSwitchControlMode: the new mode (on device `control_device`)
  std::string control_device;
  std::string reason;
};
const char* to_string(FaultAction::Kind kind);

class FaultResponse {
 public:
  virtual ~FaultResponse() = default;
  virtual std::vector<FaultAction> assess(const Observations& seen, const PlanState& plan) = 0;
};

// A device whose reported mode stays different from the plan's for `samples` ticks (camera
// stuck on after its off) and that is not reporting "failed": the plan cannot go on.
class StuckDeviceResponse : public FaultResponse {
 public:
  explicit StuckDeviceResponse(int samples = 2) : samples_(samples) {}
  std::vector<FaultAction> assess(const Observations& seen, const PlanState& plan) override;

 private:
  int samples_;
  std::map<std::string, int> disagreeing_;
};

// A unit that reports mode "failed": reset it, up to `max_resets` times per unit; once they
// are used up, stop commanding it.
class ResetUnitResponse : public FaultResponse {
 public:
  explicit ResetUnitResponse(int max_resets = 2) : max_resets_(max_resets) {}
  std::vector<FaultAction> assess(const Observations& seen, const PlanState& plan) override;

 private:
  int max_resets_;
  std::map<std::string, int> resets_;
  std::map<std::string, bool> was_failed_;
};

// A sensor with redundant evidence (other readings that predict it: bus current predicts the
// bus switch status): when it disagrees with the evidence's mean by more than `tolerance` for
// `samples` consecutive readings while the evidence agrees within itself, the sensor is the
// one that failed, not the device, and it is ignored.
struct RedundantEvidence {
  std::string sensor;
  std::vector<std::string> evidence;
  double tolerance = 0.5;
  int samples = 3;
};
class FalseSensorResponse : public FaultResponse {
 public:
  explicit FalseSensorResponse(std::vector<RedundantEvidence> rules) : rules_(std::move(rules)) {}
  std::vector<FaultAction> assess(const Observations& seen, const PlanState& plan) override;
  bool ignored(const std::string& sensor) const { return ignored_.count(sensor) > 0; }

 private:
  std::vector<RedundantEvidence> rules_;
  std::map<std::string, int> disagreeing_;
  std::map<std::string, bool> ignored_;
};

// An actuator reporting "stuck_closed" (an attitude thruster): switch its controller to a
// mode that does not use it.
struct ActuatorFallback {
  std::string actuator, control_device, fallback_mode;
};
class ActuatorStuckResponse : public FaultResponse {
 public:
  explicit ActuatorStuckResponse(std::vector<ActuatorFallback> table) : table_(std::move(table)) {}
  std::vector<FaultAction> assess(const Observations& seen, const PlanState& plan) override;

 private:
  std::vector<ActuatorFallback> table_;
  std::map<std::string, bool> switched_;
};

// A command never confirmed (the ion engine): stop commanding that device, carry on.
class UnconfirmedCommandResponse : public FaultResponse {
 public:
  std::vector<FaultAction> assess(const Observations& seen, const PlanState& plan) override;
};

// The DS1 table: every response above, in the order they are consulted.
std::vector<std::unique_ptr<FaultResponse>> ds1_fault_table(
    std::vector<RedundantEvidence> sensors, std::vector<ActuatorFallback> actuators);

}  // namespace autonomy::executive
