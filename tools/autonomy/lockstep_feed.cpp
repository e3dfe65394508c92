#include "tools/autonomy/lockstep_feed.hpp"

namespace autonomy::tools {

std::vector<msg::LockstepChange> LockstepFeed::take(const msg::SimulatorStatus& status, uint64_t* missed) {
  std::vector<msg::LockstepChange> out;
  if (missed) *missed = 0;
  const auto& changes = status.lockstep_changes;
  if (changes.empty()) return out;
  // Numbers lower than what was seen: another simulator run (its numbers start at 1 again).
  if (changes.back().number < last_) last_ = 0;
  if (missed && changes.front().number > last_ + 1) *missed = changes.front().number - last_ - 1;
  for (const auto& c : changes) {
    if (c.number <= last_) continue;
    out.push_back(c);
    last_ = c.number;
  }
  return out;
}

const char* event_name(const msg::LockstepChange& change) {
  return change.dropped ? "lockstep_dropped" : "lockstep_rejoined";
}

std::string describe(const msg::LockstepChange& change) {
  return std::string(event_name(change)) + " " + change.participant + " at tick " + std::to_string(change.tick) +
         ": " + change.reason;
}

}  // namespace autonomy::tools
