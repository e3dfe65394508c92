#include "services/courier/core/scheduler/scheduler_engine.hpp"

#include "services/courier/core/scheduler/route_search.hpp"

namespace autonomy::courier::scheduling {

std::unique_ptr<SchedulerEngine> make_scheduler_engine(const std::string& name) {
  if (name == "exact") return detail::make_exact_engine();
  if (name == "large") return detail::make_large_engine();
  if (name == "paper") return detail::make_paper_engine();
  return nullptr;
}

std::vector<std::string> scheduler_engine_names() {
  return {"exact", "large", "paper"};
}

OpportunityCheck check_opportunity(const SchedulingProblem& problem, int courier,
                                   const std::vector<StopRef>& stops, SchedulerEngine& engine,
                                   const SearchBudget& budget) {
  OpportunityCheck out;
  out.without_detour = engine.solve(problem, budget);
  SchedulingProblem detour = problem;
  if (courier >= 0 && static_cast<std::size_t>(courier) < detour.couriers.size()) {
    auto& prefix = detour.couriers[static_cast<std::size_t>(courier)].forced_prefix;
    prefix.insert(prefix.end(), stops.begin(), stops.end());
  }
  out.with_detour = engine.solve(detour, budget);
  if (!out.without_detour.ok() || !out.with_detour.ok()) {
    out.keeps_deadlines = out.with_detour.ok();
    return out;
  }
  // Every job on time without the detour is scheduled and on time with it (the detour may make
  // a job clash with it: left out, it is not kept either).
  out.keeps_deadlines = true;
  for (const JobOutcome& before : out.without_detour.outcomes) {
    if (before.late) continue;
    bool on_time = false;
    for (const JobOutcome& after : out.with_detour.outcomes)
      if (after.job == before.job) on_time = !after.late;
    if (!on_time) out.keeps_deadlines = false;
  }
  return out;
}

}  // namespace autonomy::courier::scheduling
