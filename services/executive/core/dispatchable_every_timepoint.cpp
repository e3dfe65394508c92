// The dispatchable form as the executive built it before issue 28, kept as the reference the
// benchmark and the tests measure and check the current construction against: the closure by
// one Dijkstra per timepoint (Johnson) into an n x n matrix, dominance by flag propagation per
// source and per target over the plan's edges. O(n m); 1.2-2.2 s at 1,000 tokens.
#include "dispatchable_every_timepoint.hpp"

#include "dispatchable_graph.hpp"

#include <algorithm>
#include <numeric>
#include <queue>

namespace autonomy::executive {
namespace every_timepoint {

constexpr Time kNone = kUnbounded;  // no path in the distance matrix

// Row `source` of the closure: Dijkstra on the weights reweighted by the potentials.
void shortest_row(const dispatchable_graph::SparseGraph& g, const std::vector<Time>& h,
                  std::size_t source, Time* row) {
  const std::size_t n = g.out.size();
  std::vector<Time> reduced(n, kNone);
  using Entry = std::pair<Time, std::size_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> heap;
  reduced[source] = 0;
  heap.push({0, source});
  while (!heap.empty()) {
    auto [d, u] = heap.top();
    heap.pop();
    if (d != reduced[u]) continue;
    for (const dispatchable_graph::Arc& a : g.out[u]) {
      Time nd = d + a.weight + h[u] - h[a.to];
      if (nd < reduced[a.to]) {
        reduced[a.to] = nd;
        heap.push({nd, a.to});
      }
    }
  }
  for (std::size_t v = 0; v < n; ++v)
    row[v] = reduced[v] == kNone ? kNone : reduced[v] - h[source] + h[v];
}

// Rigid classes: timepoints at a fixed distance from each other (D(x,y) + D(y,x) = 0). The
// relation is an equivalence, and its classes are the strongly connected parts of every
// shortest-path graph, which is what lets the filter below work on a DAG of classes.
std::vector<std::size_t> rigid_classes(const std::vector<Time>& d, std::size_t n) {
  std::vector<std::size_t> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](std::size_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (std::size_t x = 0; x < n; ++x)
    for (std::size_t y = x + 1; y < n; ++y) {
      Time xy = d[x * n + y], yx = d[y * n + x];
      if (xy != kNone && yx != kNone && xy + yx == 0) parent[find(x)] = find(y);
    }
  std::vector<std::size_t> cls(n);
  for (std::size_t x = 0; x < n; ++x) cls[x] = find(x);
  return cls;
}

// Which closure edges the triangle rule of Muscettola, Morris and Pollack removes:
//  a non-negative A->C is dominated by a non-negative B->C, and a negative A->C by a negative
//  A->B, where B lies on a shortest path from A to C (D(A,B) + D(B,C) = D(A,C)) and B is not
//  rigidly linked to A or to C (two edges through a rigid middle can dominate each other;
//  keeping both removes fewer edges, none wrongly).
// Testing every middle B is n^3. Instead, per source A (negative edges) and per target C
// (non-negative edges), flags are propagated along the tight edges of the sparse graph: a
// timepoint learns whether a qualifying B outside its own rigid class precedes it on a shortest
// path. Each flag changes at most twice, so a pass is O(edges) and the filter O(n * edges).
class DominanceFilter {
 public:
  DominanceFilter(const dispatchable_graph::SparseGraph& g, const std::vector<Time>& d,
                  std::size_t n)
      : g_(g), d_(d), n_(n), cls_(rigid_classes(d, n)), in_(n) {
    for (std::size_t u = 0; u < n; ++u)
      for (const dispatchable_graph::Arc& a : g.out[u]) in_[a.to].push_back({u, a.weight});
    dominated_.assign(n * n, false);
    for (std::size_t a = 0; a < n; ++a) negative_from(a);
    for (std::size_t c = 0; c < n; ++c) non_negative_to(c);
  }
  bool dominated(std::size_t a, std::size_t c) const { return dominated_[a * n_ + c]; }

 private:
  Time D(std::size_t x, std::size_t y) const { return d_[x * n_ + y]; }

  // Per timepoint: `self` = a qualifying B in its own class reaches it (through its class),
  // `foreign` = a qualifying B of another class does. Propagated over `next`, the tight
  // successors (forward from a source, or backward towards a target).
  template <typename Tight, typename Flag>
  void propagate(const std::vector<std::vector<dispatchable_graph::Arc>>& adjacency, Tight tight,
                 Flag flag) {
    self_.assign(n_, false);
    foreign_.assign(n_, false);
    std::vector<std::size_t> work;
    for (std::size_t v = 0; v < n_; ++v)
      if (flag(v)) {
        self_[v] = true;
        work.push_back(v);
      }
    while (!work.empty()) {
      std::size_t u = work.back();
      work.pop_back();
      for (const dispatchable_graph::Arc& a : adjacency[u]) {
        std::size_t v = a.to;
        if (!tight(u, v, a.weight)) continue;
        bool changed = false;
        if (cls_[u] == cls_[v]) {
          if (self_[u] && !self_[v]) self_[v] = changed = true;
          if (foreign_[u] && !foreign_[v]) foreign_[v] = changed = true;
        } else if ((self_[u] || foreign_[u]) && !foreign_[v]) {
          foreign_[v] = changed = true;
        }
        if (changed) work.push_back(v);
      }
    }
  }

  void negative_from(std::size_t a) {
    bool any = false;
    for (std::size_t c = 0; c < n_ && !any; ++c) any = c != a && D(a, c) < 0;
    if (!any) return;
    propagate(
        g_.out,
        [&](std::size_t u, std::size_t v, Time w) {
          return D(a, u) != kNone && D(a, v) != kNone && D(a, u) + w == D(a, v);
        },
        [&](std::size_t b) { return D(a, b) < 0 && cls_[b] != cls_[a]; });
    for (std::size_t c = 0; c < n_; ++c)
      if (c != a && D(a, c) < 0 && foreign_[c]) dominated_[a * n_ + c] = true;
  }

  void non_negative_to(std::size_t c) {
    // Backwards from C: an arc v->u of in_ stands for the plan's edge u->v.
    propagate(
        in_,
        [&](std::size_t v, std::size_t u, Time w) {
          return D(u, c) != kNone && D(v, c) != kNone && w + D(v, c) == D(u, c);
        },
        [&](std::size_t b) { return D(b, c) != kNone && D(b, c) >= 0 && cls_[b] != cls_[c]; });
    for (std::size_t a = 0; a < n_; ++a)
      if (a != c && D(a, c) != kNone && D(a, c) >= 0 && foreign_[a]) dominated_[a * n_ + c] = true;
  }

  const dispatchable_graph::SparseGraph& g_;
  const std::vector<Time>& d_;
  std::size_t n_;
  std::vector<std::size_t> cls_;
  std::vector<std::vector<dispatchable_graph::Arc>> in_;
  std::vector<bool> dominated_, self_, foreign_;
};

}  // namespace every_timepoint

std::optional<DispatchableNetwork> make_dispatchable_every_timepoint(
    const planner::FlexiblePlan& plan, std::string* error, bool filter) {
  DispatchableNetwork net;
  auto pg = dispatchable_graph::plan_graph(plan, &net, error);
  if (!pg) return std::nullopt;
  const std::size_t n = net.names.size();
  const dispatchable_graph::SparseGraph& g = pg->graph;
  const std::vector<Time>* h = &pg->potentials;
  std::vector<Time> d(n * n, every_timepoint::kNone);
  for (std::size_t a = 0; a < n; ++a) every_timepoint::shortest_row(g, *h, a, &d[a * n]);
  auto at = [&](std::size_t a, std::size_t b) { return d[a * n + b]; };
  net.earliest.assign(n, -kUnbounded);
  net.latest.assign(n, kUnbounded);
  for (std::size_t a = 0; a < n; ++a) {
    if (at(a, 0) != every_timepoint::kNone) net.earliest[a] = -at(a, 0);
    if (at(0, a) != every_timepoint::kNone) net.latest[a] = at(0, a);
  }
  std::optional<every_timepoint::DominanceFilter> dominance;
  if (filter) dominance.emplace(g, d, n);
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t c = 0; c < n; ++c) {
      if (a == c || at(a, c) == every_timepoint::kNone) continue;
      ++net.closed_edges;
      if (!dominance || !dominance->dominated(a, c)) net.edges.push_back({a, c, at(a, c)});
    }
  return net;
}

}  // namespace autonomy::executive
