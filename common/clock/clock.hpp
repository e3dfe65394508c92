#pragma once
// One clock interface for every service: wall time in real deployments, the simulator's
// published time otherwise. Cores never read a clock: nodes read one and pass time inward.
#include <atomic>
#include <cstdint>

namespace autonomy::clock {

class Clock {
 public:
  virtual ~Clock() = default;
  // Nanoseconds since this clock's epoch (Unix epoch for wall time, run start for simulated).
  virtual int64_t now_ns() const = 0;
  // False until the clock can tell time (a simulated clock before the first tick arrives).
  virtual bool running() const = 0;
  double now_s() const { return static_cast<double>(now_ns()) * 1e-9; }
};

class WallClock final : public Clock {
 public:
  int64_t now_ns() const override;
  bool running() const override { return true; }
};

// Time as the simulator last published it. Written by the thread that receives autonomy/clock,
// readable from any thread.
class SimulatedClock final : public Clock {
 public:
  void advance(int64_t tick, int64_t sim_time_ns);
  int64_t now_ns() const override { return sim_time_ns_.load(std::memory_order_acquire); }
  bool running() const override { return tick_.load(std::memory_order_acquire) >= 0; }
  int64_t tick() const { return tick_.load(std::memory_order_acquire); }

 private:
  std::atomic<int64_t> tick_{-1};
  std::atomic<int64_t> sim_time_ns_{0};
};

}  // namespace autonomy::clock
