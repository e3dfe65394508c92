#pragma once
// Which processes still answer: the judgement behind `autonomy node watch` (and so behind the
// launcher noticing a hung process), apart from DDS. It looks at a ProcessTable that a reader
// keeps up to date and at the clock the caller passes in, and says what changed since the last
// look, as events:
//
//   heard        heard for the first time
//   silent       not heard for longer than silent_after_ns(its heartbeat period), or its writer
//                is gone (lease expired): it may be hung, stopped (SIGSTOP), dead or cut off
//   heard_again  a silent process spoke again
//   hung         silent for its hang limit (and at least silent_after_ns), once per silence
//   stopped      it disposed its heartbeat: a clean stop; forgotten
//   gone         silent, and the caller's is_gone says it no longer exists (a process of this
//                host whose pid is not running); forgotten
//
// Times are the caller's monotonic clock in ns: a process's silence is measured from when its
// last heartbeat arrived here, so the clocks of other hosts do not matter.
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "tools/autonomy/processes.hpp"

namespace autonomy::tools {

struct LivelinessEvent {
  enum class Kind { Heard, Silent, HeardAgain, Hung, Stopped, Gone };
  Kind kind = Kind::Silent;
  ProcessKey process;
  msg::Heartbeat last;      // its last heartbeat
  double silent_s = 0.0;    // how long it has not been heard (heard_again: how long it was not)
  double limit_s = 0.0;     // hung: the limit that applied
};
const char* to_string(LivelinessEvent::Kind kind);

struct LivelinessRules {
  // Seconds of silence after which a process is hung; 0: never.
  double hang_after_s = 10.0;
  // Per name (service/instance), overriding hang_after_s.
  std::map<std::string, double> hang_after_by_name;
  // Only these names (service/instance); empty: every process.
  std::vector<std::string> only;

  bool watches(const std::string& name) const;
  double hang_after(const std::string& name) const;
};

class LivelinessMonitor {
 public:
  explicit LivelinessMonitor(LivelinessRules rules) : rules_(std::move(rules)) {}

  // Events since the last call, in the table's order. Forgets stopped and gone processes in
  // `table` too (so that a respawned process's pid reused later starts afresh).
  std::vector<LivelinessEvent> check(ProcessTable& table, int64_t now_ns,
                                     const std::function<bool(const ProcessKey&)>& is_gone);

  // The processes that are silent now, with their last heartbeat.
  std::vector<const ProcessView*> silent(const ProcessTable& table) const;

 private:
  struct Memo {
    int64_t heard_at_ns = 0;  // the last arrival this monitor has seen
    bool silent = false;
    bool hung = false;
  };

  LivelinessRules rules_;
  std::map<ProcessKey, Memo> memos_;
};

}  // namespace autonomy::tools
