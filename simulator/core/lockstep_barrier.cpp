#include "simulator/core/lockstep_barrier.hpp"

namespace autonomy::sim {

bool LockstepBarrier::add(const std::string& participant, bool from_current) {
  dropped_.erase(participant);
  // While a tick is open the newcomer may have missed its clock sample: wait for it from the next.
  const Tick first = current_ ? *current_ + (from_current ? 0 : 1) : 0;
  return members_.emplace(participant, first).second;
}

void LockstepBarrier::remove(const std::string& participant) {
  members_.erase(participant);
  dropped_.erase(participant);
  quiet_until_.erase(participant);
}

void LockstepBarrier::silent(const std::string& participant) { quiet_until_.erase(participant); }

void LockstepBarrier::begin_tick(Tick tick, double now_s) {
  current_ = tick;
  tick_started_s_ = now_s;
  ticks_.erase(ticks_.begin(), ticks_.lower_bound(tick));
}

LockstepBarrier::AckOutcome LockstepBarrier::on_ack(const std::string& participant, Tick tick,
                                                    std::uint32_t commands_sent, Tick quiet_until) {
  if (members_.count(participant) || dropped_.count(participant)) quiet_until_[participant] = quiet_until;
  if (stale(tick)) return AckOutcome::IgnoredStale;
  AckOutcome outcome = AckOutcome::Counted;
  auto member = members_.find(participant);
  if (member == members_.end()) {
    if (dropped_.erase(participant) == 0) {
      // Kept, not counted: a participant whose registration is still on its way (it read the
      // held tick 0 from the durable clock and answered first) is added from the current tick.
      ticks_[tick].announced[participant] = commands_sent;
      return AckOutcome::IgnoredUnknown;
    }
    member = members_.emplace(participant, tick).first;
    outcome = AckOutcome::Rejoined;
  }
  // An ack for a tick it was not yet waited for shows it is in step already: wait from then on.
  if (tick < member->second) member->second = tick;
  ticks_[tick].announced[participant] = commands_sent;
  return outcome;
}

bool LockstepBarrier::on_command(const std::string& source, Tick tick) {
  if (stale(tick)) return false;
  ++ticks_[tick].received[source];  // kept for a registration still on its way (see on_ack)
  return members_.count(source) > 0 || dropped_.count(source) > 0;
}

bool LockstepBarrier::done(const std::string& participant, Tick tick) const {
  const auto counters = ticks_.find(tick);
  if (counters == ticks_.end()) return false;
  const auto ack = counters->second.announced.find(participant);
  if (ack == counters->second.announced.end()) return false;
  const auto got = counters->second.received.find(participant);
  const std::uint32_t received = got == counters->second.received.end() ? 0 : got->second;
  return received >= ack->second;
}

std::vector<std::string> LockstepBarrier::waited_for(Tick tick) const {
  std::vector<std::string> out;
  for (const auto& [name, first] : members_) {
    if (first <= tick) out.push_back(name);
  }
  return out;
}

// complete() and quiet() run several times per tick: they walk the members in place instead of
// copying the names waited_for() lists.
bool LockstepBarrier::complete(Tick tick) const {
  if (current_ != tick) return false;
  for (const auto& [p, first] : members_) {
    if (first <= tick && !done(p, tick)) return false;
  }
  return true;
}

bool LockstepBarrier::quiet(Tick tick) const {
  bool anybody = false;
  for (const auto& [p, first] : members_) {
    if (first > tick) continue;
    anybody = true;
    const auto q = quiet_until_.find(p);
    if (q == quiet_until_.end() || q->second <= tick) return false;
  }
  return anybody;
}

std::vector<std::string> LockstepBarrier::expire(Tick tick, double now_s, double timeout_s) {
  std::vector<std::string> expired;
  if (current_ != tick || now_s - tick_started_s_ < timeout_s) return expired;
  for (const std::string& p : waited_for(tick)) {
    if (done(p, tick)) continue;
    members_.erase(p);
    quiet_until_.erase(p);
    dropped_.insert(p);
    expired.push_back(p);
  }
  return expired;
}

void LockstepBarrier::end_tick(Tick tick) {
  ticks_.erase(ticks_.begin(), ticks_.upper_bound(tick));
}

std::vector<std::string> LockstepBarrier::participants() const {
  std::vector<std::string> out;
  for (const auto& [name, first] : members_) out.push_back(name);
  return out;
}

}  // namespace autonomy::sim
