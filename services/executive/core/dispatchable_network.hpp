#pragma once
// The dispatchable form of a flexible plan (Muscettola, Morris and Pollack 1998): the plan's
// timepoints (origin, every token's start and end) and its distance graph closed by all-pairs
// shortest paths, with dominated edges removed. In that form an executive that propagates an
// executed time only to a timepoint's neighbours keeps every later bound exact.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "flexible_plan.hpp"

namespace autonomy::executive {

using Time = std::int64_t;
// The planner writes unbounded as +-2^52; anything that large is "no constraint".
inline constexpr Time kUnbounded = Time{1} << 52;

// weight w on edge from -> to means  time(to) - time(from) <= w.
struct DistanceEdge {
  std::size_t from = 0, to = 0;
  Time weight = 0;
};

struct DispatchableNetwork {
  std::vector<std::string> names;   // "origin", "<id>.start", "<id>.end"; index 0 is origin
  std::vector<DistanceEdge> edges;  // minimal dispatchable set
  std::size_t closed_edges = 0;     // finite edges of the all-pairs closure, before filtering
  // Each timepoint's window relative to the origin, from the closure (+-kUnbounded if none):
  // the filtered edges alone do not link every timepoint to the origin.
  std::vector<Time> earliest, latest;
  // Per timepoint: the token it belongs to (index into FlexiblePlan::tokens) and which end.
  std::vector<std::size_t> token;  // SIZE_MAX for origin
  std::vector<bool> is_start;

  std::size_t index_of(std::size_t token_index, bool start) const {
    return 1 + 2 * token_index + (start ? 0 : 1);
  }
};

// Builds the dispatchable form. Returns nullopt (and a reason) when the plan names an unknown
// timepoint or its constraints are inconsistent (a negative cycle). filter = false keeps every
// edge of the closure (the baseline the filter is checked and measured against).
// Cost: one Dijkstra per rigid class (timepoints at fixed distances, one node) on the plan's
// collapsed graph, dominance decided inside it; no n x n matrix (about 50 ms at 1,000 tokens,
// 190 ms at 2,000: docs/executive.md).
std::optional<DispatchableNetwork> make_dispatchable(const planner::FlexiblePlan& plan,
                                                     std::string* error, bool filter = true);

}  // namespace autonomy::executive
