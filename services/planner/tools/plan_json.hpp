#pragma once
// A flexible plan as JSON (the protobuf JSON mapping of pb::FlexiblePlan, every field printed):
// what planner_tool and `autonomy plan` write with --json.
#include <string>

#include "flexible_plan.hpp"

namespace autonomy::planner {
std::string plan_json(const FlexiblePlan& plan);
}
