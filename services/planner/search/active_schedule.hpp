#pragma once
// A cheap first plan by active schedule generation on timelines (Giffler and Thompson 1960,
// as a priority rule over the token network's flaws; see active_schedule.cpp): the large-
// neighbourhood engine starts from the best of a few such greedy dives instead of the
// chronological engine's earliest-start first plan.
#include <cstddef>
#include <random>
#include <vector>

#include "search_engine.hpp"

namespace autonomy::planner {

// The default selector's choice, except when it is a free token: then the free token whose
// earliest end on its timeline (its earliest slot there) is smallest names a timeline, and
// among the free tokens of that timeline that could start before that end, the one with the
// least latest start (the most work that must follow it) is taken. With `rng`, the rank in
// that order is drawn with weight 1 / (rank + 1)^2 instead of always the first.
FlawSelector active_schedule_selector(std::mt19937* rng = nullptr);

// One greedy dive from the network's state: the selector's flaw, its options in the network's
// order, the first that applies; no backtracking. On success the network holds the plan and
// `decisions` lists what was applied (replaying them from the same state gives the same plan);
// on a dead end the network is back in its starting state and the result is false.
bool greedy_dive(TokenNetwork& net, const FlawSelector& select, const Termination& term,
                 SearchStatistics& stats, std::vector<Decision>* decisions);

}  // namespace autonomy::planner
