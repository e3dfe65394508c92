#pragma once
// C++ value types of idl/clock.idl: the simulator's clock and the lockstep handshake.
#include <cstdint>
#include <string>

namespace autonomy::msg {

enum class ClockMode { Lockstep, Paced };

struct SimClock {
  int64_t tick = 0;
  int64_t sim_time_ns = 0;
  int64_t step_ns = 0;
  ClockMode mode = ClockMode::Lockstep;
  double warp = 1.0;
  uint64_t world_id = 0;  // the simulator's random id of its world (idl/clock.idl)
};

struct LockstepRegistration {
  std::string participant;
  bool active = true;
};

struct TickAck {
  std::string participant;
  int64_t tick = 0;
  uint32_t commands_sent = 0;
  int64_t quiet_until_tick = 0;  // 0: not quiet (idl/clock.idl)
};

const char* to_string(ClockMode m);

}  // namespace autonomy::msg
