#pragma once
// Dispatch must never stall (on 18 May 1999 a race left the Remote Agent's executive waiting
// and the engine thrusting). The event loop marks each tick it starts and ends; this thread
// checks that a tick in progress ends within `limit`. When it does not, `on_stall` runs once
// on this thread (it must only write DDS samples: writers are thread-safe, no locks are held)
// and `on_recover` when ticks end again.
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <thread>

namespace autonomy::executive {

class Watchdog {
 public:
  using Clock = std::chrono::steady_clock;

  Watchdog(Clock::duration limit, std::function<void(Clock::duration)> on_stall,
           std::function<void()> on_recover);
  ~Watchdog();
  Watchdog(const Watchdog&) = delete;
  Watchdog& operator=(const Watchdog&) = delete;

  void tick_started() { busy_since_ns_.store(now_ns(), std::memory_order_release); }
  void tick_ended() { busy_since_ns_.store(0, std::memory_order_release); }
  bool alarmed() const { return alarmed_.load(); }

 private:
  static std::int64_t now_ns() {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now().time_since_epoch()).count();
  }
  void watch();

  Clock::duration limit_;
  std::function<void(Clock::duration)> on_stall_;
  std::function<void()> on_recover_;
  std::atomic<std::int64_t> busy_since_ns_{0};
  std::atomic<bool> alarmed_{false};
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  std::thread thread_;
};

}  // namespace autonomy::executive
