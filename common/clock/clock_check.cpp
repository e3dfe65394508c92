#include "common/clock/clock_check.hpp"

#include <limits>

namespace autonomy::clock {

namespace {

constexpr int64_t kMax = std::numeric_limits<int64_t>::max();

// ticks * step_ns, or nothing when it does not fit in 64 bits (a forged tick near 2^63 does not).
std::optional<int64_t> span_ns(int64_t ticks, int64_t step_ns) {
  if (ticks < 0 || step_ns <= 0) return std::nullopt;
  if (ticks > kMax / step_ns) return std::nullopt;
  return ticks * step_ns;
}

// The simulator stamps tick k with k * step (rounded per tick from seconds): a time that
// disagrees by more than a rounding error is not a real world's clock.
bool consistent(const ClockReading& r) {
  const std::optional<int64_t> expected = span_ns(r.tick, r.step_ns);
  if (!expected) return false;
  const int64_t diff = *expected > r.sim_time_ns ? *expected - r.sim_time_ns : r.sim_time_ns - *expected;
  return diff <= 1'000'000 + *expected / 1'000'000;
}

}  // namespace

const char* to_string(ClockVerdict v) {
  switch (v) {
    case ClockVerdict::Follow: return "follow";
    case ClockVerdict::Repeated: return "repeated";
    case ClockVerdict::OtherWorld: return "other world";
    case ClockVerdict::Backwards: return "backwards";
    case ClockVerdict::Leap: return "leap";
    case ClockVerdict::Malformed: return "malformed";
  }
  return "?";
}

ClockCheck::ClockCheck(LeapLimit limit) : limit_(limit) {}

ClockVerdict ClockCheck::check(const ClockReading& r, int64_t wall_ns) {
  ClockVerdict v = ClockVerdict::Follow;
  if (r.sim_time_ns < 0 || !consistent(r)) {
    v = ClockVerdict::Malformed;
  } else if (world_ && r.world_id != *world_) {
    v = ClockVerdict::OtherWorld;
  } else if (world_ && r.tick == tick_) {
    return ClockVerdict::Repeated;
  } else if (world_ && r.tick < tick_) {
    v = ClockVerdict::Backwards;
  } else if (world_) {
    // In double: a forged tick minus ours may not fit the arithmetic of 64-bit integers.
    const double wall_s = static_cast<double>(wall_ns - followed_at_ns_) * 1e-9;
    const double allowed = static_cast<double>(limit_.floor_ticks) +
                           static_cast<double>(limit_.ticks_per_s) * (wall_s > 0 ? wall_s : 0.0);
    if (static_cast<double>(r.tick) - static_cast<double>(tick_) > allowed) v = ClockVerdict::Leap;
  }
  switch (v) {
    case ClockVerdict::Follow:
      world_ = r.world_id;
      tick_ = r.tick;
      followed_at_ns_ = wall_ns;
      break;
    case ClockVerdict::OtherWorld: ++counts_.other_world; break;
    case ClockVerdict::Backwards: ++counts_.backwards; break;
    case ClockVerdict::Leap: ++counts_.leap; break;
    case ClockVerdict::Malformed: ++counts_.malformed; break;
    case ClockVerdict::Repeated: break;
  }
  return v;
}

std::string ClockCheck::explain(const ClockReading& r, ClockVerdict v) const {
  const std::string what = "tick " + std::to_string(r.tick) + " of world " + std::to_string(r.world_id);
  const std::string followed = world_ ? "tick " + std::to_string(tick_) + " of world " + std::to_string(*world_)
                                      : std::string("no clock yet");
  switch (v) {
    case ClockVerdict::Follow: return what + " followed";
    case ClockVerdict::Repeated: return what + " again";
    case ClockVerdict::OtherWorld:
      return what + " belongs to another world than the one joined (following " + followed +
             "): a second simulator or a forged clock on this domain";
    case ClockVerdict::Backwards: return what + " goes back from " + followed;
    case ClockVerdict::Leap:
      return what + " leaps ahead of " + followed + " by more ticks than any world steps in the time since (" +
             std::to_string(limit_.floor_ticks) + " + " + std::to_string(limit_.ticks_per_s) + " per second)";
    case ClockVerdict::Malformed:
      return what + " is not a world's clock: time " + std::to_string(r.sim_time_ns) + " ns is not tick * step (" +
             std::to_string(r.step_ns) + " ns)";
  }
  return what;
}

}  // namespace autonomy::clock
