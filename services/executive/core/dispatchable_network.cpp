#include "dispatchable_network.hpp"

#include <algorithm>
#include <unordered_map>

namespace autonomy::executive {
namespace {

constexpr Time kNone = kUnbounded;  // no edge in the distance matrix

bool finite(Time t) {
  return t < kUnbounded && t > -kUnbounded;
}

}  // namespace

std::optional<DispatchableNetwork> make_dispatchable(const planner::FlexiblePlan& plan,
                                                     std::string* error, bool filter) {
  DispatchableNetwork net;
  const std::size_t n = 1 + 2 * plan.tokens.size();
  net.names.push_back("origin");
  net.token.push_back(SIZE_MAX);
  net.is_start.push_back(false);
  std::unordered_map<std::string, std::size_t> index{{"origin", 0}};
  for (std::size_t i = 0; i < plan.tokens.size(); ++i) {
    for (bool start : {true, false}) {
      std::string name = std::to_string(plan.tokens[i].id) + (start ? ".start" : ".end");
      index.emplace(name, net.names.size());
      net.names.push_back(name);
      net.token.push_back(i);
      net.is_start.push_back(start);
    }
  }
  std::vector<Time> d(n * n, kNone);
  auto at = [&](std::size_t a, std::size_t b) -> Time& { return d[a * n + b]; };
  for (std::size_t a = 0; a < n; ++a) at(a, a) = 0;
  // lb <= to - from <= ub  ->  from->to weight ub, to->from weight -lb.
  auto add = [&](std::size_t from, std::size_t to, Time lb, Time ub) {
    if (finite(ub)) at(from, to) = std::min(at(from, to), ub);
    if (finite(lb)) at(to, from) = std::min(at(to, from), -lb);
  };
  for (std::size_t i = 0; i < plan.tokens.size(); ++i) {
    const planner::PlanToken& t = plan.tokens[i];
    std::size_t s = net.index_of(i, true), e = net.index_of(i, false);
    add(0, s, t.start_lb, t.start_ub);
    add(0, e, t.end_lb, t.end_ub);
    add(s, e, std::max<Time>(0, t.duration_lb), t.duration_ub);
  }
  for (const planner::PlanConstraint& c : plan.constraints) {
    auto f = index.find(c.from), t = index.find(c.to);
    if (f == index.end() || t == index.end()) {
      if (error)
        *error =
            "plan constraint names unknown timepoint '" + (f == index.end() ? c.from : c.to) + "'";
      return std::nullopt;
    }
    add(f->second, t->second, c.lb, c.ub);
  }
  // Floyd-Warshall closure.
  for (std::size_t k = 0; k < n; ++k)
    for (std::size_t a = 0; a < n; ++a) {
      Time ak = at(a, k);
      if (ak == kNone) continue;
      for (std::size_t b = 0; b < n; ++b) {
        Time kb = at(k, b);
        if (kb != kNone && ak + kb < at(a, b)) at(a, b) = ak + kb;
      }
    }
  for (std::size_t a = 0; a < n; ++a)
    if (at(a, a) < 0) {
      if (error)
        *error = "plan constraints are inconsistent (negative cycle through " + net.names[a] + ")";
      return std::nullopt;
    }
  net.earliest.assign(n, -kUnbounded);
  net.latest.assign(n, kUnbounded);
  for (std::size_t a = 0; a < n; ++a) {
    if (at(a, 0) != kNone) net.earliest[a] = -at(a, 0);
    if (at(0, a) != kNone) net.latest[a] = at(0, a);
  }
  // Triangle rule of Muscettola, Morris and Pollack: with D(A,B) + D(B,C) = D(A,C),
  //  a non-negative edge A->C is dominated by a non-negative B->C, and
  //  a negative edge A->C is dominated by a negative A->B.
  // Two edges can dominate each other only when the triangle holds a zero-length cycle (the
  // middle timepoint rigidly linked to an end). Rather than collapsing rigid components, a
  // rigidly linked middle never dominates: fewer edges are removed, none wrongly.
  auto rigid = [&](std::size_t x, std::size_t y) {
    return at(x, y) != kNone && at(y, x) != kNone && at(x, y) + at(y, x) == 0;
  };
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t c = 0; c < n; ++c) {
      if (a == c || at(a, c) == kNone) continue;
      ++net.closed_edges;
      Time w = at(a, c);
      bool dominated = false;
      for (std::size_t b = 0; filter && b < n && !dominated; ++b) {
        if (b == a || b == c || at(a, b) == kNone || at(b, c) == kNone) continue;
        if (at(a, b) + at(b, c) != w || rigid(a, b) || rigid(b, c)) continue;
        dominated = w >= 0 ? at(b, c) >= 0 : at(a, b) < 0;
      }
      if (!dominated) net.edges.push_back({a, c, w});
    }
  return net;
}

}  // namespace autonomy::executive
