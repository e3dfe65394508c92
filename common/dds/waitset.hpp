#pragma once
// Blocking on DDS conditions from a thread the service owns, rather than running service logic
// inside Cyclone's listener callbacks (closing an entity while a listener runs aborts). The one
// exception, for short lockstep handlers, is EventLoop::on_samples_at_arrival: its handlers never
// close their own reader, and none runs once the loop's run() has ended.
#include "common/dds/entity.hpp"
#include "common/dds/participant.hpp"

#include <atomic>
#include <chrono>
#include <utility>
#include <vector>

namespace autonomy::dds {

// A condition the program triggers itself: shutdown requests, wake-ups from other threads.
class GuardCondition {
 public:
  explicit GuardCondition(const Participant& participant);
  void trigger() const;
  void reset() const;
  bool triggered() const;
  dds_entity_t handle() const { return entity_.handle(); }

 private:
  Entity entity_;
};

class WaitSet {
 public:
  explicit WaitSet(const Participant& participant);

  // tag is returned by wait() when the condition triggers. attach/detach may run while another
  // thread is in wait() (not in triggered_now()).
  void attach(dds_entity_t condition, dds_attach_t tag);
  void detach(dds_entity_t condition);

  // Returns the tags of triggered conditions; empty when the timeout passed first. A zero (or
  // negative) timeout asks which are triggered now, without waiting: see triggered_now().
  std::vector<dds_attach_t> wait(std::chrono::nanoseconds timeout) const;

 private:
  // The attached conditions that dds_triggered() reports triggered, in attach order. For a zero
  // timeout dds_waitset_wait would ask with a timed condition wait whose deadline has passed: a
  // futex call that sleeps until the next timer interrupt, a context switch each time, and a
  // lockstep node asks several times a tick (EventLoop::drain). The waitset triggers on exactly
  // what dds_triggered() reports (dds.h, dds_waitset_attach).
  std::vector<dds_attach_t> triggered_now() const;

  Entity entity_;
  std::vector<std::pair<dds_entity_t, dds_attach_t>> attached_;  // condition, tag
  // attached_.size() for wait(): a handler running in a receive thread (EventLoop) may attach
  // while the loop's thread waits.
  std::atomic<size_t> attached_count_{0};
};

}  // namespace autonomy::dds
