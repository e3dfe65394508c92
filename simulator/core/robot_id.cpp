#include "simulator/core/robot_id.hpp"

namespace autonomy::sim {

namespace {
bool allowed(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
         c == '-' || c == '.';
}
}  // namespace

std::optional<std::string> robot_id_problem(const std::string& id) {
  if (id.empty()) return "robot id is empty";
  if (id.size() > kMaxRobotIdLength) {
    return "robot id '" + id.substr(0, 16) + "...' is longer than " +
           std::to_string(kMaxRobotIdLength) + " characters";
  }
  for (const char c : id) {
    if (!allowed(c)) return "robot id '" + id + "' has characters outside [A-Za-z0-9_.-]";
  }
  return std::nullopt;
}

}  // namespace autonomy::sim
