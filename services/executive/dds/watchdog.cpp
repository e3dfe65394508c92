#include "watchdog.hpp"

namespace autonomy::executive {

Watchdog::Watchdog(Clock::duration limit, std::function<void(Clock::duration)> on_stall,
                   std::function<void()> on_recover)
    : limit_(limit), on_stall_(std::move(on_stall)), on_recover_(std::move(on_recover)) {
  thread_ = std::thread([this] { watch(); });
}

Watchdog::~Watchdog() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void Watchdog::watch() {
  const auto period = std::max<Clock::duration>(limit_ / 4, std::chrono::milliseconds(5));
  std::unique_lock<std::mutex> lock(mutex_);
  while (!wake_.wait_for(lock, period, [this] { return stopping_; })) {
    const std::int64_t since = busy_since_ns_.load(std::memory_order_acquire);
    const auto busy = std::chrono::nanoseconds(since == 0 ? 0 : now_ns() - since);
    if (since != 0 && busy > limit_ && !alarmed_.exchange(true)) {
      lock.unlock();  // the callbacks write DDS samples: no lock held across them
      on_stall_(busy);
      lock.lock();
    } else if (since == 0 && alarmed_.exchange(false)) {
      lock.unlock();
      on_recover_();
      lock.lock();
    }
  }
}

}  // namespace autonomy::executive
