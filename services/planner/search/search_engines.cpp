#include <algorithm>
#include <random>

#include "backjumping.hpp"
#include "iterative_repair.hpp"
#include "large_neighbourhood.hpp"
#include "search_engine.hpp"

namespace autonomy::planner {

FlawSelector earliest_first_selector() {
  return [](const TokenNetwork& net, const std::vector<Flaw>& flaws) {
    auto rank = [&](const Flaw& f) -> std::tuple<int, Time, Time, std::size_t> {
      const TemporalNetwork& tn = net.temporal();
      switch (f.kind) {
        case Flaw::Kind::kUnboundParameter:
          if (f.blocks_schema) return {0, 0, 0, f.token};
          return {4, 0, 0, f.token};
        case Flaw::Kind::kResourceConflict:
          return {3, 0, 0, f.token};
        case Flaw::Kind::kOpenRequirement:
          return {1, 0, 0, f.token};
        case Flaw::Kind::kFreeToken: {
          const Token& t = net.tokens()[f.token];
          return {2, tn.earliest(t.start), tn.latest(t.start), f.token};
        }
      }
      return {5, 0, 0, 0};
    };
    std::size_t best = 0;
    auto best_rank = rank(flaws[0]);
    for (std::size_t i = 1; i < flaws.size(); ++i) {
      auto r = rank(flaws[i]);
      if (r < best_rank) {
        best_rank = r;
        best = i;
      }
    }
    return best;
  };
}

namespace {

// Depth-first search over flaws and their options with chronological backtracking; taking
// the i-th option of a flaw costs i discrepancies, and a probe never spends more than
// `budget` (unlimited: plain chronological backtracking, complete).
class DepthFirst {
 public:
  DepthFirst(TokenNetwork& net, const FlawSelector& select, const Termination& term,
             SearchStatistics& stats)
      : net_(net), select_(select), term_(term), stats_(stats) {}

  SearchStatus run(std::size_t budget) {
    struct Frame {
      TokenNetwork::Mark mark;
      std::vector<Decision> options;
      std::size_t next = 0;
      std::size_t spent = 0;  // discrepancies used above this frame
    };
    std::vector<Frame> stack;
    const TokenNetwork::Mark root = net_.mark();
    bool descend = true;
    std::size_t spent = 0;
    bool pruned = false;  // a probe refused an option for lack of discrepancies
    while (true) {
      if (descend) {
        std::vector<Flaw> flaws = net_.flaws();
        if (flaws.empty()) {
          ++stats_.plans;
          return SearchStatus::kPlanFound;
        }
        const Flaw& flaw = flaws[select_(net_, flaws)];
        stack.push_back({net_.mark(), net_.options(flaw), 0, spent});
        if (stack.back().options.empty()) ++stats_.dead_ends;
      }
      // Try the next option of the deepest frame that has one.
      descend = false;
      while (!stack.empty()) {
        Frame& f = stack.back();
        if (term_.should_stop(stats_.decisions)) {
          net_.undo_to(root);
          return SearchStatus::kOutOfBudget;
        }
        net_.undo_to(f.mark);
        if (f.next >= f.options.size() || f.spent + f.next > budget) {
          if (f.next < f.options.size()) pruned = true;
          stack.pop_back();
          ++stats_.backtracks;
          continue;
        }
        spent = f.spent + f.next;
        const Decision& d = f.options[f.next++];
        ++stats_.decisions;
        if (net_.apply(d)) {
          descend = true;
          break;
        }
        ++stats_.dead_ends;
      }
      if (!descend) {
        net_.undo_to(root);
        return pruned ? SearchStatus::kOutOfBudget : SearchStatus::kExhausted;
      }
    }
  }

 private:
  TokenNetwork& net_;
  const FlawSelector& select_;
  const Termination& term_;
  SearchStatistics& stats_;
};

class EngineBase : public SearchEngine {
 public:
  explicit EngineBase(EngineOptions options) : options_(std::move(options)) {
    if (!options_.selector) options_.selector = earliest_first_selector();
  }

 protected:
  SearchOutcome finish(TokenNetwork& net, SearchOutcome out, const PropagationCount& count) {
    count.record(net, out.statistics);
    return out;
  }
  EngineOptions options_;
};

class ChronologicalBacktracking final : public EngineBase {
 public:
  using EngineBase::EngineBase;
  std::string name() const override { return "chronological"; }
  SearchOutcome solve(TokenNetwork& net, const Termination& term) override {
    const PropagationCount count(net);
    SearchOutcome out;
    DepthFirst dfs(net, options_.selector, term, out.statistics);
    out.status = dfs.run(static_cast<std::size_t>(-1));
    return finish(net, out, count);
  }
};

class LimitedDiscrepancy final : public EngineBase {
 public:
  using EngineBase::EngineBase;
  std::string name() const override { return "discrepancy"; }
  SearchOutcome solve(TokenNetwork& net, const Termination& term) override {
    const PropagationCount count(net);
    SearchOutcome out;
    DepthFirst dfs(net, options_.selector, term, out.statistics);
    // Probes with 0, 1, ... discrepancies, then without a limit (so the engine stays complete).
    for (std::size_t k = 0; k <= options_.discrepancies; ++k) {
      out.status = dfs.run(k);
      if (out.status == SearchStatus::kPlanFound || out.status == SearchStatus::kExhausted ||
          term.should_stop(out.statistics.decisions))
        return finish(net, out, count);
    }
    out.status = dfs.run(static_cast<std::size_t>(-1));
    return finish(net, out, count);
  }
};

// Heuristic-biased iterative sampling (Langley 1992, Bresina 1996): probes from the root that
// pick the option of rank r with weight 1 / (r + 1)^2, trying the remaining options in order
// when the pick fails, and restart (with the next seed) at a dead end. Incomplete: it never
// proves anything, it only finds plans.
class IterativeSampling final : public EngineBase {
 public:
  using EngineBase::EngineBase;
  std::string name() const override { return "sampling"; }
  SearchOutcome solve(TokenNetwork& net, const Termination& term) override {
    const PropagationCount count(net);
    SearchOutcome out;
    SearchStatistics& stats = out.statistics;
    const TokenNetwork::Mark root = net.mark();
    std::mt19937 rng(options_.seed + probes_);
    for (std::size_t probe = 0; probe < options_.restarts; ++probe, ++probes_) {
      bool dead = false;
      while (!dead) {
        if (term.should_stop(stats.decisions)) {
          net.undo_to(root);
          out.status = SearchStatus::kOutOfBudget;
          return finish(net, out, count);
        }
        std::vector<Flaw> flaws = net.flaws();
        if (flaws.empty()) {
          ++stats.plans;
          out.status = SearchStatus::kPlanFound;
          return finish(net, out, count);
        }
        std::vector<Decision> options = net.options(flaws[options_.selector(net, flaws)]);
        std::vector<double> weights;
        for (std::size_t r = 0; r < options.size(); ++r)
          weights.push_back(1.0 / double((r + 1) * (r + 1)));
        std::vector<std::size_t> order;
        if (!options.empty()) {
          std::discrete_distribution<std::size_t> pick(weights.begin(), weights.end());
          order.push_back(pick(rng));
        }
        for (std::size_t r = 0; r < options.size(); ++r)
          if (r != order.front()) order.push_back(r);
        const TokenNetwork::Mark here = net.mark();
        dead = true;
        for (std::size_t r : order) {
          ++stats.decisions;
          if (net.apply(options[r])) {
            dead = false;
            break;
          }
          ++stats.dead_ends;
          net.undo_to(here);
        }
      }
      ++stats.backtracks;  // a restart
      net.undo_to(root);
    }
    out.status = SearchStatus::kOutOfBudget;
    return finish(net, out, count);
  }

 private:
  std::size_t probes_ = 0;  // successive solve() calls continue the seed sequence
};

}  // namespace

std::unique_ptr<SearchEngine> make_search_engine(const std::string& name,
                                                 const EngineOptions& options) {
  if (name == "chronological")
    return options.backjumping ? make_backjumping_search(options)
                               : std::make_unique<ChronologicalBacktracking>(options);
  if (name == "discrepancy") return std::make_unique<LimitedDiscrepancy>(options);
  if (name == "sampling") return std::make_unique<IterativeSampling>(options);
  if (name == "repair") return make_iterative_repair(options);
  if (name == "lns") return make_large_neighbourhood_search(options);
  return nullptr;
}

std::vector<std::string> search_engine_names() {
  return {"chronological", "discrepancy", "sampling", "repair", "lns"};
}

}  // namespace autonomy::planner
