#pragma once
// Dispatches a flexible plan by the rules of Muscettola, Morris and Pollack 1998: a timepoint
// is executed when it is enabled (every timepoint that must precede it has been executed) and
// its window [lb, ub] contains now; its time is then propagated to its neighbours only. Some
// timepoints are controlled by the world (a turn ends when the turn ends): those are observed,
// never forced. step(now) never blocks and does at most one pass per timepoint; a window that
// closes without its timepoint, or an observation outside its window, is reported as a
// violation (the plan broke) instead of waiting for ever.
#include <string>
#include <vector>

#include "dispatchable_network.hpp"

namespace autonomy::executive {

struct DispatchEvent {
  enum class Kind { kStarted, kEnded, kViolation };
  Kind kind = Kind::kStarted;
  std::size_t token = 0;  // index into FlexiblePlan::tokens (SIZE_MAX: origin)
  Time time = 0;
  std::string reason;  // for violations: which bound, by how much
};

class Dispatcher {
 public:
  // plan times are relative to the origin, which is executed at `origin_time`.
  Dispatcher(planner::FlexiblePlan plan, DispatchableNetwork net, Time origin_time);

  // Marks a timepoint as observed (the world ends it); it is then only executed by observe().
  void set_observed(std::size_t token, bool start, bool observed);
  bool observed(std::size_t token, bool start) const { return observed_[tp(token, start)]; }

  // Executes every controllable timepoint that is enabled and whose window holds `now` (at
  // its earliest; a timeline's last end at its latest, the horizon at most);
  // reports windows that closed. Returns the events of this tick in execution order.
  std::vector<DispatchEvent> step(Time now);
  // The plan's first step, at its origin, whenever the plan is started: what is due at the
  // origin (the starts of its initial values, tokens pinned to it) executes at the origin. A
  // plan that arrives after its origin (paced time goes on while the planner searches) would
  // otherwise find those timepoints past their bound at the first tick it is stepped, and break.
  // Call after set_observed(); the events are returned by the next step().
  void start();
  // An observed time for a timepoint (a token end seen in telemetry, a confirmed command).
  // Events are appended to the next step's result; an observation outside the window is a
  // violation, and the time is still recorded (it is what happened).
  void observe(std::size_t token, bool start, Time time);

  Time origin() const { return at_[0]; }  // when plan time 0 is
  bool broken() const { return broken_; }
  bool finished() const;  // every timepoint executed
  bool executed(std::size_t token, bool start) const { return done_[tp(token, start)]; }
  Time executed_at(std::size_t token, bool start) const { return at_[tp(token, start)]; }
  // Current window of a timepoint in absolute time (tightened by what has executed).
  Time lower(std::size_t token, bool start) const { return lb_[tp(token, start)]; }
  Time upper(std::size_t token, bool start) const { return ub_[tp(token, start)]; }
  bool executing(std::size_t token) const {
    return executed(token, true) && !executed(token, false);
  }

  const planner::FlexiblePlan& plan() const { return plan_; }
  const DispatchableNetwork& network() const { return net_; }

 private:
  std::size_t tp(std::size_t token, bool start) const { return net_.index_of(token, start); }
  bool enabled(std::size_t p) const;
  void execute(std::size_t p, Time t);
  void violation(std::size_t p, Time t, std::string reason);

  planner::FlexiblePlan plan_;
  DispatchableNetwork net_;
  std::vector<std::vector<std::size_t>> out_, in_;  // edge indices by from / to
  std::vector<Time> lb_, ub_, at_;
  std::vector<bool> done_, observed_, reported_;
  // The last token of each timeline holds its value to the end: its end is executed at its
  // latest time within the horizon, not its earliest.
  std::vector<bool> held_;
  Time hold_until_ = kUnbounded;
  std::vector<DispatchEvent> pending_;
  bool broken_ = false;
};

}  // namespace autonomy::executive
