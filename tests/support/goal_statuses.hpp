#pragma once
// A go-to goal's status history as one line for failure messages:
// "accepted -> active -> blocked (door d1 closed)".
#include <string>
#include <vector>

#include "common/msg/navigation.hpp"

namespace autonomy::test {

inline std::string states_text(const std::vector<msg::GoalStatus>& v) {
  std::string out;
  for (const auto& s : v) {
    if (!out.empty()) out += " -> ";
    out += msg::to_string(s.state);
    if (!s.reason.empty()) out += " (" + s.reason + ")";
  }
  return out.empty() ? "(none)" : out;
}

}  // namespace autonomy::test
