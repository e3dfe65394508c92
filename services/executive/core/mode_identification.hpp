#pragma once
// Mode identification in the manner of the Remote Agent's MIR (Livingstone): components with
// modes, each mode predicting some of the telemetry; the identified state is the assignment of
// modes that explains the readings at the least cost. A reading no mode explains is charged as
// a false sensor, so one disagreeing sensor against several agreeing readings is judged false,
// while several readings that agree on a failure are judged a failed device.
//
// Costs stand for unlikeliness (think -log probability): a component in the mode the plan
// commanded costs nothing, another nominal mode costs `unexpected_mode_cost` (a command not
// taken), a fault mode its own cost, a reading judged false `false_sensor_cost`.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "fault_responses.hpp"

namespace autonomy::executive {

// A numeric reading the mode predicts (bus current 1.2 A +- 0.3).
struct Prediction {
  std::string observable;
  double value = 0;
  double tolerance = 0;
};

struct ModeModel {
  std::string name;
  bool fault = false;
  double cost = 0;                      // for fault modes; nominal modes cost by expectation
  std::string reports;                  // the mode the device reports in it ("" = none)
  std::vector<Prediction> predictions;  // numeric readings
};

// A component that needs another in some modes (the camera needs its bus on): while the
// other is in none of them, the component can only be in `otherwise`, at no cost (an
// unpowered camera is off because of the bus, not because of a second fault).
struct Dependency {
  std::string component;
  std::vector<std::string> modes;
  std::string otherwise;
};

struct ComponentModel {
  std::string name;  // the device name of its mode reports (Observations::device_modes)
  std::vector<ModeModel> modes;
  std::vector<Dependency> depends_on;
};

struct Diagnosis {
  std::map<std::string, std::string> modes;  // component -> identified mode
  std::vector<std::string> faults;           // "component=mode" for fault modes, in model order
  std::vector<std::string> false_sensors;    // readings (or "mode:<device>" reports) judged false
  double cost = 0;
  bool ambiguous = false;  // another assignment explains the readings at the same cost
  std::size_t assignments_tried = 0;
};

struct ModeCosts {
  double unexpected_mode = 2.0;
  double false_sensor = 1.0;
};

class ModeIdentifier {
 public:
  // Components are ordered so that every dependency comes before its dependants; a model
  // that names an unknown component or mode, or depends in a cycle, is rejected (`error`).
  static std::optional<ModeIdentifier> create(std::vector<ComponentModel> components,
                                              ModeCosts costs, std::string* error);

  // `expected`: component -> the mode the plan commanded (components not named may be in
  // any nominal mode at no cost). Readings and reports absent this tick predict nothing.
  Diagnosis identify(const std::map<std::string, std::string>& expected,
                     const Observations& seen) const;

  const std::vector<ComponentModel>& components() const { return components_; }

 private:
  ModeIdentifier(std::vector<ComponentModel> components, ModeCosts costs)
      : components_(std::move(components)), costs_(costs) {}
  std::vector<ComponentModel> components_;
  ModeCosts costs_;
};

// The fault response built on it: the diagnosis, once the same for `samples` ticks in a row
// and not ambiguous, becomes actions: a reading judged false is ignored; a component in a
// fault mode gets the action its (component, mode) entry in the table names.
struct ModeResponseRule {
  std::string component, mode;
  FaultAction::Kind action = FaultAction::Kind::kAbortAndReplan;
  std::string control_device, control_mode;  // for kSwitchControlMode
};

class ModeIdentificationResponse : public FaultResponse {
 public:
  ModeIdentificationResponse(ModeIdentifier identifier, std::vector<ModeResponseRule> rules,
                             int samples = 2)
      : identifier_(std::move(identifier)), rules_(std::move(rules)), samples_(samples) {}
  std::vector<FaultAction> assess(const Observations& seen, const PlanState& plan) override;
  const Diagnosis& last() const { return last_; }

 private:
  ModeIdentifier identifier_;
  std::vector<ModeResponseRule> rules_;
  int samples_;
  Diagnosis last_;
  int same_for_ = 0;
  std::map<std::string, bool> acted_;  // "sensor:x" / "component=mode" already answered
};

}  // namespace autonomy::executive
