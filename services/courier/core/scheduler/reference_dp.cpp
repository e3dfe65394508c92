#include "services/courier/core/scheduler/reference_dp.hpp"

#include "services/courier/core/scheduler/route_search.hpp"

#include <unordered_map>

namespace autonomy::courier::scheduling {

namespace {

struct Node {
  detail::RouteState state;
  std::uint32_t picked = 0;
  std::uint32_t delivered = 0;
  int last = -1;  // local stop index: 2 * job + (delivery ? 1 : 0)
  int parent = -1;
  StopRef stop;
};

}  // namespace

ReferenceDpResult reference_dp(const SchedulingProblem& problem, int courier) {
  ReferenceDpResult out;
  if (!problem_error(problem).empty()) return out;
  const SearchBudget budget;
  detail::RouteSearch rs(problem, budget);
  const auto& sim = rs.sim();
  std::vector<int> jobs;
  for (int j : rs.free_jobs())
    if (rs.allowed(courier, j)) jobs.push_back(j);
  if (jobs.size() > 26) return out;  // the state key packs 2 x 26 bits + the last stop
  const int capacity = problem.couriers[static_cast<std::size_t>(courier)].capacity;
  detail::RouteState start = sim.start(courier);
  for (StopRef s : problem.couriers[static_cast<std::size_t>(courier)].forced_prefix)
    if (!rs.step(courier, start, s)) return out;
  std::vector<Node> arena;
  Node root;
  root.state = start;
  for (std::size_t i = 0; i < jobs.size(); ++i)
    if (start.carries(jobs[i])) root.picked |= 1u << i;
  arena.push_back(root);
  const std::uint32_t all = (1u << jobs.size()) - 1u;
  std::vector<int> layer{0};
  for (std::size_t depth = 0; !layer.empty(); ++depth) {
    // key: (picked, delivered, last) -> node indices (Pareto set)
    std::unordered_map<std::uint64_t, std::vector<int>> next;
    for (int index : layer) {
      const Node node = arena[static_cast<std::size_t>(index)];
      if (node.delivered == all) {
        if (!out.feasible || better(node.state.cost, out.best)) {
          out.feasible = true;
          out.best = node.state.cost;
          out.route.clear();
          for (int k = index; k > 0; k = arena[static_cast<std::size_t>(k)].parent)
            out.route.insert(out.route.begin(), arena[static_cast<std::size_t>(k)].stop);
        }
        continue;
      }
      for (std::size_t i = 0; i < jobs.size(); ++i) {
        if (node.delivered >> i & 1u) continue;
        const bool deliver = node.picked >> i & 1u;
        if (!deliver && (node.state.load >= capacity || !sim.may_pick_up(node.state, jobs[i])))
          continue;
        Node child = node;
        child.stop = {jobs[i], deliver ? StopKind::kDelivery : StopKind::kPickup};
        if (!sim.advance(child.state, child.stop)) continue;
        if (deliver)
          child.delivered |= 1u << i;
        else
          child.picked |= 1u << i;
        child.last = static_cast<int>(2 * i + (deliver ? 1 : 0));
        child.parent = index;
        const std::uint64_t key = (static_cast<std::uint64_t>(child.picked) |
                                   static_cast<std::uint64_t>(child.delivered) << 26) *
                                      64 +
                                  static_cast<std::uint64_t>(child.last);
        auto& labels = next[key];
        bool dominated = false;
        for (int l : labels) {
          const auto& o = arena[static_cast<std::size_t>(l)].state;
          if (o.t <= child.state.t + 1e-9 && compare(o.cost, child.state.cost) <= 0)
            dominated = true;
        }
        if (dominated) continue;
        std::vector<int> kept;
        for (int l : labels) {
          const auto& o = arena[static_cast<std::size_t>(l)].state;
          if (!(child.state.t <= o.t + 1e-9 && compare(child.state.cost, o.cost) <= 0))
            kept.push_back(l);
        }
        arena.push_back(child);
        ++out.labels;
        kept.push_back(static_cast<int>(arena.size() - 1));
        labels = std::move(kept);
      }
    }
    layer.clear();
    for (auto& entry : next) layer.insert(layer.end(), entry.second.begin(), entry.second.end());
  }
  std::vector<StopRef> full = problem.couriers[static_cast<std::size_t>(courier)].forced_prefix;
  full.insert(full.end(), out.route.begin(), out.route.end());
  out.route = std::move(full);
  return out;
}

}  // namespace autonomy::courier::scheduling
