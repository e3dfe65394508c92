#pragma once
// The planner's flexible plan as the DDS value type (common/msg/planner.hpp) and back: the
// planner publishes plans with to_plan_message, an executive (or the CLI) reads them with
// from_plan_message. No DDS here: both services link this beside their own DDS node.
#include "common/msg/planner.hpp"
#include "flexible_plan.hpp"

namespace autonomy::planner {

msg::FlexiblePlan to_plan_message(const FlexiblePlan& plan);
// from_plan_message(to_plan_message(p)) == p, field by field.
FlexiblePlan from_plan_message(const msg::FlexiblePlan& plan);

}  // namespace autonomy::planner
