#include "dispatchable_network.hpp"

#include <algorithm>
#include <numeric>
#include <queue>
#include <unordered_map>

namespace autonomy::executive {
namespace {

constexpr Time kNone = kUnbounded;  // no path in the distance matrix

bool finite(Time t) {
  return t < kUnbounded && t > -kUnbounded;
}

struct Arc {
  std::size_t to;
  Time weight;
};

// The plan's distance graph as it was written: a few edges per timepoint. Everything below
// works on it instead of a dense matrix, so the closure costs n Dijkstra runs (Johnson), not
// Floyd-Warshall's n^3: a 1,000-token plan has 2,001 timepoints.
struct SparseGraph {
  std::vector<std::vector<Arc>> out;

  explicit SparseGraph(std::size_t n) : out(n) {}
  void add(std::size_t from, std::size_t to, Time weight) {
    for (Arc& a : out[from])
      if (a.to == to) {
        a.weight = std::min(a.weight, weight);
        return;
      }
    out[from].push_back({to, weight});
  }
};

// Bellman-Ford from a virtual source joined to every timepoint by a zero edge (queue-based).
// Returns the potentials that make every edge weight non-negative, or the index of a
// timepoint on a negative cycle.
std::optional<std::vector<Time>> potentials(const SparseGraph& g, std::size_t* on_cycle) {
  const std::size_t n = g.out.size();
  std::vector<Time> h(n, 0);
  std::vector<std::size_t> parent(n, SIZE_MAX), relaxations(n, 0);
  std::vector<bool> queued(n, true);
  std::queue<std::size_t> work;
  for (std::size_t v = 0; v < n; ++v) work.push(v);
  while (!work.empty()) {
    std::size_t u = work.front();
    work.pop();
    queued[u] = false;
    for (const Arc& a : g.out[u]) {
      if (h[u] + a.weight >= h[a.to]) continue;
      h[a.to] = h[u] + a.weight;
      parent[a.to] = u;
      // A shortest path has at most n edges; relaxed more often, the timepoint is reached
      // from a negative cycle. Walking back n parents lands on the cycle itself.
      if (++relaxations[a.to] > n) {
        std::size_t v = a.to;
        for (std::size_t i = 0; i < n; ++i) v = parent[v];
        *on_cycle = v;
        return std::nullopt;
      }
      if (!queued[a.to]) {
        queued[a.to] = true;
        work.push(a.to);
      }
    }
  }
  return h;
}

// Row `source` of the closure: Dijkstra on the weights reweighted by the potentials.
void shortest_row(const SparseGraph& g, const std::vector<Time>& h, std::size_t source,
                  Time* row) {
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
    for (const Arc& a : g.out[u]) {
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
  DominanceFilter(const SparseGraph& g, const std::vector<Time>& d, std::size_t n)
      : g_(g), d_(d), n_(n), cls_(rigid_classes(d, n)), in_(n) {
    for (std::size_t u = 0; u < n; ++u)
      for (const Arc& a : g.out[u]) in_[a.to].push_back({u, a.weight});
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
  void propagate(const std::vector<std::vector<Arc>>& adjacency, Tight tight, Flag flag) {
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
      for (const Arc& a : adjacency[u]) {
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

  const SparseGraph& g_;
  const std::vector<Time>& d_;
  std::size_t n_;
  std::vector<std::size_t> cls_;
  std::vector<std::vector<Arc>> in_;
  std::vector<bool> dominated_, self_, foreign_;
};

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
  SparseGraph g(n);
  std::string self_conflict;
  // lb <= to - from <= ub  ->  from->to weight ub, to->from weight -lb.
  auto add = [&](std::size_t from, std::size_t to, Time lb, Time ub) {
    if (from == to) {
      if ((finite(lb) && lb > 0) || (finite(ub) && ub < 0)) self_conflict = net.names[from];
      return;
    }
    if (finite(ub)) g.add(from, to, ub);
    if (finite(lb)) g.add(to, from, -lb);
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
  std::size_t on_cycle = 0;
  auto h = potentials(g, &on_cycle);
  if (!self_conflict.empty() || !h) {
    if (error)
      *error = "plan constraints are inconsistent (negative cycle through " +
               (h ? self_conflict : net.names[on_cycle]) + ")";
    return std::nullopt;
  }
  std::vector<Time> d(n * n, kNone);
  for (std::size_t a = 0; a < n; ++a) shortest_row(g, *h, a, &d[a * n]);
  auto at = [&](std::size_t a, std::size_t b) { return d[a * n + b]; };
  net.earliest.assign(n, -kUnbounded);
  net.latest.assign(n, kUnbounded);
  for (std::size_t a = 0; a < n; ++a) {
    if (at(a, 0) != kNone) net.earliest[a] = -at(a, 0);
    if (at(0, a) != kNone) net.latest[a] = at(0, a);
  }
  std::optional<DominanceFilter> dominance;
  if (filter) dominance.emplace(g, d, n);
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t c = 0; c < n; ++c) {
      if (a == c || at(a, c) == kNone) continue;
      ++net.closed_edges;
      if (!dominance || !dominance->dominated(a, c)) net.edges.push_back({a, c, at(a, c)});
    }
  return net;
}

}  // namespace autonomy::executive
