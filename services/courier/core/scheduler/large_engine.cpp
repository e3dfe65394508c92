// The large-scale engine: greedy parallel dispatch (or the previous schedule, repaired, or when
// both fail the order the job selection found: job_selection.hpp), local descent (stop moves, job
// relocation across couriers), then ruin and recreate until the budget or a number of rounds
// without improvement. Anytime: the best routes so far are always complete. Never infeasible while
// a schedule exists: the selection's search is complete, and only its proof says infeasible.
#include "services/courier/core/scheduler/route_search.hpp"

#include <algorithm>

namespace autonomy::courier::scheduling::detail {

namespace {

// The previous schedule with what is no longer valid dropped and the missing jobs inserted where
// they cost least. A job is kept only if all of its stops are on one courier in a usable order.
bool repaired_previous(RouteSearch& search, Routes& out) {
  const SchedulingProblem& p = search.problem();
  if (p.previous_order.size() != p.couriers.size()) return false;
  std::vector<int> free_mask(p.jobs.size(), 0);
  for (int j : search.free_jobs()) free_mask[static_cast<std::size_t>(j)] = 1;
  out.assign(p.couriers.size(), {});
  std::vector<int> placed(p.jobs.size(), 0);  // courier + 1
  for (std::size_t c = 0; c < p.couriers.size(); ++c) {
    out[c] = p.couriers[c].forced_prefix;
    std::vector<int> pick_seen(p.jobs.size(), 0);
    std::vector<StopRef> kept;
    for (StopRef s : p.previous_order[c]) {
      if (s.job < 0 || static_cast<std::size_t>(s.job) >= p.jobs.size()) continue;
      const auto j = static_cast<std::size_t>(s.job);
      if (!free_mask[j] || placed[j] || !search.allowed(static_cast<int>(c), s.job)) continue;
      const bool aboard = search.delivery_only(s.job);
      if (s.kind == StopKind::kPickup) {
        if (aboard || pick_seen[j]) continue;
        pick_seen[j] = 1;
        kept.push_back(s);
      } else if (aboard || pick_seen[j]) {
        kept.push_back(s);
        placed[j] = static_cast<int>(c) + 1;
      }
    }
    for (StopRef s : kept)
      if (placed[static_cast<std::size_t>(s.job)] == static_cast<int>(c) + 1) out[c].push_back(s);
  }
  for (int j : search.free_jobs()) {
    if (placed[static_cast<std::size_t>(j)]) continue;
    int best_c = -1;
    RouteSearch::Insertion best;
    for (std::size_t c = 0; c < out.size(); ++c) {
      RouteSearch::Insertion ins;
      if (search.best_insertion(static_cast<int>(c), out[c], j, -1, ins) &&
          (best_c < 0 || better(ins.cost, best.cost)))
        best_c = static_cast<int>(c), best = ins;
    }
    if (best_c < 0) return false;
    RouteSearch::apply(out[static_cast<std::size_t>(best_c)], j, best);
  }
  std::vector<Objective> costs;
  Objective total;
  return search.total_cost(out, costs, total);
}

int window_for(const RouteSearch& search) {
  const std::size_t stops_per_courier =
      2 * search.free_jobs().size() / std::max<std::size_t>(1, search.problem().couriers.size());
  return stops_per_courier > 40 ? 6 : -1;
}

class LargeEngine final : public SchedulerEngine {
 public:
  const char* name() const override { return "large"; }
  JobSchedule solve(const SchedulingProblem& problem, const SearchBudget& budget) override {
    if (std::string e = problem_error(problem); !e.empty())
      return failed_schedule(problem, ScheduleStatus::kInvalidProblem, e, name(), 0);
    RouteSearch search(problem, budget);
    Routes routes;
    if (!large_search(search, routes, 400)) {
      const JobSelection& sel = search.selection();
      return failed_schedule(
          search, sel.proved ? ScheduleStatus::kInfeasible : ScheduleStatus::kNoSolution,
          sel.reason.empty() ? "no order of the stops satisfies every constraint" : sel.reason,
          name());
    }
    return finish_schedule(search, routes, name(), false);
  }
};

}  // namespace

bool large_search(RouteSearch& search, Routes& routes, int stale_limit) {
  Routes start;
  std::vector<Objective> costs;
  Objective total;
  bool have = search.greedy(start) && search.total_cost(start, costs, total);
  Routes previous;
  if (repaired_previous(search, previous)) {
    std::vector<Objective> prev_costs;
    Objective prev_total;
    if (search.total_cost(previous, prev_costs, prev_total) &&
        (!have || better(prev_total, total))) {
      start = std::move(previous);
      costs = std::move(prev_costs);
      total = prev_total;
      have = true;
    }
  }
  if (!have && search.selection().feasible) {
    start = search.selection().witness;
    have = search.total_cost(start, costs, total);
  }
  if (!have) return false;
  const int window = window_for(search);
  search.descend(start, costs, window);
  search.ruin_and_recreate(start, costs, window, stale_limit);
  routes = std::move(start);
  return true;
}

std::unique_ptr<SchedulerEngine> make_large_engine() {
  return std::make_unique<LargeEngine>();
}

}  // namespace autonomy::courier::scheduling::detail
