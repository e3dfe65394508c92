#pragma once
// Not-first/not-last on a unary timeline (Baptiste and Le Pape 1996; Torres and Lopez 2000):
// for a set Omega of tokens that exclude each other and a token i outside it,
//  - not last: when Omega and i cannot all fit with i last (est(Omega) + p(Omega) > lct(i) -
//    p(i)), i ends before the start of some token of Omega: lct(i) <= max over Omega of lst;
//  - not first: when they cannot fit with i first (est(i) + p(i) > lct(Omega) - p(Omega)),
//    i starts after the end of some token of Omega: est(i) >= min over Omega of ect.
// Edge finding (token_network.cpp) finds what must come first or last; these rules find what
// cannot, and narrow the bounds where edge finding adds nothing.
#include <vector>

#include "temporal_network.hpp"

namespace autonomy::planner {

struct UnaryWindow {
  Time est = 0, lct = 0, duration = 0;  // earliest start, latest end, minimum duration
};

// One pass over the task intervals (Omega: the tokens other than i whose windows lie within
// [est(a), lct(b)] for two tokens a and b; O(n^3)). Returns the windows with each est raised
// and each lct lowered as far as the rules allow; never widens one. Sound for any Omega, so a
// window the rules empty (est + duration > lct) means the tokens cannot all fit.
std::vector<UnaryWindow> not_first_not_last(const std::vector<UnaryWindow>& windows);

}  // namespace autonomy::planner
