#pragma once
// What an integration test sees of an executive: its events and statuses recorded, the goals
// its final status names achieved and lost, and its story (every event but confirmations, one
// per line) for failure messages.
#include <algorithm>
#include <functional>
#include <string>
#include <vector>

#include "common/dds/topics.hpp"
#include "tests/support/dds_observer.hpp"

namespace autonomy::test {

inline std::vector<std::string> sorted(std::vector<std::string> v) {
  std::sort(v.begin(), v.end());
  return v;
}

class ExecutiveWatch {
 public:
  explicit ExecutiveWatch(const dds::Participant& participant)
      : events_(participant, dds::topics::executive_event), status_(participant, dds::topics::executive_status) {}

  void poll() {
    events_.poll();
    status_.poll();
  }
  bool finished() const {
    return !status_.matching([](const auto& s) { return s.state == "finished"; }).empty();
  }
  // The status that said finished (empty before).
  msg::ExecutiveStatus final_status() const {
    auto done = status_.matching([](const auto& s) { return s.state == "finished"; });
    return done.empty() ? msg::ExecutiveStatus{} : done.back();
  }
  std::vector<std::string> achieved() const { return sorted(final_status().goals_achieved); }
  // The labels of the goals lost ("r3: rover.radio == ...: why" -> "r3").
  std::vector<std::string> lost() const {
    std::vector<std::string> labels;
    for (const std::string& g : final_status().goals_lost) labels.push_back(g.substr(0, g.find(':')));
    return sorted(labels);
  }
  std::vector<msg::ExecutiveEvent> events(const std::string& kind) const {
    return events_.matching([&](const auto& e) { return e.kind == kind; });
  }
  std::vector<msg::ExecutiveEvent> events_where(const std::function<bool(const msg::ExecutiveEvent&)>& pred) const {
    return events_.matching(pred);
  }
  const std::vector<msg::ExecutiveEvent>& all_events() const { return events_.all(); }
  // One event per line; with_dispatch false leaves out token starts, ends and commands too.
  std::string story(bool with_dispatch = true) const {
    std::string s;
    for (const auto& e : events_.all()) {
      if (e.kind == "confirmed") continue;
      if (!with_dispatch && (e.kind == "started" || e.kind == "ended" || e.kind == "command")) continue;
      s += std::to_string(e.tick) + " " + e.kind + ": " + e.text + "\n";
    }
    return s;
  }

 private:
  Recorder<msg::ExecutiveEvent> events_;
  Recorder<msg::ExecutiveStatus> status_;
};

}  // namespace autonomy::test
