#include "dispatchable_network.hpp"

#include "dispatchable_graph.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <queue>
#include <unordered_map>

namespace autonomy::executive {
namespace {

bool finite(Time t) {
  return t < kUnbounded && t > -kUnbounded;
}

// Bellman-Ford from a virtual source joined to every timepoint by a zero edge (queue-based).
// Returns the potentials that make every edge weight non-negative, or the index of a
// timepoint on a negative cycle.
std::optional<std::vector<Time>> potentials(const dispatchable_graph::SparseGraph& g,
                                            std::size_t* on_cycle) {
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
    for (const dispatchable_graph::Arc& a : g.out[u]) {
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

// Rigid classes: timepoints at a fixed distance from each other (D(x,y) + D(y,x) = 0). With
// potentials h (every reduced weight w + h[u] - h[v] >= 0), x and y are rigid exactly when a
// cycle of zero reduced weight joins them: the two shortest paths between them close a cycle of
// weight 0, so every reduced weight on it is 0, and a zero-reduced cycle is a zero cycle. The
// classes are the strongly connected components of the zero-reduced arcs (Tarjan). Tarjan ends a
// component after every component it reaches, so numbering them backwards gives each zero arc
// between two classes a lower class at its tail: class order is a topological order of the
// zero arcs, which the per-class Dijkstra below breaks ties with.
struct RigidClasses {
  std::vector<std::uint32_t> of;  // timepoint -> class
  std::size_t count = 0;
};

RigidClasses rigid_classes(const dispatchable_graph::SparseGraph& g, const std::vector<Time>& h) {
  const std::size_t n = g.out.size();
  constexpr std::size_t kUnseen = SIZE_MAX;
  std::vector<std::size_t> order(n, kUnseen), low(n, 0), stack;
  std::vector<bool> on_stack(n, false);
  std::vector<std::pair<std::size_t, std::size_t>> frames;  // timepoint, next arc
  std::vector<std::size_t> component(n, 0);
  std::size_t counter = 0, components = 0;
  auto zero = [&](std::size_t u, const dispatchable_graph::Arc& a) {
    return a.weight + h[u] - h[a.to] == 0;
  };
  for (std::size_t root = 0; root < n; ++root) {
    if (order[root] != kUnseen) continue;
    frames.push_back({root, 0});
    order[root] = low[root] = counter++;
    stack.push_back(root);
    on_stack[root] = true;
    while (!frames.empty()) {
      auto& [u, next] = frames.back();
      if (next < g.out[u].size()) {
        const dispatchable_graph::Arc& a = g.out[u][next++];
        if (!zero(u, a)) continue;
        if (order[a.to] == kUnseen) {
          order[a.to] = low[a.to] = counter++;
          stack.push_back(a.to);
          on_stack[a.to] = true;
          frames.push_back({a.to, 0});
        } else if (on_stack[a.to]) {
          low[u] = std::min(low[u], order[a.to]);
        }
        continue;
      }
      std::size_t v = u;
      frames.pop_back();
      if (!frames.empty()) low[frames.back().first] = std::min(low[frames.back().first], low[v]);
      if (low[v] != order[v]) continue;
      std::size_t w;
      do {
        w = stack.back();
        stack.pop_back();
        on_stack[w] = false;
        component[w] = components;
      } while (w != v);
      ++components;
    }
  }
  RigidClasses r;
  r.count = components;
  r.of.resize(n);
  for (std::size_t v = 0; v < n; ++v)
    r.of[v] = static_cast<std::uint32_t>(components - 1 - component[v]);
  return r;
}

// The distance graph with every rigid class collapsed to one node and the weights reduced by
// the potentials (all >= 0), parallel arcs merged. Since D(x,y) = D(rX,rY) - o_x + o_y for x in
// class X at offset o_x = D(rX,x) = h[x] - h[rX] from its representative, every closure entry
// is D(x,y) = R(X,Y) + h[y] - h[x], R the reduced distance between the classes: the closure
// of the whole plan is the closure of this smaller graph.
struct ClassGraph {
  std::vector<std::size_t> first;  // CSR: arcs of class X are [first[X], first[X + 1])
  std::vector<std::uint32_t> to;
  std::vector<Time> weight;
};

ClassGraph class_graph(const dispatchable_graph::SparseGraph& g, const std::vector<Time>& h,
                       const RigidClasses& rc) {
  struct Entry {
    std::uint32_t from, to;
    Time weight;
  };
  std::vector<Entry> arcs;
  for (std::size_t u = 0; u < g.out.size(); ++u)
    for (const dispatchable_graph::Arc& a : g.out[u])
      if (rc.of[u] != rc.of[a.to])
        arcs.push_back({rc.of[u], rc.of[a.to], a.weight + h[u] - h[a.to]});
  std::sort(arcs.begin(), arcs.end(), [](const Entry& x, const Entry& y) {
    return x.from != y.from ? x.from < y.from : x.to != y.to ? x.to < y.to : x.weight < y.weight;
  });
  ClassGraph cg;
  cg.first.assign(rc.count + 1, 0);
  for (std::size_t i = 0; i < arcs.size(); ++i) {
    if (i > 0 && arcs[i].from == arcs[i - 1].from && arcs[i].to == arcs[i - 1].to) continue;
    ++cg.first[arcs[i].from + 1];
    cg.to.push_back(arcs[i].to);
    cg.weight.push_back(arcs[i].weight);
  }
  for (std::size_t x = 0; x < rc.count; ++x) cg.first[x + 1] += cg.first[x];
  return cg;
}

// The triangle rule of Muscettola, Morris and Pollack, as the construction always applied it:
// A->C (C not rigid with A) is dominated when some B, rigid with neither, lies on a shortest
// path from A to C (D(A,B) + D(B,C) = D(A,C)) and either A->C >= 0 and B->C >= 0, or A->C < 0
// and A->B < 0. In class terms (X, Y, Z the classes of A, C, B; R reduced distances) B lies on
// a shortest path exactly when Z lies strictly inside a shortest class path from X to Y, and
//   B->C >= 0  <=>  R(X,Z) + h[B] <= R(X,Y) + h[C],     A->B < 0  <=>  R(X,Z) + h[B] < h[A],
// so both tests need only mu(X,Y) = min of R(X,Z) + min_{B in Z} h[B] over the classes Z inside
// a shortest path from X to Y:
//   A->C >= 0 is dominated  <=>  mu(X,Y) <= R(X,Y) + h[C],   A->C < 0  <=>  mu(X,Y) < h[A].
// mu is carried along the shortest-path DAG by the Dijkstra from X itself (Tsamardinos,
// Muscettola and Morris's predecessor-graph idea), which needs the classes taken from the queue
// in a topological order of the tight arcs: by R, then by class number (an arc of positive
// reduced weight raises R; those of zero weight go up in class number). Both go into one
// integer key, K R + class with K >= classes, i.e. the arc weights K w + class(to) -
// class(from), all >= 0; then a class's mu is complete when it leaves the queue. One Dijkstra
// per rigid class, no n x n matrix.
constexpr Time kNoMu = std::numeric_limits<Time>::max();
__extension__ typedef unsigned __int128 Wide;  // keys too long for 64 bits

// Monotone priority queue for Dijkstra's integer keys (radix heap, Ahuja, Mehlhorn, Orlin and
// Tarjan 1990): an entry sits in the bucket of the highest bit where its key differs from the
// last key taken; taking from an empty bucket 0 redistributes the first non-empty bucket.
template <typename Key>
class RadixQueue {
 public:
  void reset() { last_ = 0; }
  bool empty() const {
    for (const auto& b : buckets_)
      if (!b.empty()) return false;
    return true;
  }
  void push(Key key, std::uint32_t value) { buckets_[bucket(key)].push_back({key, value}); }
  // Smallest key first; false when empty.
  bool pop(Key* key, std::uint32_t* value) {
    if (buckets_[0].empty()) {
      std::size_t i = 1;
      while (i < kBuckets && buckets_[i].empty()) ++i;
      if (i == kBuckets) return false;
      Key least = buckets_[i][0].first;
      for (const auto& e : buckets_[i]) least = std::min(least, e.first);
      last_ = least;
      for (const auto& e : buckets_[i]) buckets_[bucket(e.first)].push_back(e);
      buckets_[i].clear();
    }
    *key = buckets_[0].back().first;
    *value = buckets_[0].back().second;
    buckets_[0].pop_back();
    return true;
  }

 private:
  static constexpr std::size_t kBits = sizeof(Key) * 8, kBuckets = kBits + 1;
  static std::size_t width(std::uint64_t v) {
    return v == 0 ? 0 : 64 - static_cast<std::size_t>(__builtin_clzll(v));
  }
  std::size_t bucket(Key key) const {
    const Key diff = key ^ last_;
    if constexpr (sizeof(Key) > 8) {
      const auto high = static_cast<std::uint64_t>(diff >> 64);
      if (high != 0) return 64 + width(high);
    }
    return width(static_cast<std::uint64_t>(diff));
  }
  Key last_ = 0;
  std::array<std::vector<std::pair<Key, std::uint32_t>>, kBuckets> buckets_;
};

// One Dijkstra per source class over the class graph, keys of type Key (64 bits when K times
// the longest possible distance fits, else 128).
template <typename Key>
class ClassRows {
 public:
  ClassRows(const ClassGraph& cg, std::vector<Time> min_h)
      : dist(min_h.size()),
        mu(min_h.size()),
        cg_(cg),
        min_h_(std::move(min_h)),
        key_(min_h_.size()),
        done_(min_h_.size()) {
    shift_ = 0;
    while ((std::size_t{1} << shift_) < min_h_.size()) ++shift_;
    arc_key_.resize(cg.to.size());
    for (std::uint32_t u = 0; u + 1 < cg.first.size(); ++u)
      for (std::size_t i = cg.first[u]; i < cg.first[u + 1]; ++i)
        arc_key_[i] = (static_cast<Key>(cg.weight[i]) << shift_) + Key{cg.to[i]} - Key{u};
  }

  // dist[Y] = R(X,Y) (kNoMu when unreachable), mu[Y] as above (kNoMu when no class inside).
  void run(std::uint32_t x) {
    const Key kUnreached = ~Key{0};
    std::fill(key_.begin(), key_.end(), kUnreached);
    std::fill(mu.begin(), mu.end(), kNoMu);
    std::fill(done_.begin(), done_.end(), 0);
    queue_.reset();
    key_[x] = x;
    queue_.push(key_[x], x);
    Key kp;
    std::uint32_t p;
    while (queue_.pop(&kp, &p)) {
      if (done_[p] || kp != key_[p]) continue;
      done_[p] = 1;
      const Time rp = static_cast<Time>((kp - p) >> shift_);
      const Time carried = p == x ? kNoMu : std::min(mu[p], rp + min_h_[p]);
      for (std::size_t i = cg_.first[p]; i < cg_.first[p + 1]; ++i) {
        const std::uint32_t v = cg_.to[i];
        const Key nk = kp + arc_key_[i];
        if (nk < key_[v]) {
          key_[v] = nk;
          mu[v] = carried;
          queue_.push(nk, v);
        } else if (nk == key_[v] && carried < mu[v]) {
          mu[v] = carried;
        }
      }
    }
    for (std::size_t y = 0; y < dist.size(); ++y)
      dist[y] = key_[y] == kUnreached ? kNoMu : static_cast<Time>((key_[y] - y) >> shift_);
  }

  std::vector<Time> dist, mu;

 private:
  const ClassGraph& cg_;
  std::vector<Time> min_h_;
  std::vector<Key> key_, arc_key_;
  std::vector<char> done_;
  std::size_t shift_ = 0;
  RadixQueue<Key> queue_;
};

// Every closure edge A->C (finite distance), kept unless dominated (filter), into out[A] in
// the order of C; the windows from the origin's row and column. With A in X, C in Y != X,
// R = R(X,Y) and mu = mu(X,Y) finite, the rule above keeps A->C exactly when
// R + h[C] < mu and h[A] <= mu (a negative A->C has R + h[C] < h[A]; a non-negative one,
// R + h[C] >= h[A]): the kept targets in Y are those of least h, so per class only a prefix of
// its timepoints sorted by h is looked at, not all n.
template <typename Key>
void closure_edges(const ClassGraph& cg, const RigidClasses& rc,
                   const std::vector<std::vector<std::size_t>>& members, std::vector<Time> min_h,
                   const std::vector<Time>& pot, bool filter, DispatchableNetwork* net,
                   std::vector<std::vector<DistanceEdge>>* out) {
  const std::size_t n = pot.size();
  ClassRows<Key> rows(cg, std::move(min_h));
  std::vector<std::vector<std::size_t>> by_h = members;
  for (auto& list : by_h)
    std::sort(list.begin(), list.end(), [&](std::size_t p, std::size_t q) {
      return pot[p] != pot[q] ? pot[p] < pot[q] : p < q;
    });
  const std::uint32_t origin_class = rc.of[0];
  for (std::uint32_t x = 0; x < rc.count; ++x) {
    rows.run(x);
    const std::vector<Time>& dist = rows.dist;
    const std::vector<Time>& mu = rows.mu;
    if (x == origin_class)
      for (std::size_t c = 0; c < n; ++c)
        if (dist[rc.of[c]] != kNoMu) net->latest[c] = dist[rc.of[c]] + pot[c] - pot[0];
    for (std::size_t a : members[x]) {
      if (dist[origin_class] != kNoMu) net->earliest[a] = -(dist[origin_class] + pot[0] - pot[a]);
      const Time ha = pot[a];
      std::vector<DistanceEdge>& list = (*out)[a];
      if (!filter) {
        for (std::size_t c = 0; c < n; ++c)
          if (c != a && dist[rc.of[c]] != kNoMu)
            list.push_back({a, c, dist[rc.of[c]] + pot[c] - ha});
        net->closed_edges += list.size();
        continue;
      }
      for (std::uint32_t y = 0; y < rc.count; ++y) {
        const Time r = dist[y], m = mu[y];
        if (r == kNoMu) continue;
        net->closed_edges += members[y].size() - (y == x ? 1 : 0);
        if (y == x || m == kNoMu) {
          for (std::size_t c : members[y])
            if (c != a) list.push_back({a, c, r + pot[c] - ha});
        } else if (ha <= m) {
          for (std::size_t c : by_h[y]) {
            if (r + pot[c] >= m) break;
            list.push_back({a, c, r + pot[c] - ha});
          }
        }
      }
      std::sort(list.begin(), list.end(),
                [](const DistanceEdge& p, const DistanceEdge& q) { return p.to < q.to; });
    }
  }
}

}  // namespace

namespace dispatchable_graph {

std::optional<PlanGraph> plan_graph(const planner::FlexiblePlan& plan, DispatchableNetwork* out,
                                    std::string* error) {
  DispatchableNetwork& net = *out;
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
  return PlanGraph{std::move(g), std::move(*h)};
}

}  // namespace dispatchable_graph

std::optional<DispatchableNetwork> make_dispatchable(const planner::FlexiblePlan& plan,
                                                     std::string* error, bool filter) {
  DispatchableNetwork net;
  auto pg = dispatchable_graph::plan_graph(plan, &net, error);
  if (!pg) return std::nullopt;
  const std::size_t n = net.names.size();
  const dispatchable_graph::SparseGraph& g = pg->graph;
  const std::vector<Time>& pot = pg->potentials;
  const RigidClasses rc = rigid_classes(g, pot);
  const ClassGraph cg = class_graph(g, pot, rc);
  std::vector<Time> min_h(rc.count, kNoMu);
  std::vector<std::vector<std::size_t>> members(rc.count);
  for (std::size_t v = 0; v < n; ++v) {
    min_h[rc.of[v]] = std::min(min_h[rc.of[v]], pot[v]);
    members[rc.of[v]].push_back(v);
  }
  net.earliest.assign(n, -kUnbounded);
  net.latest.assign(n, kUnbounded);
  // Keys of 64 bits when K (2^shift >= classes) times the longest possible class distance, plus
  // the class, stays below the 64-bit "unreached"; else 128.
  std::size_t shift = 0;
  while ((std::size_t{1} << shift) < rc.count) ++shift;
  Wide longest = 0, heaviest = 0;
  for (Time w : cg.weight) {
    longest += static_cast<Wide>(w);
    heaviest = std::max(heaviest, static_cast<Wide>(w));
  }
  longest = std::min(longest, heaviest * rc.count);
  std::vector<std::vector<DistanceEdge>> out(n);
  if (((longest + 1) << shift) + rc.count < Wide{std::numeric_limits<std::uint64_t>::max()})
    closure_edges<std::uint64_t>(cg, rc, members, std::move(min_h), pot, filter, &net, &out);
  else
    closure_edges<Wide>(cg, rc, members, std::move(min_h), pot, filter, &net, &out);
  std::size_t total = 0;
  for (const auto& list : out) total += list.size();
  net.edges.reserve(total);
  for (const auto& list : out) net.edges.insert(net.edges.end(), list.begin(), list.end());
  return net;
}

}  // namespace autonomy::executive
