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
    drainable_.back() = true;
  }

  // handler runs whenever the condition triggers; it must clear the condition (take, reset).
  void on_condition(dds_entity_t condition, std::function<void()> handler);

  // handler runs every period (first time one period from now); a late timer runs once, not in
  // a burst.
  void every(std::chrono::nanoseconds period, std::function<void()> handler);

  // Runs now the handler of every reader (on_samples) that has samples, except the handler that is
  // running (it took its samples already); timers and guard conditions wait for their round.
  // For lockstep: what a participant wrote before its tick ack (or the simulator before its clock
  // tick) has arrived when the ack has (one socket, delivered in order), but it may still sit in
  // its reader, after the ack's reader in the waitset's order. A node that drains before it acts
  // on a tick acts on everything sent for that tick, whatever order the waitset reported the
  // readers in: the run is deterministic. Handlers run by drain() that would act on a tick
  // should check draining() and leave it to the caller, which looks again after drain().
  // Nested calls do nothing.
  void drain();
  bool draining() const { return draining_; }

  // Thread-safe: ends run() after the handler in progress.
  void stop() const { stop_.trigger(); }
  bool stopped() const { return stop_.triggered(); }

  // Runs handlers until stop().
  void run();
  // One round: waits up to timeout for something to do, runs what is due. For tests, benches and
  // hosts that run several loops on one thread (tools/experiments/runner/trial_host.cpp). Returns
  // whether a reader's or condition's handler ran (timers do not count).
  bool run_once(std::chrono::nanoseconds timeout);

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
  std::vector<bool> drainable_;                   // index = attach tag: a reader's handler
  dds_attach_t running_ = -1;                     // the handler run_once() is in, -1: none
  bool draining_ = false;
  std::vector<Timer> timers_;
};

}  // namespace autonomy::service
