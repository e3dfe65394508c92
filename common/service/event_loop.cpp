#include "common/service/event_loop.hpp"

#include "common/dds/error.hpp"

#include <algorithm>

namespace autonomy::service {

namespace {
constexpr dds_attach_t kStopTag = -1;
}

// The loop's thread handles the samples when the receive thread cannot: `pending` is attached
// to the waitset with the handler's tag.
struct EventLoop::AtArrival {
  EventLoop* loop;
  dds_attach_t tag;
  dds_entity_t reader;
  dds_entity_t data_condition;
  dds::GuardCondition pending;
};

EventLoop::Holding::Holding(EventLoop& loop) : loop_(loop) {
  loop_.mutex_.lock();
  loop_.holder_.store(std::this_thread::get_id());
}

EventLoop::Holding::Holding(EventLoop& loop, std::adopt_lock_t) : loop_(loop) {
  loop_.holder_.store(std::this_thread::get_id());
}

EventLoop::Holding::~Holding() {
  loop_.holder_.store(std::thread::id());
  loop_.mutex_.unlock();
}

EventLoop::EventLoop(const dds::Participant& participant)
    : participant_(participant), waitset_(participant), stop_(participant) {
  waitset_.attach(stop_.handle(), kStopTag);
}

EventLoop::~EventLoop() {
  // dds_set_listener waits for a callback in progress; a reader deleted already answers with an
  // error, harmlessly.
  for (const auto& a : at_arrival_) (void)dds_set_listener(a->reader, nullptr);
}

void EventLoop::on_condition(dds_entity_t condition, std::function<void()> handler) {
  waitset_.attach(condition, static_cast<dds_attach_t>(handlers_.size()));
  handlers_.push_back(std::move(handler));
  drainable_.push_back(false);
}

void EventLoop::add_at_arrival(dds_entity_t reader, dds_entity_t data_condition, std::function<void()> take_and_handle) {
  const auto tag = static_cast<dds_attach_t>(handlers_.size());
  auto a = std::make_unique<AtArrival>(AtArrival{this, tag, reader, data_condition, dds::GuardCondition(participant_)});
  AtArrival* raw = a.get();
  on_condition(raw->pending.handle(), [raw, take_and_handle = std::move(take_and_handle)] {
    raw->pending.reset();  // before the take: a sample that comes during it triggers it again
    take_and_handle();
  });
  drainable_.back() = true;
  at_arrival_.push_back(std::move(a));
  dds_listener_t* listener = dds_create_listener(raw);
  dds_lset_data_available(listener, &EventLoop::on_data_available);
  const dds_return_t rc = dds_set_listener(reader, listener);
  dds_delete_listener(listener);
  dds::check(rc, "dds_set_listener");
  // What arrived before the listener was set called nobody.
  if (dds_triggered(data_condition) > 0) raw->pending.trigger();
}

void EventLoop::on_data_available(dds_entity_t /*reader*/, void* arg) {
  auto* a = static_cast<AtArrival*>(arg);
  a->loop->handle_at_arrival(*a);
}

void EventLoop::handle_at_arrival(AtArrival& a) {
  // This thread holds the lock already (a handler of this loop wrote what is delivered here), or
  // another thread runs a handler or a timer: the loop's thread takes the samples.
  if (holder_.load() == std::this_thread::get_id() || !mutex_.try_lock()) {
    a.pending.trigger();
    return;
  }
  Holding holding(*this, std::adopt_lock);
  if (!running_loop_) {
    a.pending.trigger();
    return;
  }
  in_receive_thread_ = true;
  try {
    run_handler(a.tag);
    in_receive_thread_ = false;
  } catch (...) {
    in_receive_thread_ = false;
    // An exception must not unwind into Cyclone's C code: run() ends and rethrows it.
    if (!failure_) failure_ = std::current_exception();
    stop();
  }
}

void EventLoop::every(std::chrono::nanoseconds period, std::function<void()> handler) {
  timers_.push_back({period, Clock::now() + period, std::move(handler)});
}

std::chrono::nanoseconds EventLoop::time_to_next_timer() const {
  auto wait = std::chrono::nanoseconds(std::chrono::seconds(1));
  const auto now = Clock::now();
  for (const auto& t : timers_) wait = std::min(wait, std::max<std::chrono::nanoseconds>(t.due - now, {}));
  return wait;
}

void EventLoop::run_due_timers() {
  const auto now = Clock::now();
  for (auto& t : timers_) {
    if (t.due > now) continue;
    // Next due time on the timer's own phase, after now: missed periods are skipped, so a late
    // timer runs once (due = now would run it again at once, a burst of two).
    t.due += t.period;
    if (t.due <= now) t.due += ((now - t.due) / t.period + 1) * t.period;
    t.handler();
  }
}

void EventLoop::run_handler(dds_attach_t tag) {
  struct Running {
    dds_attach_t& running;
    ~Running() { running = -1; }
  } in_handler{running_ = tag};
  handlers_[static_cast<size_t>(tag)]();
}

bool EventLoop::run_once(std::chrono::nanoseconds timeout) {
  std::chrono::nanoseconds wait;
  {
    Holding holding(*this);  // a handler in a receive thread may add a timer
    wait = std::min(timeout, time_to_next_timer());
  }
  std::vector<dds_attach_t> tags;
  if (wait > std::chrono::nanoseconds(0)) tags = waitset_.wait(wait);
  Holding holding(*this);
  // Asking without waiting reads the attached conditions, which a handler in a receive thread may
  // add to: under the lock.
  if (wait <= std::chrono::nanoseconds(0)) tags = waitset_.wait(wait);
  bool ran = false;
  for (dds_attach_t tag : tags) {
    if (tag == kStopTag) continue;
    ran = true;
    run_handler(tag);
  }
  run_due_timers();
  return ran;
}

void EventLoop::drain() {
  if (draining_) return;
  draining_ = true;
  struct EndDrain {
    bool& flag;
    ~EndDrain() { flag = false; }
  } end{draining_};
  for (dds_attach_t tag : waitset_.wait(std::chrono::nanoseconds(0))) {
    if (tag == kStopTag || tag == running_ || !drainable_[static_cast<size_t>(tag)]) continue;
    handlers_[static_cast<size_t>(tag)]();
  }
  // Samples whose listener has not run yet (it will find them taken).
  for (const auto& a : at_arrival_)
    if (a->tag != running_ && dds_triggered(a->data_condition) > 0) handlers_[static_cast<size_t>(a->tag)]();
}

void EventLoop::run() {
  {
    Holding holding(*this);
    running_loop_ = true;
  }
  struct Off {
    EventLoop& loop;
    ~Off() {
      Holding holding(loop);  // waits for a handler in a receive thread to end
      loop.running_loop_ = false;
    }
  } off{*this};
  while (!stopped()) run_once(std::chrono::seconds(1));
  std::exception_ptr failure;
  {
    Holding holding(*this);
    failure = failure_;
  }
  if (failure) std::rethrow_exception(failure);
}

}  // namespace autonomy::service
