// Depth-first search with conflict-directed backjumping (Prosser 1993) over the token
// network's flaws: the chronological engine's flaw and option order, but when every option of
// a decision point has failed, the search goes back to the most recent decision that took part
// in one of those failures, skipping the decisions in between, which had nothing to do with
// them (their other options would fail the same way).
//
// Soundness rests on two kinds of explanation, each conservative where the network cannot say
// more:
// - Why an option failed: with explanations on, a failure in the temporal network names the
//   constraints of one negative cycle exactly. A constraint made before the search is part of
//   the problem; one that a decision added itself (an insertion's two precedences, a resource
//   order) depends on that decision; one that propagation or schema instantiation added
//   while applying decision m (edge finding, detectable precedences, slaves' relations, pushed
//   durations) depends on the whole state it was derived from: decisions 1..m. A failure
//   anywhere else (parameters, overload, ...) depends on every decision so far.
// - Why a decision point's options were all there was: a free token must take one of the slots
//   of its timeline's current sequence or merge with a token of it, so the point depends on
//   the decisions that inserted those tokens. Slots or merges left out because of the
//   network's bounds or domains, tokens made during the search, and every other kind of flaw
//   depend on every decision so far.
// Where every explanation falls back to "every decision so far", the search is the
// chronological engine's, decision for decision.
#include "backjumping.hpp"

#include <algorithm>

namespace autonomy::planner {

namespace {

// Levels are indices into the search's stack of decision points.
using LevelSet = std::vector<char>;

void add_all_below(LevelSet& set, std::size_t level) {
  for (std::size_t i = 0; i < level && i < set.size(); ++i) set[i] = 1;
}

class Backjumping final : public SearchEngine {
 public:
  explicit Backjumping(EngineOptions options) : options_(std::move(options)) {
    if (!options_.selector) options_.selector = earliest_first_selector();
  }
  std::string name() const override { return "chronological"; }

  SearchOutcome solve(TokenNetwork& net, const Termination& term) override {
    const PropagationCount count(net);
    SearchOutcome out;
    net.set_explain_conflicts(true);
    struct Off {
      TokenNetwork& net;
      ~Off() { net.set_explain_conflicts(false); }
    } off{net};
    out.status = run(net, term, out.statistics);
    count.record(net, out.statistics);
    return out;
  }

 private:
  struct Frame {
    TokenNetwork::Mark mark;
    std::vector<Decision> options;
    std::size_t next = 0;
    LevelSet conflict;  // levels below this one that its failures (and its options) depend on
    // The constraints of the option applied here: ids from `begin`, the first `own` of them
    // made by the decision itself.
    std::size_t begin = 0, own = 0;
  };

  SearchStatus run(TokenNetwork& net, const Termination& term, SearchStatistics& stats) {
    stack_.clear();
    const TokenNetwork::Mark root = net.mark();
    root_tokens_ = net.tokens().size();
    root_constraints_ = net.temporal().constraints().size();
    root_domains_.clear();
    for (const Token& t : net.tokens())
      for (VariableId v : t.parameters) {
        if (v >= root_domains_.size()) root_domains_.resize(v + 1, Domain::real(0, 0));
        root_domains_[v] = net.constraints().domain(v);
      }
    root_sequence_.clear();
    for (const Timeline& tl : net.timelines()) root_sequence_.push_back(tl.sequence.size());
    bool descend = true;
    while (true) {
      if (descend) {
        std::vector<Flaw> flaws = net.flaws();
        if (flaws.empty()) {
          ++stats.plans;
          return SearchStatus::kPlanFound;
        }
        const Flaw& flaw = flaws[options_.selector(net, flaws)];
        Frame f;
        f.mark = net.mark();
        f.options = net.options(flaw);
        f.conflict.assign(stack_.size(), 0);
        completeness(net, flaw, f);
        stack_.push_back(std::move(f));
        if (stack_.back().options.empty()) ++stats.dead_ends;
      }
      descend = false;
      while (!stack_.empty()) {
        if (term.should_stop(stats.decisions)) {
          net.undo_to(root);
          return SearchStatus::kOutOfBudget;
        }
        Frame& f = stack_.back();
        const std::size_t level = stack_.size() - 1;
        net.undo_to(f.mark);
        if (f.next >= f.options.size()) {
          // Exhausted: back to the deepest level its conflicts name, or out if none.
          LevelSet conflict = std::move(f.conflict);
          std::size_t target = conflict.size();
          while (target > 0 && !conflict[target - 1]) --target;
          if (target == 0) {
            stack_.clear();
            ++stats.backtracks;
            net.undo_to(root);
            return SearchStatus::kExhausted;
          }
          --target;
          while (stack_.size() > target + 1) {
            stack_.pop_back();
            ++stats.backtracks;
          }
          Frame& back = stack_.back();
          for (std::size_t i = 0; i < target; ++i) back.conflict[i] |= conflict[i];
          continue;
        }
        const Decision& d = f.options[f.next++];
        f.begin = net.temporal().constraints().size();
        f.own = own_constraints(net, d);
        ++stats.decisions;
        // An explanation costs a pass over the whole network; once this point depends on
        // every level below, no failure of its options can say more.
        net.set_explain_conflicts(
            !std::all_of(f.conflict.begin(), f.conflict.end(), [](char c) { return c != 0; }));
        if (net.apply(d)) {
          descend = true;
          break;
        }
        ++stats.dead_ends;
        explain_failure(net, level, f.conflict);
      }
      if (!descend) {
        net.undo_to(root);
        return SearchStatus::kExhausted;
      }
    }
  }

  // How many of the constraints apply(d) adds first are d's own (TokenNetwork::insert and
  // the resource order add them before anything else).
  static std::size_t own_constraints(const TokenNetwork& net, const Decision& d) {
    if (d.kind == Decision::Kind::kOrder) return 1;
    if (d.kind != Decision::Kind::kInsert) return 0;
    const std::size_t size = net.timelines()[net.tokens()[d.token].timeline].sequence.size();
    return (d.index > 0 ? 1 : 0) + (d.index < size ? 1 : 0);
  }

  // Marks in `conflict` the levels below `level` that the failed apply() at `level` depends on.
  void explain_failure(const TokenNetwork& net, std::size_t level, LevelSet& conflict) const {
    const std::vector<TemporalConstraintId>* cycle = net.failed_cycle();
    if (!cycle) return add_all_below(conflict, level);
    for (TemporalConstraintId c : *cycle) {
      if (c == TemporalNetwork::kHorizonConstraint || c < root_constraints_) continue;
      // The level whose apply() made c: the last one that began at or before it.
      std::size_t m = level;
      while (m > 0 && stack_[m].begin > c) --m;
      if (stack_[m].begin > c) continue;  // cannot happen: c >= root_constraints_
      if (c < stack_[m].begin + stack_[m].own) {
        if (m < level) conflict[m] = 1;
      } else {
        add_all_below(conflict, std::min(m + 1, level));
      }
    }
  }

  // Marks in f.conflict what makes f's options the only ways to resolve the flaw.
  void completeness(const TokenNetwork& net, const Flaw& flaw, Frame& f) const {
    const std::size_t level = stack_.size();
    if (flaw.kind != Flaw::Kind::kFreeToken || flaw.token >= root_tokens_)
      return add_all_below(f.conflict, level);
    const Token& t = net.tokens()[flaw.token];
    const Timeline& tl = net.timelines()[t.timeline];
    std::size_t inserts = 0, merges = 0;
    for (const Decision& d : f.options) {
      if (d.kind == Decision::Kind::kInsert) ++inserts;
      if (d.kind == Decision::Kind::kMerge) ++merges;
    }
    if (inserts != tl.sequence.size() + 1) return add_all_below(f.conflict, level);
    // A token of the same predicate not offered as a merge was left out by the network's
    // state, unless the two had different constants before the search.
    std::size_t mergeable = 0;
    for (TokenId other : tl.sequence)
      if (net.tokens()[other].predicate == t.predicate && !apart_at_root(net, flaw.token, other))
        ++mergeable;
    if (merges != mergeable) return add_all_below(f.conflict, level);
    std::size_t placed = 0;
    for (std::size_t i = 0; i < level; ++i) {
      const Decision& d = stack_[i].options[stack_[i].next - 1];
      if (d.kind == Decision::Kind::kInsert && net.tokens()[d.token].timeline == t.timeline) {
        f.conflict[i] = 1;
        ++placed;
      }
    }
    if (root_sequence_[t.timeline] + placed != tl.sequence.size())
      add_all_below(f.conflict, level);
  }

  // Two tokens made before the search whose parameter domains then had no value in common
  // (a merge between them is impossible in any state the search reaches).
  bool apart_at_root(const TokenNetwork& net, TokenId a, TokenId b) const {
    if (a >= root_tokens_ || b >= root_tokens_) return false;
    const Token &t = net.tokens()[a], &u = net.tokens()[b];
    for (std::size_t i = 0; i < t.parameters.size() && i < u.parameters.size(); ++i) {
      Domain d = root_domains_[t.parameters[i]];
      d.intersect(root_domains_[u.parameters[i]]);
      if (d.empty()) return true;
    }
    return false;
  }

  EngineOptions options_;
  std::vector<Domain> root_domains_;  // per parameter variable of the tokens made before
  std::vector<Frame> stack_;
  std::size_t root_tokens_ = 0, root_constraints_ = 0;
  std::vector<std::size_t> root_sequence_;
};

}  // namespace

std::unique_ptr<SearchEngine> make_backjumping_search(const EngineOptions& options) {
  return std::make_unique<Backjumping>(options);
}

}  // namespace autonomy::planner
