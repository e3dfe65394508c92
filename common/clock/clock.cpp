#include "common/clock/clock.hpp"

#include <chrono>

namespace autonomy::clock {

int64_t WallClock::now_ns() const {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

void SimulatedClock::advance(int64_t tick, int64_t sim_time_ns) {
  // Time never runs backwards for a reader: a stale or duplicate sample is ignored.
  if (tick <= tick_.load(std::memory_order_acquire)) return;
  sim_time_ns_.store(sim_time_ns, std::memory_order_release);
  tick_.store(tick, std::memory_order_release);
}

}  // namespace autonomy::clock
