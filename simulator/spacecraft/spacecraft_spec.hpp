#pragma once
// Everything a Spacecraft needs to start, as plain values: its targets, subsystems, ground-station
// windows and scheduled faults. Built and checked at the edge (simulator/scenario reads the
// `spacecraft` section of a scenario file); the Spacecraft re-checks only what it relies on.
// Units: seconds, watts, watt-hours, megabytes, kilobits per second, degrees.
#include <Eigen/Core>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace autonomy::sim::spacecraft {

// A thing to point the camera at (a star, an asteroid): a direction in the inertial frame.
struct TargetSpec {
  std::string name;
  Eigen::Vector3d direction{0, 0, 1};  // any non-zero length; normalised by the Spacecraft
};

// An attitude control mode: the actuators it fires and how fast it turns the spacecraft.
struct ControlModeSpec {
  std::string name;                    // e.g. "thrusters", "wheels_and_other_thrusters"
  std::vector<std::string> actuators;  // thruster names of AttitudeSpec::thrusters
  double max_rate_deg_s = 0.1;         // > 0
};

// Attitude control ("adcs"): the camera boresight is the body +z axis.
struct AttitudeSpec {
  std::string initial_target;          // pointed at when the run starts
  std::string control_mode;            // initial, one of modes
  std::vector<std::string> thrusters;  // each is a device reporting "ok" / "stuck_closed"
  std::vector<ControlModeSpec> modes;
  double pointing_tolerance_deg = 0.5;  // an image is on target when the error is below this
};

// Ion propulsion ("ips"): standby or thrusting at a level 1..max_level whose power draw is
// linear between min_power_w (level 1) and max_power_w (max_level).
struct IonEngineSpec {
  int max_level = 10;
  double min_power_w = 500;
  double max_power_w = 2500;
};

struct CameraSpec {
  std::string initial_mode = "ready";  // "off" or "ready"
  double ready_power_w = 10;
  double imaging_power_w = 20;
  double exposure_s = 10;  // imaging time of one picture
  double image_mb = 1.0;   // stored when the exposure ends
};

// A switch on the power bus that feeds one device. Its status sensor and its two downstream
// voltage sensors are telemetry readings (see spacecraft.hpp).
struct BusSwitchSpec {
  std::string name;
  std::string device;  // a switchable device: "camera", "ips" or "telecom"
  bool closed = true;
};

struct PowerSpec {
  double solar_array_w = 2500;
  double battery_capacity_wh = 1000;
  double battery_soc = 1.0;      // initial state of charge, 0..1
  double base_load_w = 300;      // everything not modelled as a device
  double max_discharge_w = 500;  // the battery's help to a load the array cannot carry
  std::vector<BusSwitchSpec> switches;
};

// A pass over a ground station: downlink is possible in [start_s, end_s).
struct StationWindowSpec {
  std::string station;
  double start_s = 0;
  double end_s = 0;
  double rate_kbps = 10;
};

struct TelecomSpec {
  double transmit_power_w = 100;           // drawn while downlinking
  std::vector<StationWindowSpec> windows;  // sorted by start, not overlapping
};

struct StorageSpec {
  double capacity_mb = 100;
  double used_mb = 0;
};

// An electronics unit (DS1's low-power electronics, "lpe") that commands to some devices pass
// through: while it has failed, those commands are rejected.
struct ElectronicsSpec {
  std::string name;
  std::vector<std::string> devices;
};

enum class FaultKind {
  StuckOn,         // a camera or ion engine, once on (imaging / thrusting), stays on
  Failed,          // the device reports "failed" and rejects commands until a reset cures it
  FalseSensor,     // one reading shows `value` while every other reading stays true
  StuckClosed,     // a thruster: control modes that use it cannot turn the spacecraft
  NeverConfirmed,  // commands to the device are accepted, never executed, never confirmed
};
const char* to_string(FaultKind kind);
std::optional<FaultKind> fault_kind_from_string(const std::string& text);

// A fault: at a time, on the first accepted command "device command", or at once (injected).
struct FaultSpec {
  std::string id;
  FaultKind kind = FaultKind::Failed;
  std::string subject;      // a device, or a reading for FalseSensor
  double value = 0;         // FalseSensor: what the sensor reads
  bool reset_cures = true;  // Failed: a reset clears it
  std::optional<double> at_s;
  std::string on_command;  // "ips thrust"; empty: not on an event
};

// Fault protection: safe the spacecraft when its commander has been silent this long (simulated
// seconds; 0: never). Signs of the commander reach the Spacecraft as commander_heard() calls
// (the node decides what counts: heartbeats, lockstep acks) and as submitted commands.
struct FaultProtectionSpec {
  double commander_timeout_s = 600;
  std::string commander = "executive";  // the service whose heartbeats count
};

struct SpacecraftSpec {
  std::string name = "spacecraft";
  std::vector<TargetSpec> targets;
  AttitudeSpec attitude;
  IonEngineSpec ion_engine;
  CameraSpec camera;
  PowerSpec power;
  TelecomSpec telecom;
  StorageSpec storage;
  std::vector<ElectronicsSpec> electronics;
  std::vector<FaultSpec> faults;
  FaultProtectionSpec fault_protection;
  // Commands waiting for their step (in the node), at most; more are answered "busy".
  std::size_t command_queue_limit = 1000;
};

}  // namespace autonomy::sim::spacecraft
