#pragma once
// The construction of the dispatchable form used before issue 28 (one Dijkstra per timepoint
// over every timepoint, the n x n closure kept), for the benchmark's baseline and the tests'
// comparison only. Same contract and result as make_dispatchable.
#include "dispatchable_network.hpp"

namespace autonomy::executive {

std::optional<DispatchableNetwork> make_dispatchable_every_timepoint(
    const planner::FlexiblePlan& plan, std::string* error, bool filter = true);

}  // namespace autonomy::executive
