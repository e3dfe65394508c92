#include "common/service/event_loop.hpp"

#include <algorithm>

namespace autonomy::service {

namespace {
constexpr dds_attach_t kStopTag = -1;
}

EventLoop::EventLoop(const dds::Participant& participant) : waitset_(participant), stop_(participant) {
  waitset_.attach(stop_.handle(), kStopTag);
}

void EventLoop::on_condition(dds_entity_t condition, std::function<void()> handler) {
  waitset_.attach(condition, static_cast<dds_attach_t>(handlers_.size()));
  handlers_.push_back(std::move(handler));
  drainable_.push_back(false);
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

bool EventLoop::run_once(std::chrono::nanoseconds timeout) {
  const auto wait = std::min(timeout, time_to_next_timer());
  bool ran = false;
  for (dds_attach_t tag : waitset_.wait(wait)) {
    if (tag == kStopTag) continue;
    ran = true;
    struct Running {
      dds_attach_t& running;
      ~Running() { running = -1; }
    } in_handler{running_ = tag};
    handlers_[static_cast<size_t>(tag)]();
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
}

void EventLoop::run() {
  while (!stopped()) run_once(std::chrono::seconds(1));
}

}  // namespace autonomy::service
