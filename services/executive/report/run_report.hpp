#pragma once
// The report of a flight: every plan's tokens as planned (earliest start to earliest end, with
// the start window) against what was executed, the faults and the executive's responses on the
// same time axis, and the goals achieved and lost. Written as a Gantt SVG and a Markdown page
// when the mission ends (executive --report-dir).
#include <optional>
#include <string>
#include <vector>

#include "dispatcher.hpp"

namespace autonomy::executive {

struct ReportToken {
  std::string plan_id, timeline, text;  // text: "predicate(args)"
  bool goal = false;
  Time start_lb = 0, start_ub = 0, end_lb = 0;  // planned, absolute
  std::optional<Time> started, ended;           // executed
  bool cut_short = false;                       // ended by an abort, not by the plan
};

struct ReportEvent {
  Time time = 0;
  std::string kind, text;
};

class RunReport {
 public:
  // The tokens of a plan that has been replaced or has finished, with what the dispatcher did.
  void add_plan(const std::string& plan_id, const Dispatcher& dispatcher, Time stopped_at);
  // Faults, responses, aborts, plans and goals (other kinds are not drawn).
  void add_event(Time time, const std::string& kind, const std::string& text);
  void set_goals(std::vector<std::string> achieved, std::vector<std::string> lost);

  std::string svg(Time horizon) const;
  std::string markdown(const std::string& title, Time horizon) const;
  const std::vector<ReportToken>& tokens() const { return tokens_; }
  const std::vector<ReportEvent>& events() const { return events_; }

  static bool reported(const std::string& kind);  // the kinds add_event keeps

 private:
  std::vector<ReportToken> tokens_;
  std::vector<ReportEvent> events_;
  std::vector<std::string> achieved_, lost_;
};

}  // namespace autonomy::executive
