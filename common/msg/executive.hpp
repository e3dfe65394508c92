#pragma once
// C++ value types of idl/executive.idl: the executive's events and status.
#include <cstdint>
#include <string>
#include <vector>

namespace autonomy::msg {

struct ExecutiveEvent {
  std::string executive;
  uint64_t number = 0;
  int64_t tick = 0;
  int64_t sim_time_ns = 0;
  std::string kind;
  std::string text;
  std::string plan_id;
};

struct ExecutiveStatus {
  std::string executive;
  std::string state;
  std::string plan_id;
  int64_t tick = 0;
  int64_t plan_origin_s = 0;
  int64_t horizon_end_s = 0;
  std::vector<std::string> executing;
  std::vector<std::string> goals_achieved;
  std::vector<std::string> goals_lost;
  std::vector<std::string> disabled_devices;
  std::vector<std::string> ignored_sensors;
  uint32_t replans = 0;
  uint32_t horizons = 0;
  double decision_us_mean = 0;
  double decision_us_max = 0;
  bool watchdog_alarm = false;
};

}  // namespace autonomy::msg
