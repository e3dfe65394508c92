#include "tools/experiments/office_day/strategy.hpp"

namespace autonomy::office_day {

const std::vector<Strategy>& strategies() {
  static const std::vector<Strategy> all = {
      {"a", "paper heuristic, waits at closed doors", {"--engine", "paper", "--door-policy", "wait", "--learning", "false"}, 1, false},
      {"b", "paper heuristic + monitoring + opportunism", {"--engine", "paper", "--learning", "false"}, 1, false},
      {"c", "exact/large engines + monitoring + opportunism", {"--engine", "exact", "--learning", "false"}, 1, false},
      {"d", "(c) + learning, carried from day to day", {"--engine", "exact", "--learning", "true"}, 1, true},
      {"e", "(d) with 3 couriers", {"--engine", "exact", "--learning", "true"}, 3, true},
  };
  return all;
}

const Strategy* strategy(const std::string& id) {
  for (const Strategy& s : strategies())
    if (s.id == id) return &s;
  return nullptr;
}

}  // namespace autonomy::office_day
