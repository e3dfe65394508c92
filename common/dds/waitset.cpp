#include "common/dds/waitset.hpp"

#include "common/dds/error.hpp"

#include <algorithm>

namespace autonomy::dds {

GuardCondition::GuardCondition(const Participant& participant)
    : entity_(check(dds_create_guardcondition(participant.handle()), "dds_create_guardcondition")) {}

void GuardCondition::trigger() const { check(dds_set_guardcondition(entity_.handle(), true), "dds_set_guardcondition"); }

void GuardCondition::reset() const { check(dds_set_guardcondition(entity_.handle(), false), "dds_set_guardcondition"); }

bool GuardCondition::triggered() const {
  bool value = false;
  check(dds_read_guardcondition(entity_.handle(), &value), "dds_read_guardcondition");
  return value;
}

WaitSet::WaitSet(const Participant& participant)
    : entity_(check(dds_create_waitset(participant.handle()), "dds_create_waitset")) {}

void WaitSet::attach(dds_entity_t condition, dds_attach_t tag) {
  check(dds_waitset_attach(entity_.handle(), condition, tag), "dds_waitset_attach");
  attached_.emplace_back(condition, tag);
  attached_count_.store(attached_.size());
}

void WaitSet::detach(dds_entity_t condition) {
  check(dds_waitset_detach(entity_.handle(), condition), "dds_waitset_detach");
  attached_.erase(std::remove_if(attached_.begin(), attached_.end(),
                                 [condition](const auto& a) { return a.first == condition; }),
                  attached_.end());
  attached_count_.store(attached_.size());
}

std::vector<dds_attach_t> WaitSet::wait(std::chrono::nanoseconds timeout) const {
  if (timeout <= std::chrono::nanoseconds(0)) return triggered_now();
  const size_t attached = attached_count_.load();
  std::vector<dds_attach_t> triggered(attached == 0 ? 1 : attached);
  const dds_return_t n = check(
      dds_waitset_wait(entity_.handle(), triggered.data(), triggered.size(), timeout.count()), "dds_waitset_wait");
  triggered.resize(static_cast<size_t>(n) < triggered.size() ? static_cast<size_t>(n) : triggered.size());
  return triggered;
}

std::vector<dds_attach_t> WaitSet::triggered_now() const {
  std::vector<dds_attach_t> triggered;
  for (const auto& [condition, tag] : attached_) {
    // An error means the condition's entity was deleted: Cyclone then detached it from the
    // waitset, which no longer reports it either.
    if (dds_triggered(condition) > 0) triggered.push_back(tag);
  }
  return triggered;
}

}  // namespace autonomy::dds
