#pragma once
// C++ value types of idl/spacecraft.idl: device commands, their status, telemetry, faults.
#include <cstdint>
#include <string>
#include <vector>

namespace autonomy::msg {

struct SpacecraftCommand {
  std::string command_id;
  std::string source;
  int64_t tick = 0;
  std::string device;
  std::string command;
  std::vector<std::string> arguments;
};

struct SpacecraftCommandStatus {
  std::string command_id;
  std::string source;
  std::string device;
  std::string command;
  bool accepted = false;
  std::string reason;
  int64_t tick = 0;
  int64_t sim_time_ns = 0;
  bool busy = false;
};

struct DeviceReport {
  std::string device;
  std::string mode;
  std::string confirmed_command;
  std::string confirmed_command_id;
  int64_t confirmed_tick = -1;
};

struct SensorReading {
  std::string sensor;
  double value = 0.0;
};

struct AttitudeTelemetry {
  double qw = 1.0, qx = 0.0, qy = 0.0, qz = 0.0;
  std::string pointing_target;
  std::string turn_target;
  std::string control_mode;
  double rate_deg_s = 0.0;
  double remaining_deg = 0.0;
};

struct PropulsionTelemetry {
  uint32_t thrust_level = 0;
  double power_w = 0.0;
  double thrust_time_s = 0.0;
};

struct CameraTelemetry {
  double power_w = 0.0;
  uint32_t images_taken = 0;
  uint32_t images_on_target = 0;
  std::string last_image_target;
};

struct PowerTelemetry {
  double solar_array_w = 0.0;
  double load_w = 0.0;
  double battery_soc = 0.0;
  double battery_wh = 0.0;
};

struct TelecomTelemetry {
  std::string ground_station;
  double downlink_rate_kbps = 0.0;
  double downlinked_mb = 0.0;
};

struct StorageTelemetry {
  double used_mb = 0.0;
  double capacity_mb = 0.0;
};

struct FaultProtectionTelemetry {
  bool safe_mode = false;
  std::string reason;
  int64_t safed_at_ns = 0;
  uint32_t safings = 0;
  double commander_silent_s = 0.0;
  double commander_timeout_s = 0.0;
};

struct SpacecraftTelemetry {
  std::string spacecraft;
  int64_t tick = 0;
  int64_t sim_time_ns = 0;
  std::vector<DeviceReport> devices;
  std::vector<SensorReading> readings;
  AttitudeTelemetry attitude;
  PropulsionTelemetry propulsion;
  CameraTelemetry camera;
  PowerTelemetry power;
  TelecomTelemetry telecom;
  StorageTelemetry storage;
  uint64_t commands_accepted = 0;
  uint64_t commands_rejected = 0;
  FaultProtectionTelemetry fault_protection;
  uint64_t commands_busy = 0;
};

struct SpacecraftEvent {
  std::string spacecraft;
  int64_t tick = 0;
  int64_t sim_time_ns = 0;
  std::string kind;
  std::string detail;
};

struct SpacecraftFaultInjection {
  std::string fault_id;
  std::string source;
  std::string kind;
  std::string subject;
  double value = 0.0;
  bool reset_cures = true;
  bool clear = false;
};

struct SpacecraftFaultState {
  std::string fault_id;
  std::string kind;
  std::string subject;
  double value = 0.0;
  bool active = false;
  std::string trigger;
  std::string ended_by;
  int64_t since_ns = 0;
};

}  // namespace autonomy::msg
