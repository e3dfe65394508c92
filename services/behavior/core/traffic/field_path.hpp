#pragma once
// The path a robot on a cost-to-go field is about to drive: from its position, cell after cell
// down the field's advice towards the goal, as cell centres every `spacing_m` (the last point is
// the goal). What the itinerary publishes and the traffic rule looks ahead on.
#include "common/geometry/geometry.hpp"
#include "services/behavior/core/cost_to_go_field.hpp"

#include <vector>

namespace autonomy::behavior::traffic {

// At most `length_m` of path; empty when the position has no route (the grid controller escapes
// first; the next call finds the path).
std::vector<geometry::Vec2> field_path(const CostToGoField& field, const geometry::Vec2& from, double length_m,
                                       double spacing_m = 0.3);

}  // namespace autonomy::behavior::traffic
