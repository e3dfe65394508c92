// Iterative repair (in the spirit of Zweben et al.'s constraint-based repair and of ASPEN):
// the engine keeps the current partial plan as its sequence of decisions and, at a dead end,
// changes one earlier decision instead of backing up chronologically or restarting.
//
//  - A dead end is a flaw none of whose options applies. The culprit is one of the few most
//    recent decisions that touched a timeline of the failing flaw's tokens (or of their
//    masters), drawn with weights 1, 0.8, 0.64, 0.51 from the seeded generator; when no decision
//    touched them, the most recent one that still has an alternative.
//  - The engine undoes to just before the culprit, takes another option there (one not tried
//    at that point yet, drawn at random, else one not proved to fail) and goes on resolving flaws.
//    For every flaw it first offers the option it chose last time for the same flaw (a memory keyed
//    by signatures that survive undo: tokens named by their problem fact or by their master's name
//    and their place among its slaves, options by what they do, not by positions). So a repair
//    changes one decision and re-applies the rest of the previous plan wherever it still applies.
//    The memory outlives solve(): the anytime loop's next, tighter solve starts from the last
//    plan's choices and repairs them.
//  - Incomplete, like sampling: the culprit jumps non-chronologically, so what is below a
//    replaced decision is never proved empty. It proves infeasibility only the way
//    chronological backtracking would: a flaw with no working option proves the state before
//    it has no plan, so the decision that led there is marked as failing, and a decision point
//    all of whose options are marked proves the state before it has no plan in turn. Only
//    when that chain reaches the root does it answer kExhausted; otherwise kOutOfBudget.
//
// Statistics: decisions (every option applied, replays included), backtracks (the repairs:
// each undo to a culprit decision), dead ends (options whose propagation failed and flaws
// left without options), plans.
#include "iterative_repair.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <random>
#include <unordered_map>

namespace autonomy::planner {
namespace {

using Key = std::uint64_t;
// Culprits: among this many of the most recent decisions touching the dead end's timelines,
// the r-th most recent with weight kCulpritDecay^r (measured on la01-la04, 20000 decisions:
// a flatter draw and a random new option find shorter schedules than always the latest).
constexpr std::size_t kCulprits = 4;
constexpr double kCulpritDecay = 0.8;

Key mix(Key h, Key v) {
  // splitmix64 of the combination: well spread, the same on every platform.
  Key x = h ^ (v + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2));
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

Key bits(double d) {
  Key k = 0;
  std::memcpy(&k, &d, sizeof k);
  return k;
}

// Names of tokens that stay the same when the plan around them changes: a problem fact's token
// by its fact, a slave by its master's name, its predicate, timeline and relation, and its rank
// among the master's slaves of that kind. Token ids are reused after an undo, so the names of
// tokens beyond a mark are forgotten when the engine undoes to it.
class TokenNames {
 public:
  void update(const TokenNetwork& net) {
    const auto& tokens = net.tokens();
    for (TokenId id = names_.size(); id < tokens.size(); ++id) {
      const Token& t = tokens[id];
      Key k = 0;
      if (t.fact >= 0) {
        k = mix(1, Key(t.fact));
      } else if (t.master != kNoToken && t.master < id) {
        std::size_t rank = 0;
        for (TokenId o = t.master + 1; o < id; ++o) {
          const Token& u = tokens[o];
          rank += u.master == t.master && u.predicate == t.predicate && u.timeline == t.timeline &&
                  u.relation == t.relation;
        }
        k = mix(mix(mix(mix(mix(2, names_[t.master]), Key(t.predicate)), Key(t.timeline)),
                    Key(t.relation)),
                rank);
      } else {
        k = mix(3, id);
      }
      names_.push_back(k);
    }
  }
  void forget_beyond(std::size_t tokens) {
    if (names_.size() > tokens) names_.resize(tokens);
  }
  Key operator[](TokenId id) const { return id < names_.size() ? names_[id] : mix(4, id); }

 private:
  std::vector<Key> names_;
};

Key flaw_key(const TokenNetwork& net, const TokenNames& names, const Flaw& f) {
  Key k = mix(10 + Key(f.kind), names[f.token]);
  switch (f.kind) {
    case Flaw::Kind::kFreeToken:
      return k;
    case Flaw::Kind::kOpenRequirement:
      return mix(mix(k, Key(net.instances()[f.instance].schema)), f.requirement);
    case Flaw::Kind::kUnboundParameter: {
      const auto& ps = net.tokens()[f.token].parameters;
      std::size_t position = ps.size();
      for (std::size_t i = 0; i < ps.size(); ++i)
        if (ps[i] == f.variable) position = i;
      return mix(mix(k, position), f.blocks_schema);
    }
    case Flaw::Kind::kResourceConflict:
      // Not by the tokens involved: they change as the plan does, and the ordering chosen
      // last time is found among the new options by its own name.
      return mix(mix(k, f.reservoir), f.reservoir_low);
  }
  return k;
}

// What an option does, independently of positions and ids (computed before it is applied).
Key option_key(const TokenNetwork& net, const TokenNames& names, const Decision& d) {
  Key k = Key(20 + int(d.kind));
  switch (d.kind) {
    case Decision::Kind::kInsert: {
      const auto& seq = net.timelines()[net.tokens()[d.token].timeline].sequence;
      return mix(k, d.index == 0 || d.index > seq.size() ? 0 : names[seq[d.index - 1]]);
    }
    case Decision::Kind::kMerge:
      return mix(k, names[d.index]);
    case Decision::Kind::kOmit:
      return k;
    case Decision::Kind::kRestrict:
      return mix(mix(mix(k, bits(d.domain.lo())), bits(d.domain.hi())), d.domain.is_set());
    case Decision::Kind::kChoose:
      return mix(k, d.index);
    case Decision::Kind::kOrder:
      return mix(mix(mix(k, names[d.token]), names[d.index]), d.requirement);
  }
  return k;
}

void add_timeline(const TokenNetwork& net, TokenId id, std::vector<std::size_t>& out) {
  if (id >= net.tokens().size()) return;
  const std::size_t tl = net.tokens()[id].timeline;
  if (std::find(out.begin(), out.end(), tl) == out.end()) out.push_back(tl);
}

// The timelines a dead end is about: its tokens' and their masters'.
std::vector<std::size_t> flaw_timelines(const TokenNetwork& net, const Flaw& f) {
  std::vector<std::size_t> out;
  std::vector<TokenId> tokens = f.involved;
  tokens.push_back(f.token);
  for (TokenId t : tokens) {
    add_timeline(net, t, out);
    if (t < net.tokens().size()) add_timeline(net, net.tokens()[t].master, out);
  }
  return out;
}

std::vector<std::size_t> decision_timelines(const TokenNetwork& net, const Decision& d) {
  std::vector<std::size_t> out;
  add_timeline(net, d.token, out);
  if (d.kind == Decision::Kind::kMerge || d.kind == Decision::Kind::kOrder)
    add_timeline(net, d.index, out);
  return out;
}

class IterativeRepair final : public SearchEngine {
 public:
  explicit IterativeRepair(EngineOptions options)
      : options_(std::move(options)), rng_(options_.seed) {
    if (!options_.selector) options_.selector = earliest_first_selector();
  }
  std::string name() const override { return "repair"; }
  SearchOutcome solve(TokenNetwork& net, const Termination& term) override;

 private:
  // One decision point of the current plan. `tried` and `proved` hold for the state before it
  // (unchanged while the step is in the plan): options applied here since the step was made,
  // and options proved to leave no plan.
  struct Step {
    TokenNetwork::Mark mark;
    Key flaw = 0;
    std::vector<std::size_t> flaw_timelines;
    std::vector<Decision> options;
    std::vector<Key> option_keys;
    std::vector<char> tried, proved;
    std::size_t chosen = 0;
    std::vector<std::size_t> touched;  // timelines of the chosen decision
    bool has_alternative() const {
      for (std::size_t o = 0; o < options.size(); ++o)
        if (o != chosen && !proved[o]) return true;
      return false;
    }
    bool all_proved() const {
      return std::all_of(proved.begin(), proved.end(), [](char p) { return p; });
    }
  };

  std::size_t pick_culprit(const std::vector<std::size_t>& failing) {
    std::vector<std::size_t> candidates;
    std::size_t latest_eligible = plan_.size();
    for (std::size_t i = plan_.size(); i-- > 0 && candidates.size() < kCulprits;) {
      const Step& s = plan_[i];
      if (!s.has_alternative()) continue;
      if (latest_eligible == plan_.size()) latest_eligible = i;
      bool relevant = false;
      for (std::size_t tl : s.touched)
        relevant |= std::find(failing.begin(), failing.end(), tl) != failing.end();
      if (relevant) candidates.push_back(i);
    }
    if (candidates.empty()) return latest_eligible;  // plan_.size(): none
    std::vector<double> weights;
    for (std::size_t r = 0; r < candidates.size(); ++r)
      weights.push_back(std::pow(kCulpritDecay, double(r)));
    std::discrete_distribution<std::size_t> pick(weights.begin(), weights.end());
    return candidates[pick(rng_)];
  }

  void undo_to(TokenNetwork& net, const TokenNetwork::Mark& m) {
    net.undo_to(m);
    names_.forget_beyond(m.tokens);
  }

  // The state after the last step has no plan: mark its decision as failing and carry the
  // proof down while a step has all its options marked. False when it reaches the root.
  bool propagate_proof(TokenNetwork& net, std::vector<std::size_t>& failing) {
    while (!plan_.empty()) {
      Step& back = plan_.back();
      back.proved[back.chosen] = 1;
      if (!back.all_proved()) return true;
      failing = back.flaw_timelines;
      undo_to(net, back.mark);
      plan_.pop_back();
    }
    return false;
  }

  bool apply(TokenNetwork& net, Step& s, std::size_t o, bool repair, SearchStatistics& stats) {
    ++stats.decisions;
    s.tried[o] = 1;
    const Decision& d = s.options[o];
    std::vector<std::size_t> touched = decision_timelines(net, d);
    const auto choice = repair               ? EngineOptions::Choice::kRepair
                        : memory_hit(s) == o ? EngineOptions::Choice::kRemembered
                                             : EngineOptions::Choice::kHeuristic;
    const bool applied = net.apply(d);
    if (options_.on_decision) options_.on_decision(d, choice, applied);
    if (applied) {
      s.chosen = o;
      s.touched = std::move(touched);
      memory_[s.flaw] = s.option_keys[o];
      return true;
    }
    ++stats.dead_ends;
    s.proved[o] = 1;
    undo_to(net, s.mark);
    return false;
  }

  std::size_t memory_hit(const Step& s) const {
    auto it = memory_.find(s.flaw);
    if (it == memory_.end()) return s.options.size();
    for (std::size_t o = 0; o < s.options.size(); ++o)
      if (s.option_keys[o] == it->second) return o;
    return s.options.size();
  }

  EngineOptions options_;
  std::mt19937 rng_;
  std::unordered_map<Key, Key> memory_;  // flaw -> the option chosen for it last
  TokenNames names_;
  std::vector<Step> plan_;
};

SearchOutcome IterativeRepair::solve(TokenNetwork& net, const Termination& term) {
  const std::size_t tn0 = net.temporal().propagations();
  const std::size_t cn0 = net.constraints().statistics().procedure_calls;
  SearchOutcome out;
  SearchStatistics& stats = out.statistics;
  const TokenNetwork::Mark root = net.mark();
  names_.forget_beyond(0);
  plan_.clear();
  auto finish = [&](SearchStatus status) {
    if (status != SearchStatus::kPlanFound) undo_to(net, root);
    plan_.clear();
    out.status = status;
    stats.temporal_propagations = net.temporal().propagations() - tn0;
    stats.procedure_calls = net.constraints().statistics().procedure_calls - cn0;
    return out;
  };
  auto stop = [&] { return term.should_stop(stats.decisions); };

  while (true) {
    // Resolve the next flaw, the memory's option first, then the heuristic's order.
    names_.update(net);
    std::vector<Flaw> flaws = net.flaws();
    if (flaws.empty()) {
      ++stats.plans;
      return finish(SearchStatus::kPlanFound);
    }
    const Flaw& flaw = flaws[options_.selector(net, flaws)];
    Step s;
    s.mark = net.mark();
    s.flaw = flaw_key(net, names_, flaw);
    s.flaw_timelines = flaw_timelines(net, flaw);
    s.options = net.options(flaw);
    for (const Decision& d : s.options) s.option_keys.push_back(option_key(net, names_, d));
    s.tried.assign(s.options.size(), 0);
    s.proved.assign(s.options.size(), 0);
    std::vector<std::size_t> order;
    const std::size_t remembered = memory_hit(s);
    if (remembered < s.options.size()) order.push_back(remembered);
    for (std::size_t o = 0; o < s.options.size(); ++o)
      if (o != remembered) order.push_back(o);
    bool placed = false;
    for (std::size_t o : order) {
      if (stop()) return finish(SearchStatus::kOutOfBudget);
      if ((placed = apply(net, s, o, false, stats))) break;
    }
    if (placed) {
      plan_.push_back(std::move(s));
      continue;
    }
    if (s.options.empty()) ++stats.dead_ends;

    // A dead end: this state has no plan. Repair until a decision takes a new option.
    std::vector<std::size_t> failing = s.flaw_timelines;
    if (!propagate_proof(net, failing)) return finish(SearchStatus::kExhausted);
    bool repaired = false;
    while (!repaired) {
      const std::size_t j = pick_culprit(failing);
      // Every decision's other options are proved to fail, yet no proof reached the root:
      // cannot happen with proofs carried down at once; answer honestly if it does.
      if (j == plan_.size()) return finish(SearchStatus::kOutOfBudget);
      ++stats.backtracks;
      undo_to(net, plan_[j].mark);
      plan_.resize(j + 1);
      Step& c = plan_[j];
      const std::size_t old = c.chosen;
      std::vector<std::size_t> alternatives;
      for (int untried = 1; untried >= 0; --untried)
        for (std::size_t o = 0; o < c.options.size(); ++o)
          if (o != old && !c.proved[o] && bool(c.tried[o]) != bool(untried))
            alternatives.push_back(o);
      // The new option is drawn among those not tried here yet (the others follow, in order).
      std::size_t fresh = 0;
      for (std::size_t o : alternatives) fresh += !c.tried[o];
      std::shuffle(alternatives.begin(), alternatives.begin() + long(fresh), rng_);
      for (std::size_t o : alternatives) {
        if (stop()) return finish(SearchStatus::kOutOfBudget);
        if ((repaired = apply(net, c, o, true, stats))) break;
      }
      if (repaired) break;
      // No other option applies here: keep the old one (the memory replays what followed
      // and the next dead end looks elsewhere), unless it is proved to fail too.
      if (!c.proved[old]) {
        if (stop()) return finish(SearchStatus::kOutOfBudget);
        if ((repaired = apply(net, c, old, false, stats))) break;
      }
      failing = c.flaw_timelines;
      plan_.pop_back();  // its options all fail: the state before it has no plan
      if (!propagate_proof(net, failing)) return finish(SearchStatus::kExhausted);
    }
  }
}

}  // namespace

std::unique_ptr<SearchEngine> make_iterative_repair(const EngineOptions& options) {
  return std::make_unique<IterativeRepair>(options);
}

}  // namespace autonomy::planner
