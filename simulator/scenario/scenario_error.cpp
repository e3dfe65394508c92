#include "simulator/scenario/scenario_error.hpp"

namespace autonomy::sim {

std::string ScenarioError::to_string() const {
  if (line <= 0) return source + ": " + message;
  return source + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " + message;
}

}  // namespace autonomy::sim
