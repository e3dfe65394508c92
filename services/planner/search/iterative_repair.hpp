#pragma once
// The repair-based engine ("repair"), made by make_search_engine; see iterative_repair.cpp.
#include <memory>

#include "search_engine.hpp"

namespace autonomy::planner {

std::unique_ptr<SearchEngine> make_iterative_repair(const EngineOptions& options);

}  // namespace autonomy::planner
