#pragma once
// Search engines behind one small interface (paper, section 4: the token network's three
// decision operations are all a search engine needs, so engines are interchangeable).
//
// An engine searches from the network's current state for a state without flaws; on success
// it leaves the network in that state (the plan), otherwise it restores the starting state.
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "token_network.hpp"

namespace autonomy::planner {

// When to give up: a decision budget and/or a predicate the caller evaluates (a deadline on
// the caller's clock, a cancellation flag). One value, passed to every solve().
struct Termination {
  std::size_t max_decisions = static_cast<std::size_t>(-1);
  std::function<bool()> stop;  // true: stop now
  bool should_stop(std::size_t decisions) const {
    return decisions >= max_decisions || (stop && stop());
  }
};

struct SearchStatistics {
  std::size_t decisions = 0, backtracks = 0, dead_ends = 0, plans = 0;
  std::size_t temporal_propagations = 0, procedure_calls = 0;
};

// The propagation work of one solve(): the network's totals at its start, subtracted at its end.
class PropagationCount {
 public:
  explicit PropagationCount(const TokenNetwork& net)
      : temporal_(net.temporal().propagations()),
        procedures_(net.constraints().statistics().procedure_calls) {}
  void record(const TokenNetwork& net, SearchStatistics& s) const {
    s.temporal_propagations = net.temporal().propagations() - temporal_;
    s.procedure_calls = net.constraints().statistics().procedure_calls - procedures_;
  }

 private:
  std::size_t temporal_, procedures_;
};

enum class SearchStatus { kPlanFound, kExhausted, kOutOfBudget };

struct SearchOutcome {
  SearchStatus status = SearchStatus::kExhausted;
  SearchStatistics statistics;
};

class SearchEngine {
 public:
  virtual ~SearchEngine() = default;
  virtual std::string name() const = 0;
  [[nodiscard]] virtual SearchOutcome solve(TokenNetwork& network,
                                            const Termination& termination) = 0;
};

// Picks the flaw to work on next among the network's flaws (never empty).
using FlawSelector = std::function<std::size_t(const TokenNetwork&, const std::vector<Flaw>&)>;
// The default: flaws that decide whether a schema applies, then open disjunctions, then free
// tokens by earliest possible start (ties: least slack), then resource conflicts, then other
// unbound parameters.
FlawSelector earliest_first_selector();

struct EngineOptions {
  FlawSelector selector;          // empty: earliest_first_selector()
  unsigned seed = 1;              // for engines that sample
  std::size_t discrepancies = 2;  // limited discrepancy search: the most allowed per probe
  std::size_t restarts = 1000;    // iterative sampling: probes per solve()
  // Large-neighbourhood search: the decision budget of each neighbourhood's re-planning.
  std::size_t neighbourhood_decisions = 300;
  // Large-neighbourhood search on a makespan problem: greedy dives by active schedule
  // generation (active_schedule.hpp) for the first plan, the best kept; 0: the chronological
  // engine's first plan.
  std::size_t first_dives = 8;
  // The chronological engine with conflict-directed backjumping (backjumping.cpp): the same
  // flaw and option order, but an exhausted decision point goes back to the latest decision
  // its failures depend on. Off by default: see docs/planner-search.md for what it measured.
  bool backjumping = false;
  // Iterative repair reports each decision it applies, why it took that option (the memory of
  // the previous plan's choice, the heuristic's order, or a repair of a culprit) and whether
  // it applied (its propagation succeeded).
  enum class Choice { kRemembered, kHeuristic, kRepair };
  std::function<void(const Decision&, Choice, bool applied)> on_decision;
};

// "chronological" (depth-first with chronological backtracking, the Remote Agent's),
// "discrepancy" (limited discrepancy search, Harvey 1995), "sampling" (heuristic-biased
// iterative sampling with seeded restarts; incomplete), "repair" (iterative repair: at a dead
// end one culprit decision changes and the rest of the plan is re-applied; incomplete, its
// backtracks count the repairs; iterative_repair.cpp) or "lns" (large-neighbourhood search:
// a greedy first plan (the best of a few active-schedule dives on a makespan problem, else the
// chronological engine's), then parts of the best plan relaxed and re-planned (by the
// chronological engine or by greedy dives) under a small budget, anytime; complete through
// full searches with doubling budgets; large_neighbourhood.cpp). Null for an unknown name.
std::unique_ptr<SearchEngine> make_search_engine(const std::string& name,
                                                 const EngineOptions& options = {});
std::vector<std::string> search_engine_names();

}  // namespace autonomy::planner
