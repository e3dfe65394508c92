#pragma once
// A SearchBudget that stops after a wall-clock duration, for callers at the edge (the tool, the
// node, benchmarks). The engines themselves never read a clock; they poll this predicate.
#include "services/courier/core/scheduler/scheduler_engine.hpp"

#include <chrono>

namespace autonomy::courier::scheduling {

inline SearchBudget wall_clock_budget(std::chrono::microseconds limit, std::uint64_t seed = 1) {
  SearchBudget budget;
  budget.seed = seed;
  const auto deadline = std::chrono::steady_clock::now() + limit;
  budget.stop = [deadline] { return std::chrono::steady_clock::now() >= deadline; };
  return budget;
}

}  // namespace autonomy::courier::scheduling
