#pragma once
// A single-threaded loop over one DDS waitset: reader data, guard conditions and periodic timers
// all run their handlers on the thread that calls run(), so service logic needs no locks.
#include "common/dds/reader.hpp"
#include "common/dds/waitset.hpp"

#include <chrono>
#include <functional>
#include <vector>

namespace autonomy::service {

class EventLoop {
 public:
  using Clock = std::chrono::steady_clock;

  explicit EventLoop(const dds::Participant& participant);

  // handler receives every sample taken from the reader since the last call.
  template <typename T>
  void on_samples(const dds::Reader<T>& reader, std::function<void(std::vector<dds::Sample<T>>)> handler) {
    const dds::Reader<T>* r = &reader;
    on_condition(reader.data_condition(), [r, handler = std::move(handler)] { handler(r->take()); });
  }

  // handler runs whenever the condition triggers; it must clear the condition (take, reset).
  void on_condition(dds_entity_t condition, std::function<void()> handler);

  // handler runs every period (first time one period from now); a late timer runs once, not in
  // a burst.
  void every(std::chrono::nanoseconds period, std::function<void()> handler);

  // Thread-safe: ends run() after the handler in progress.
  void stop() const { stop_.trigger(); }
  bool stopped() const { return stop_.triggered(); }

  // Runs handlers until stop().
  void run();
  // One round: waits up to timeout for something to do, runs what is due. For tests and benches.
  void run_once(std::chrono::nanoseconds timeout);

 private:
  struct Timer {
    std::chrono::nanoseconds period;
    Clock::time_point due;
    std::function<void()> handler;
  };

  void run_due_timers();
  std::chrono::nanoseconds time_to_next_timer() const;

  dds::WaitSet waitset_;
  dds::GuardCondition stop_;
  std::vector<std::function<void()>> handlers_;  // index = attach tag
  std::vector<Timer> timers_;
};

}  // namespace autonomy::service
