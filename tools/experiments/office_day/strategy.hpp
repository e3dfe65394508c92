#pragma once
// The strategies the day-in-office experiment compares (issue 10), each a way to run the
// courier service: (a) the paper's heuristic without monitoring, waiting at closed doors (what
// Open-RMF does); (b) the paper's controller: heuristic + door monitoring + opportunism; (c) ours:
// the exact / large-scale engines + monitoring + opportunism; (d) (c) + learning, the knowledge
// carried from day to day; (e) (d) with three couriers.
#include <string>
#include <vector>

namespace autonomy::office_day {

struct Strategy {
  std::string id;                        // a .. e
  std::string label;
  std::vector<std::string> courier_args;  // besides --config, --journal, --events, --domain
  int couriers = 1;
  bool carries_knowledge = false;        // the journal's learned tables go on to the next day
};

const std::vector<Strategy>& strategies();
const Strategy* strategy(const std::string& id);

}  // namespace autonomy::office_day
