#pragma once
// The large-neighbourhood search engine ("lns"), made by make_search_engine; see
// large_neighbourhood.cpp.
#include <memory>

#include "search_engine.hpp"

namespace autonomy::planner {

std::unique_ptr<SearchEngine> make_large_neighbourhood_search(const EngineOptions& options);

}  // namespace autonomy::planner
