#pragma once
// C++ value types of idl/system.idl. Services use these; the generated C types stay in common/dds.
#include <cstdint>
#include <string>
#include <vector>

namespace autonomy::msg {

enum class ServiceState { Starting, Ready, Stopping };

struct Heartbeat {
  std::string service;
  std::string instance;
  std::string host;
  int32_t pid = 0;
  ServiceState state = ServiceState::Starting;
  double uptime_s = 0.0;
  uint32_t period_ms = 0;
  std::vector<std::string> capabilities;  // "courier", ...
  uint64_t world_id = 0;  // the world whose clock it follows; 0: none yet
  uint64_t clock_samples_ignored = 0;
  std::string detail;     // e.g. the simulator's scenario file
};

const char* to_string(ServiceState s);

}  // namespace autonomy::msg
