#pragma once
// Which samples of autonomy/clock a service may follow. One world per domain: a service joins
// the first world it hears and ignores a clock of any other; within its world a clock that goes
// backwards, or leaps absurdly forwards (a forged tick 2^63-1 would otherwise freeze every later
// tick as "older"), is ignored too. Every ignored sample is counted by reason, so a warning and
// a figure show that something else is talking on the domain. Pure logic, no DDS: the lockstep
// client (common/service/lockstep_client.hpp) is its one user, shared by every service.
#include <cstdint>
#include <optional>
#include <string>

namespace autonomy::clock {

struct ClockReading {
  uint64_t world_id = 0;
  int64_t tick = 0;
  int64_t sim_time_ns = 0;
  int64_t step_ns = 0;
};

enum class ClockVerdict {
  Follow,      // a newer tick of the joined world (or the first clock heard: the world is joined)
  Repeated,    // the tick already followed, again: not news, not suspicious
  OtherWorld,  // another world's clock on this domain
  Backwards,   // an older tick than the one followed
  Leap,        // further ahead than any quiet stretch of a real world can skip
  Malformed,   // negative tick or step, or a time that is not tick * step
};

const char* to_string(ClockVerdict v);

struct ClockCheckCounts {
  uint64_t other_world = 0;
  uint64_t backwards = 0;
  uint64_t leap = 0;
  uint64_t malformed = 0;
  uint64_t ignored() const { return other_world + backwards + leap + malformed; }
};

// How far ahead a clock may be of the tick followed. A lockstep world steps the ticks every
// participant declared quiet without publishing them (idl/clock.idl): an idle behavior is quiet
// for ever, so the world races through unpublished ticks as fast as it can step, and a clock can
// rightly jump by millions of ticks. No world steps faster than ticks_per_s, though, so a jump
// larger than floor_ticks + ticks_per_s * (wall seconds since the tick followed) is forged.
struct LeapLimit {
  int64_t floor_ticks = 1'000'000;
  // A world of one idle robot steps about 2 million quiet ticks a second on a 2-core machine
  // (measured, issue 22): 1 ns a step is beyond any, and 2^63-1 still takes 292 years.
  int64_t ticks_per_s = 1'000'000'000;
};

class ClockCheck {
 public:
  explicit ClockCheck(LeapLimit limit = {});

  // Judges the reading that arrived at wall_ns (any monotonic clock of the caller's); a Follow
  // verdict moves the followed tick (and joins the world on the first one). Other verdicts
  // change nothing but their count.
  ClockVerdict check(const ClockReading& r, int64_t wall_ns);

  // The world joined: nothing before the first followed clock.
  std::optional<uint64_t> world() const { return world_; }
  int64_t tick() const { return tick_; }
  const ClockCheckCounts& counts() const { return counts_; }
  // Why the reading got its verdict, for the warning ("tick 9223372036854775807 of world 7
  // leaps ahead of tick 120 of world 7 ...").
  std::string explain(const ClockReading& r, ClockVerdict v) const;

 private:
  LeapLimit limit_;
  std::optional<uint64_t> world_;
  int64_t tick_ = -1;
  int64_t followed_at_ns_ = 0;  // wall time of the tick followed
  ClockCheckCounts counts_;
};

}  // namespace autonomy::clock
