#pragma once
// The chronological engine with conflict-directed backjumping (EngineOptions::backjumping),
// made by make_search_engine("chronological"); see backjumping.cpp.
#include <memory>

#include "search_engine.hpp"

namespace autonomy::planner {

std::unique_ptr<SearchEngine> make_backjumping_search(const EngineOptions& options);

}  // namespace autonomy::planner
