#pragma once
// A loop over one DDS waitset: reader data, guard conditions and periodic timers run their
// handlers one at a time, so service logic needs no locks. They run on the thread that calls
// run(), except the handlers of on_samples_at_arrival, which a standalone process lets run in the
// DDS receive thread that delivered the sample (under the loop's lock, never beside another).
#include "common/dds/reader.hpp"
#include "common/dds/waitset.hpp"

#include <atomic>
#include <chrono>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace autonomy::service {

class EventLoop {
 public:
  using Clock = std::chrono::steady_clock;

  explicit EventLoop(const dds::Participant& participant);
  // Removes the receive-thread listeners of readers still alive: none runs a handler after this.
  ~EventLoop();
  EventLoop(const EventLoop&) = delete;
  EventLoop& operator=(const EventLoop&) = delete;

  // handler receives every sample taken from the reader since the last call.
  template <typename T>
  void on_samples(const dds::Reader<T>& reader, std::function<void(std::vector<dds::Sample<T>>)> handler) {
    const dds::Reader<T>* r = &reader;
    on_condition(reader.data_condition(), [r, handler = std::move(handler)] { handler(r->take()); });
    drainable_.back() = true;
  }

  // Like on_samples, but once allow_handling_at_arrival() was called the handler runs as soon as
  // a sample arrives, in the thread that delivered it (Cyclone's receive thread, through a
  // data-available listener), instead of waking the loop's thread for it: a lockstep tick then
  // costs one thread wake-up less in every process (docs/scale.md, "Lockstep ticks/s"). The
  // receive thread runs the handler only when it gets the loop's lock at once and run() is on;
  // otherwise (the loop's thread is in a handler or a timer, the sample was written by a handler
  // of this loop, the loop has not started) a guard condition hands the samples to the loop's
  // thread, as on_samples does. A handler that throws there ends run(), which rethrows.
  // The receive thread is blocked while the handler runs: only for short handlers.
  template <typename T>
  void on_samples_at_arrival(const dds::Reader<T>& reader, std::function<void(std::vector<dds::Sample<T>>)> handler) {
    if (!at_arrival_allowed_) {
      on_samples(reader, std::move(handler));
      return;
    }
    const dds::Reader<T>* r = &reader;
    add_at_arrival(reader.handle(), reader.data_condition(), [r, handler = std::move(handler)] {
      std::vector<dds::Sample<T>> samples = r->take();
      if (!samples.empty()) handler(std::move(samples));  // another thread's round took them first
    });
  }
  // For processes whose loop is the only one on its thread (run_service). Hosts that run several
  // loops on one thread (a handler's write is delivered in the writing thread, which would run
  // another loop's handler inside it) and tests leave it off. Call before registering handlers.
  void allow_handling_at_arrival() { at_arrival_allowed_ = true; }
  // Whether the handler running now runs in a receive thread (one of on_samples_at_arrival, or
  // one that a drain() in it runs): such a handler should leave long or heavy work (large bursts
  // of writes) to the loop's thread.
  bool in_receive_thread() const { return in_receive_thread_; }

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

  struct AtArrival;  // a reader whose handler may run in the receive thread
  // Holds the loop's lock on this thread (adopting it when already taken with try_lock).
  class Holding {
   public:
    explicit Holding(EventLoop& loop);
    Holding(EventLoop& loop, std::adopt_lock_t);
    ~Holding();
    Holding(const Holding&) = delete;
    Holding& operator=(const Holding&) = delete;

   private:
    EventLoop& loop_;
  };

  void run_due_timers();
  std::chrono::nanoseconds time_to_next_timer() const;
  void run_handler(dds_attach_t tag);
  void add_at_arrival(dds_entity_t reader, dds_entity_t data_condition, std::function<void()> take_and_handle);
  static void on_data_available(dds_entity_t reader, void* arg);
  void handle_at_arrival(AtArrival& a);

  const dds::Participant& participant_;  // outlives the loop (Service)

  dds::WaitSet waitset_;
  dds::GuardCondition stop_;
  std::vector<std::function<void()>> handlers_;  // index = attach tag
  std::vector<bool> drainable_;                   // index = attach tag: a reader's handler
  dds_attach_t running_ = -1;                     // the handler run_once() is in, -1: none
  bool draining_ = false;
  std::vector<Timer> timers_;

  // Handlers and timers run under mutex_, by the loop's thread or a receive thread.
  std::mutex mutex_;
  std::atomic<std::thread::id> holder_{};  // the thread holding mutex_, or none
  bool running_loop_ = false;              // run() is on: a receive thread may run handlers
  bool in_receive_thread_ = false;         // a receive thread runs the handler in progress
  bool at_arrival_allowed_ = false;
  std::exception_ptr failure_;  // what a handler threw in a receive thread; run() rethrows it
  std::vector<std::unique_ptr<AtArrival>> at_arrival_;
};

}  // namespace autonomy::service
