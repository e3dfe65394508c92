#pragma once
// The executive's planned-against-executed timelines: each executive's event samples
// (autonomy/executive/event) folded into records of what each plan token actually did (when it
// started and ended), kept beside the plans the executive was given (the planner's LatestPlan of
// the same requester, by request id: the executive may run a plan that is no longer the latest,
// since the next horizon's arrives before it begins; the planner's replies give them too). Pure:
// samples in, records out.
//
// A started or ended event names its token "timeline == predicate(args) #id" (the executive's
// describe(), services/executive/core/executive.cpp); with the event's plan_id that is a token of
// one plan, unambiguous even when a timeline repeats a predicate. Text without "#id" falls back to
// the timeline and value (the latest open record of that plan with the same text).
//
// Samples may come late or not at all (the event topic keeps 256 per reader): `number` counts
// 1, 2, ... per executive run, so a gap is a lost sample and a number inside a gap a late one,
// merged where it belongs (a late "started" gives a record that already ended its start). An end
// before its start is refused and counted, never recorded. A token still running when its plan is
// abandoned (an abort, a re-plan, a restart of the executive) is cut there: it ended unseen.
#include "common/msg/executive.hpp"
#include "common/msg/planner.hpp"

#include <cstddef>
#include <cstdint>
#include <deque>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace autonomy::viewer {

struct ExecutionLimits {
  std::size_t tokens = 4000;   // executed-token records kept per executive (the oldest go first)
  std::size_t marks = 400;     // marks kept per executive
  std::size_t plans = 4;       // plans kept per executive, by request id (the oldest go first)
  std::size_t missing = 1000;  // lost sample numbers remembered, to merge a late one
};

// One plan token as executed.
struct ExecutedToken {
  std::string plan_id;
  int64_t token = -1;                // the plan token's id; -1 when the event text carried none
  std::string timeline;              // "object.attribute"
  std::string value;                 // "predicate(args)"
  std::optional<int64_t> start_ns;   // simulated time; none: its start was never heard
  std::optional<int64_t> end_ns;     // none: running (or its end not heard yet)
  bool cut = false;                  // its plan was abandoned while it ran: end_ns is that time
};

// Anything else the executive did that a person looks for on the time axis: violations, faults,
// aborts, rejected or skipped commands, plans refused or begun (re-plans), goals, lost samples.
struct ExecutionMark {
  int64_t sim_time_ns = 0;
  int64_t tick = 0;
  std::string kind;                  // the event's kind; "lost" for samples never heard
  std::string text;
  std::string plan_id;
};

struct ExecutiveTrace {
  std::string plan_id;                    // the plan of the latest event
  std::vector<std::string> plan_order;    // plan ids in the order their events began
  std::deque<ExecutedToken> tokens;       // in the order first heard
  std::deque<ExecutionMark> marks;        // in the order heard
  std::map<std::string, msg::LatestPlan> plans;  // by request id
  std::deque<std::string> plans_heard;    // request ids, oldest first (which plan goes first)
  uint64_t last_number = 0;               // the highest sample number heard
  std::set<uint64_t> missing;             // numbers skipped and not heard since
  uint64_t lost = 0;                      // samples never heard (gaps in number)
  uint64_t refused = 0;                   // samples that could not be folded (an end before its start)
  int64_t latest_ns = 0;                  // simulated time of the latest event
};

class ExecutionTraces {
 public:
  explicit ExecutionTraces(ExecutionLimits limits = {}) : limits_(limits) {}

  void apply(const msg::ExecutiveEvent& event);
  // A plan of the executive that asked for it (the requester is the executive's name).
  void apply(const msg::LatestPlan& plan);
  // A planner's reply: its plan as the planner keeps it as the requester's latest (a valid plan
  // only). Replies give every plan even when the latest-plan state, one sample per requester,
  // was overwritten before it was read (a re-plan right after the first plan).
  void apply(const msg::PlanningReply& reply);

  const std::map<std::string, ExecutiveTrace>& executives() const { return traces_; }
  uint64_t version() const { return version_; }

 private:
  void fold(ExecutiveTrace& trace, const msg::ExecutiveEvent& event);
  void fold_token(ExecutiveTrace& trace, const msg::ExecutiveEvent& event, bool start);
  void add_mark(ExecutiveTrace& trace, ExecutionMark mark);

  ExecutionLimits limits_;
  std::map<std::string, ExecutiveTrace> traces_;
  uint64_t version_ = 0;
};

// "camera.mode == imaging(target1) #7" -> timeline "camera.mode", value "imaging(target1)",
// token 7 (-1 without "#id"); false when the text is not "timeline == value".
struct TokenName {
  std::string timeline, value;
  int64_t token = -1;
};
bool parse_token_name(const std::string& text, TokenName* out);

}  // namespace autonomy::viewer
