#pragma once
// SIGINT and SIGTERM become an ordinary callback on a thread of our own. The signals are blocked
// in every thread (the mask is inherited, so construct this first in main, before DDS starts its
// threads) and collected with sigwait, because almost nothing DDS offers is async-signal-safe.
#include <atomic>
#include <functional>
#include <mutex>
#include <pthread.h>
#include <thread>

namespace autonomy::service {

class ShutdownSignals {
 public:
  ShutdownSignals();
  ~ShutdownSignals();
  ShutdownSignals(const ShutdownSignals&) = delete;
  ShutdownSignals& operator=(const ShutdownSignals&) = delete;

  // Called once, on the signal thread, for the first SIGINT/SIGTERM. Set before signals matter.
  void on_shutdown(std::function<void(int signal)> callback);
  bool requested() const { return requested_.load(); }

 private:
  void wait_for_signal();

  std::mutex mutex_;  // guards callback_ and pending_signal_
  std::function<void(int)> callback_;
  int pending_signal_ = 0;  // a signal that came before the callback was set
  std::atomic<bool> requested_{false};
  std::atomic<bool> closing_{false};
  std::thread thread_;
};

}  // namespace autonomy::service
