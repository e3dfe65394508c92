#pragma once
// Blocking on DDS conditions from a thread the service owns, rather than running service logic
// inside Cyclone's listener callbacks (closing an entity while a listener runs aborts).
#include "common/dds/entity.hpp"
#include "common/dds/participant.hpp"

#include <chrono>
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

  // tag is returned by wait() when the condition triggers.
  void attach(dds_entity_t condition, dds_attach_t tag);
  void detach(dds_entity_t condition);

  // Returns the tags of triggered conditions; empty when the timeout passed first.
  std::vector<dds_attach_t> wait(std::chrono::nanoseconds timeout) const;

 private:
  Entity entity_;
  size_t attached_ = 0;
};

}  // namespace autonomy::dds
