// Active schedule generation (Giffler and Thompson 1960) as a flaw selector. The default
// selector takes the free token with the earliest start in the temporal network, which knows
// nothing of the tokens already on the token's timeline: on a job shop it picks an operation
// whose job is ready while its machine is busy for long, and the first plan ends far off (abz5:
// 2322 against the optimum 1234). Here a token's earliest start is that of its earliest slot on
// its timeline, the timeline of the token that could end first is the one decided next (so no
// token is placed where another could have ended before it starts: an active schedule), and
// among the tokens that compete there the one with the least latest start goes first (under the
// problem's horizon or the makespan bound, that is the one followed by the most work).
// Nothing here is specific to job shops: timelines, slots, and the temporal network's bounds.
#include "active_schedule.hpp"

#include <algorithm>
#include <optional>
#include <tuple>

namespace autonomy::planner {
namespace {

struct Candidate {
  std::size_t flaw;
  Time start, end, latest;
};

struct Slot {
  Time start, end;
  std::size_t position;
};

// Where a free token goes on its timeline: the earliest slot it fits in without delaying the
// token after it at that token's earliest start (appending never delays anything), else the
// earliest slot it fits in at all (the options' fit test: the neighbours' bounds leave room).
// Inserting at the very front whenever the horizon allows, as the options' order does, pushes
// every token placed so far. Nothing fits: nullopt.
std::optional<Slot> earliest_slot(const TokenNetwork& net, TokenId id) {
  const TemporalNetwork& tn = net.temporal();
  const Token& t = net.tokens()[id];
  const std::vector<TokenId>& seq = net.timelines()[t.timeline].sequence;
  const Time length = std::max(t.min_duration, tn.earliest(t.end) - tn.earliest(t.start));
  std::optional<Slot> pushing;
  for (std::size_t p = 0; p <= seq.size(); ++p) {
    const Time after = p > 0 ? tn.earliest(net.tokens()[seq[p - 1]].end) : 0;
    const Time before = p < seq.size() ? tn.latest(net.tokens()[seq[p]].start) : kInfinity;
    if (after > tn.latest(t.start) || tn.earliest(t.end) > before) continue;
    const Time start = std::max(after, tn.earliest(t.start));
    const Slot slot{start, std::max(start + length, tn.earliest(t.end)), p};
    const Time next = p < seq.size() ? tn.earliest(net.tokens()[seq[p]].start) : kInfinity;
    if (slot.end <= next) return slot;  // slots are in time order: the first is the earliest
    if (!pushing) pushing = slot;
  }
  return pushing;
}

}  // namespace

FlawSelector active_schedule_selector(std::mt19937* rng) {
  return [rng, fallback = earliest_first_selector()](const TokenNetwork& net,
                                                     const std::vector<Flaw>& flaws) {
    const std::size_t first = fallback(net, flaws);
    if (flaws[first].kind != Flaw::Kind::kFreeToken) return first;
    std::vector<Candidate> free;
    for (std::size_t i = 0; i < flaws.size(); ++i) {
      if (flaws[i].kind != Flaw::Kind::kFreeToken) continue;
      const TokenId id = flaws[i].token;
      const auto slot = earliest_slot(net, id);
      // No slot (only a merge or an omission is left, or nothing): decide it now, fail first.
      if (!slot) return i;
      free.push_back({i, slot->start, slot->end,
                      net.temporal().latest(net.tokens()[id].start)});
    }
    const Candidate& ends_first = *std::min_element(
        free.begin(), free.end(), [](const Candidate& a, const Candidate& b) {
          return std::tie(a.end, a.start) < std::tie(b.end, b.start);
        });
    const std::size_t timeline = net.tokens()[flaws[ends_first.flaw].token].timeline;
    std::vector<Candidate> conflict;
    for (const Candidate& c : free)
      if (net.tokens()[flaws[c.flaw].token].timeline == timeline && c.start < ends_first.end)
        conflict.push_back(c);
    std::sort(conflict.begin(), conflict.end(), [&](const Candidate& a, const Candidate& b) {
      return std::tie(a.latest, a.start, flaws[a.flaw].token) <
             std::tie(b.latest, b.start, flaws[b.flaw].token);
    });
    if (!rng || conflict.size() == 1) return conflict.front().flaw;
    std::vector<double> weights;
    for (std::size_t r = 0; r < conflict.size(); ++r)
      weights.push_back(1.0 / double((r + 1) * (r + 1)));
    std::discrete_distribution<std::size_t> pick(weights.begin(), weights.end());
    return conflict[pick(*rng)].flaw;
  };
}

bool greedy_dive(TokenNetwork& net, const FlawSelector& select, const Termination& term,
                 SearchStatistics& stats, std::vector<Decision>* decisions) {
  const TokenNetwork::Mark root = net.mark();
  if (decisions) decisions->clear();
  while (!term.should_stop(stats.decisions)) {
    const std::vector<Flaw> flaws = net.flaws();
    if (flaws.empty()) {
      ++stats.plans;
      return true;
    }
    const Flaw& flaw = flaws[select(net, flaws)];
    std::vector<Decision> options = net.options(flaw);
    // A free token goes to its slot of the schedule first (earliest_slot).
    if (flaw.kind == Flaw::Kind::kFreeToken)
      if (const auto slot = earliest_slot(net, flaw.token)) {
        auto it = std::find_if(options.begin(), options.end(), [&](const Decision& d) {
          return d.kind == Decision::Kind::kInsert && d.index == slot->position;
        });
        if (it != options.end()) std::rotate(options.begin(), it, it + 1);
      }
    const TokenNetwork::Mark here = net.mark();
    bool applied = false;
    for (const Decision& d : options) {
      ++stats.decisions;
      if (net.apply(d)) {
        if (decisions) decisions->push_back(d);
        applied = true;
        break;
      }
      ++stats.dead_ends;
      net.undo_to(here);
    }
    if (!applied) break;
  }
  net.undo_to(root);
  return false;
}

}  // namespace autonomy::planner
