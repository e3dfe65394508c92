#pragma once
// A Gantt chart of a flexible plan: one row per timeline; each token drawn at its earliest
// times (solid) with its start and end windows as whiskers (the plan's flexibility).
#include <string>

#include "flexible_plan.hpp"

namespace autonomy::planner {
std::string gantt_svg(const FlexiblePlan& plan);
}
