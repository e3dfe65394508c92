// Large-neighbourhood search (Shaw 1998; for scheduling with precedence relaxation: Godard,
// Laborie and Nuijten 2005): anytime improvement of the best plan for problems too big to prove.
//
//  - The first solve() on a makespan problem is the best of a few greedy dives by active
//    schedule generation (active_schedule.hpp; the chronological engine's earliest-start first
//    plan is far worse, abz5 2322 against 1564, optimum 1234). When the first dive meets a dead
//    end, and on problems without a makespan objective, it is the chronological engine's
//    (complete): its plan, or its proof that there is none (explained as with that engine).
//    The engine then remembers the plan's order on every timeline (the tokens
//    that exist before any decision, problem facts and their forced slaves, named by their ids,
//    which the anytime loop's undo to the root keeps).
//  - A later solve() (the loop has tightened the makespan bound below the remembered plan)
//    relaxes part of that plan and re-plans it: a neighbourhood is a set of tokens (those
//    starting in a window of the plan's time, those of a few random timelines, or a random
//    sample). The other tokens keep their order on their timelines (each consecutive kept pair
//    is ordered, a kOrder decision); the relaxed ones, the slaves and every other choice are
//    left to the chronological engine, every other neighbourhood to greedy dives drawn around
//    the active schedule rule, under a small decision budget. A plan found there is an
//    improvement (the bound is in the network): it is returned and remembered. Else the next
//    neighbourhood is tried.
//  - The neighbourhood's size adapts: a sub-search that exhausts its neighbourhood (nothing
//    better there) makes the next one larger, a chronological one that runs out of budget
//    makes it smaller.
//  - Completeness is kept by full searches from the root (no kept orders) with a budget that
//    doubles each time, run when the neighbourhoods have grown to the whole plan or have spent
//    four times the last full search's budget since it; an exhausted full search proves the
//    last plan optimal (or the problem infeasible), as the chronological engine would.
//
// The plan returned keeps the orders the neighbourhood kept (they are part of the network), so
// its flexible bounds can be narrower than those of the same schedule found by another engine.
// Resource orderings and parameter choices are not remembered: the sub-search makes them again.
#include "large_neighbourhood.hpp"

#include "active_schedule.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>

namespace autonomy::planner {
namespace {

constexpr double kStartFraction = 0.2;  // of the remembered tokens relaxed at first
constexpr double kMinFraction = 0.05, kGrowth = 1.15;
constexpr std::size_t kFullSearchShare = 4;  // neighbourhood effort per full-search decision
constexpr std::size_t kFirstFullBudget = 1000;


class LargeNeighbourhood final : public SearchEngine {
 public:
  explicit LargeNeighbourhood(const EngineOptions& options)
      : options_(options),
        rng_(options.seed),
        inner_(make_search_engine("chronological", options)) {}
  std::string name() const override { return "lns"; }
  SearchOutcome solve(TokenNetwork& net, const Termination& term) override;

 private:
  struct Remembered {
    std::size_t root_tokens = 0;
    std::vector<std::vector<TokenId>> sequences;  // per timeline, root tokens only
    std::vector<std::pair<Time, TokenId>> by_start;
  };

  void remember(const TokenNetwork& net, std::size_t root_tokens) {
    Remembered r;
    r.root_tokens = root_tokens;
    for (const Timeline& tl : net.timelines()) {
      r.sequences.emplace_back();
      for (TokenId id : tl.sequence) {
        if (id >= root_tokens) continue;
        r.sequences.back().push_back(id);
        r.by_start.push_back({net.temporal().earliest(net.tokens()[id].start), id});
      }
    }
    std::sort(r.by_start.begin(), r.by_start.end());
    best_ = std::move(r);
  }

  // The tokens to relax: about fraction_ of the remembered ones.
  std::vector<char> neighbourhood() {
    const Remembered& b = *best_;
    std::vector<char> relaxed(b.root_tokens, 0);
    const std::size_t n = b.by_start.size();
    if (n == 0) return relaxed;
    // At least two tokens (one alone keeps its place), at most all (std::clamp needs 2 <= n).
    const std::size_t k =
        std::min(n, std::max<std::size_t>(2, std::size_t(std::ceil(fraction_ * double(n)))));
    switch (std::uniform_int_distribution<int>(0, 2)(rng_)) {
      case 0: {  // a window of the plan's time
        const std::size_t first = std::uniform_int_distribution<std::size_t>(0, n - k)(rng_);
        for (std::size_t i = first; i < first + k; ++i) relaxed[b.by_start[i].second] = 1;
        break;
      }
      case 1: {  // whole timelines, in random order, until k tokens
        std::vector<std::size_t> order(b.sequences.size());
        for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
        std::shuffle(order.begin(), order.end(), rng_);
        std::size_t taken = 0;
        for (std::size_t tl : order) {
          if (taken >= k) break;
          for (TokenId id : b.sequences[tl]) relaxed[id] = 1;
          taken += b.sequences[tl].size();
        }
        break;
      }
      default: {  // a random sample
        std::vector<TokenId> ids;
        for (const auto& [start, id] : b.by_start) ids.push_back(id);
        std::shuffle(ids.begin(), ids.end(), rng_);
        for (std::size_t i = 0; i < k; ++i) relaxed[ids[i]] = 1;
      }
    }
    return relaxed;
  }

  // Orders each consecutive pair of kept tokens on every timeline. False when the remembered
  // order no longer fits (the tighter bound), which rules the neighbourhood out.
  bool keep_orders(TokenNetwork& net, const std::vector<char>& relaxed, SearchStatistics& stats) {
    for (const std::vector<TokenId>& seq : best_->sequences) {
      TokenId previous = kNoToken;
      for (TokenId id : seq) {
        if (relaxed[id]) continue;
        if (previous != kNoToken) {
          ++stats.decisions;
          if (!net.apply({Decision::Kind::kOrder, previous, id})) {
            ++stats.dead_ends;
            return false;
          }
        }
        previous = id;
      }
    }
    return true;
  }

  // The best of first_dives greedy dives by active schedule generation (active_schedule.hpp),
  // left in the network. False when the first dive meets a dead end (or the budget ends): the
  // chronological engine then finds the first plan or proves there is none, as without dives.
  bool first_plan_by_dives(TokenNetwork& net, const Termination& term, SearchStatistics& stats) {
    const FlawSelector rule = active_schedule_selector(), drawn = active_schedule_selector(&rng_);
    const TokenNetwork::Mark start = net.mark();
    std::vector<Decision> best, dive;
    Time best_makespan = kInfinity;
    for (std::size_t k = 0; k < options_.first_dives; ++k) {
      if (!greedy_dive(net, k == 0 ? rule : drawn, term, stats, &dive)) {
        if (k == 0) return false;
        continue;
      }
      Time makespan = 0;
      for (const Token& t : net.tokens())
        if (t.state == Token::State::kPlaced)
          makespan = std::max(makespan, net.temporal().earliest(t.end));
      if (makespan < best_makespan) {
        best_makespan = makespan;
        best.swap(dive);
      }
      net.undo_to(start);
    }
    // The dives are deterministic in the network's state: the best one's decisions apply again.
    for (const Decision& d : best) {
      ++stats.decisions;
      if (!net.apply(d)) {
        net.undo_to(start);
        return false;
      }
    }
    return true;
  }

  // Greedy dives with the drawn rule until one finds a plan (under the bound: a better one) or
  // the neighbourhood's budget is spent. A dead end ends a dive, not the neighbourhood.
  SearchStatus dives(TokenNetwork& net, const Termination& term, SearchStatistics& stats) {
    const std::size_t start = stats.decisions;
    const FlawSelector drawn = active_schedule_selector(&rng_);
    while (stats.decisions - start < options_.neighbourhood_decisions &&
           !term.should_stop(stats.decisions))
      if (greedy_dive(net, drawn, term, stats, nullptr)) return SearchStatus::kPlanFound;
    return SearchStatus::kOutOfBudget;
  }

  EngineOptions options_;
  std::mt19937 rng_;
  std::unique_ptr<SearchEngine> inner_;
  std::size_t neighbourhoods_ = 0;
  std::optional<Remembered> best_;
  double fraction_ = kStartFraction;
  std::size_t full_budget_ = kFirstFullBudget, since_full_ = 0;
};

SearchOutcome LargeNeighbourhood::solve(TokenNetwork& net, const Termination& term) {
  const PropagationCount count(net);
  SearchOutcome out;
  SearchStatistics& stats = out.statistics;
  const TokenNetwork::Mark root = net.mark();
  auto finish = [&](SearchStatus status) {
    if (status != SearchStatus::kPlanFound) net.undo_to(root);
    out.status = status;
    count.record(net, stats);
    return out;
  };
  // The inner engine under `budget` decisions, within what is left of the caller's.
  auto run_inner = [&](std::size_t budget, SearchEngine& engine) {
    Termination inner = term;
    const std::size_t left =
        term.max_decisions - std::min(term.max_decisions, stats.decisions);
    inner.max_decisions = std::min(budget, left);
    SearchOutcome o = engine.solve(net, inner);
    stats.decisions += o.statistics.decisions;
    stats.backtracks += o.statistics.backtracks;
    stats.dead_ends += o.statistics.dead_ends;
    stats.plans += o.statistics.plans;
    // A propagation the stop condition cut short proves nothing.
    if (o.status == SearchStatus::kExhausted && net.interrupted())
      o.status = SearchStatus::kOutOfBudget;
    return o.status;
  };
  const bool fresh = !best_ || best_->root_tokens != root.tokens ||
                     best_->sequences.size() != net.timelines().size();
  if (fresh) {
    if (net.problem().objective == pb::Problem::MAKESPAN && options_.first_dives > 0 &&
        first_plan_by_dives(net, term, stats)) {
      remember(net, root.tokens);
      return finish(SearchStatus::kPlanFound);
    }
    const SearchStatus s = run_inner(static_cast<std::size_t>(-1), *inner_);
    if (s == SearchStatus::kPlanFound) remember(net, root.tokens);
    return finish(s);
  }
  while (true) {
    if (term.should_stop(stats.decisions)) return finish(SearchStatus::kOutOfBudget);
    if (fraction_ >= 1.0 || since_full_ >= kFullSearchShare * full_budget_) {
      // A full search from the root: the engine's proofs come from here only.
      since_full_ = 0;
      fraction_ = kStartFraction;
      const SearchStatus s = run_inner(full_budget_, *inner_);
      if (s == SearchStatus::kPlanFound) {
        remember(net, root.tokens);
        return finish(s);
      }
      net.undo_to(root);
      if (s == SearchStatus::kExhausted) return finish(s);
      full_budget_ *= 2;
      continue;
    }
    const std::vector<char> relaxed = neighbourhood();
    const std::size_t before = stats.decisions;
    SearchStatus s = SearchStatus::kExhausted;
    // Every other neighbourhood is re-planned by greedy dives drawn around the active schedule
    // rule: the chronological engine's fixed option order gives the same plan for the same
    // neighbourhood.
    const bool sample = neighbourhoods_++ % 2 == 1;
    if (keep_orders(net, relaxed, stats))
      s = sample ? dives(net, term, stats) : run_inner(options_.neighbourhood_decisions, *inner_);
    since_full_ += stats.decisions - before;
    if (s == SearchStatus::kPlanFound) {
      remember(net, root.tokens);
      return finish(s);
    }
    net.undo_to(root);
    // Nothing better in this neighbourhood: look wider; too wide to search: look narrower.
    // (Dives never exhaust anything: only the chronological sub-searches tell.)
    if (s == SearchStatus::kExhausted)
      fraction_ = std::min(1.0, fraction_ * kGrowth);
    else if (!sample)
      fraction_ = std::max(kMinFraction, fraction_ / kGrowth);
  }
}

}  // namespace

std::unique_ptr<SearchEngine> make_large_neighbourhood_search(const EngineOptions& options) {
  return std::make_unique<LargeNeighbourhood>(options);
}

}  // namespace autonomy::planner
