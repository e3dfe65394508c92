#include "temporal_network.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <stdexcept>
#include <string>

namespace autonomy::planner {
namespace {

TEST(TemporalNetwork, ChainGivesHandComputedBounds) {
  TemporalNetwork tn(100);
  TimepointId a = tn.add_timepoint(), b = tn.add_timepoint(), c = tn.add_timepoint();
  ASSERT_TRUE(tn.add_constraint(TemporalNetwork::origin(), a, 10, 20));
  ASSERT_TRUE(tn.add_constraint(a, b, 5, 5));
  ASSERT_TRUE(tn.add_constraint(b, c, 0, kInfinity));
  EXPECT_EQ(tn.earliest(a), 10);
  EXPECT_EQ(tn.latest(a), 20);
  EXPECT_EQ(tn.earliest(b), 15);
  EXPECT_EQ(tn.latest(b), 25);
  EXPECT_EQ(tn.earliest(c), 15);
  EXPECT_EQ(tn.latest(c), 100);
  // c no later than 22 pulls b and a back: b <= 22, a <= 17.
  ASSERT_TRUE(tn.add_constraint(TemporalNetwork::origin(), c, 0, 22));
  EXPECT_EQ(tn.latest(b), 22);
  EXPECT_EQ(tn.latest(a), 17);
  EXPECT_EQ(tn.shortest_distance(a, c), 17 - 10 + 0 + 5);  // via c<=22, a>=10: c-a <= 12
}

TEST(TemporalNetwork, NegativeCycleIsDetectedAtTheClosingConstraintAndLeavesNoTrace) {
  TemporalNetwork tn(1000);
  TimepointId a = tn.add_timepoint(), b = tn.add_timepoint(), c = tn.add_timepoint();
  TemporalConstraintId ab, bc, ca;
  ASSERT_TRUE(tn.add_constraint(a, b, 10, 20, &ab));
  ASSERT_TRUE(tn.add_constraint(b, c, 10, 20, &bc));
  const auto before_a = tn.bounds(a), before_c = tn.bounds(c);
  // c - a in [20, 40]; asking a - c >= -15 (c - a <= 15) closes a negative cycle.
  TemporalResult r = tn.add_constraint(c, a, -15, 0, &ca);
  ASSERT_FALSE(r);
  EXPECT_EQ(r.conflict.front(), ca);
  EXPECT_EQ(r.conflict.size(), 3u);
  EXPECT_EQ(tn.bounds(a).earliest, before_a.earliest);
  EXPECT_EQ(tn.bounds(a).latest, before_a.latest);
  EXPECT_EQ(tn.bounds(c).latest, before_c.latest);
  EXPECT_FALSE(tn.constraints()[ca].active);
  // The network is still usable, and c - a <= 25 is fine.
  EXPECT_TRUE(tn.add_constraint(c, a, -25, 0));
  EXPECT_EQ(tn.shortest_distance(a, c), 25);
}

TEST(TemporalNetwork, ExplainedConflictsNameTheWholeCycleThroughTheOrigin) {
  TemporalNetwork tn(1000);
  tn.set_explain_conflicts(true);
  TimepointId a = tn.add_timepoint(), b = tn.add_timepoint(), unrelated = tn.add_timepoint();
  TemporalConstraintId a_late, ab, other, b_early;
  ASSERT_TRUE(tn.add_constraint(TemporalNetwork::origin(), a, 0, 20, &a_late));
  ASSERT_TRUE(tn.add_constraint(a, b, 10, 10, &ab));
  ASSERT_TRUE(tn.add_constraint(TemporalNetwork::origin(), unrelated, 5, 6, &other));
  TemporalResult r = tn.add_constraint(TemporalNetwork::origin(), b, 40, 50, &b_early);
  ASSERT_FALSE(r);
  std::vector<TemporalConstraintId> expected{b_early, a_late, ab};
  std::vector<TemporalConstraintId> got = r.conflict;
  std::sort(expected.begin(), expected.end());
  std::sort(got.begin(), got.end());
  EXPECT_EQ(got, expected);
}

TEST(TemporalNetwork, EmptyIntervalAndHorizonAreInconsistent) {
  TemporalNetwork tn(50);
  TimepointId a = tn.add_timepoint();
  EXPECT_FALSE(tn.add_constraint(TemporalNetwork::origin(), a, 5, 4));
  EXPECT_FALSE(tn.add_constraint(TemporalNetwork::origin(), a, 51, 60));
  EXPECT_TRUE(tn.add_constraint(TemporalNetwork::origin(), a, 50, 60));
  EXPECT_EQ(tn.earliest(a), 50);
}

TEST(TemporalNetwork, UndoRestoresBoundsTimepointsAndConstraints) {
  TemporalNetwork tn(100);
  TimepointId a = tn.add_timepoint();
  ASSERT_TRUE(tn.add_constraint(TemporalNetwork::origin(), a, 3, 90));
  auto m = tn.mark();
  TimepointId b = tn.add_timepoint();
  ASSERT_TRUE(tn.add_constraint(a, b, 10, 10));
  ASSERT_TRUE(tn.add_constraint(TemporalNetwork::origin(), b, 0, 40));
  EXPECT_EQ(tn.latest(a), 30);
  tn.undo_to(m);
  EXPECT_EQ(tn.timepoint_count(), 2u);
  EXPECT_EQ(tn.latest(a), 90);
  EXPECT_EQ(tn.earliest(a), 3);
  EXPECT_EQ(tn.constraints().size(), 1u);
}

TEST(TemporalNetwork, RemovingAnOldConstraintRelaxesBounds) {
  TemporalNetwork tn(100);
  TimepointId a = tn.add_timepoint(), b = tn.add_timepoint();
  TemporalConstraintId first;
  ASSERT_TRUE(tn.add_constraint(TemporalNetwork::origin(), a, 20, 30, &first));
  ASSERT_TRUE(tn.add_constraint(a, b, 5, 5));
  EXPECT_EQ(tn.earliest(b), 25);
  tn.remove_constraint(first);
  EXPECT_EQ(tn.earliest(b), 5);
  EXPECT_EQ(tn.latest(a), 95);
}

// All-pairs shortest paths of the same network, with the origin edges, as the reference.
std::vector<std::vector<Time>> floyd_warshall(const TemporalNetwork& tn) {
  const std::size_t n = tn.timepoint_count();
  std::vector<std::vector<Time>> d(n, std::vector<Time>(n, kInfinity));
  for (std::size_t i = 0; i < n; ++i) {
    d[i][i] = 0;
    if (i) {
      d[0][i] = std::min(d[0][i], tn.horizon());
      d[i][0] = std::min<Time>(d[i][0], 0);
    }
  }
  for (const auto& c : tn.constraints()) {
    if (!c.active) continue;
    d[c.from][c.to] = std::min(d[c.from][c.to], c.ub);
    d[c.to][c.from] = std::min(d[c.to][c.from], -c.lb);
  }
  for (std::size_t k = 0; k < n; ++k)
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j)
        if (d[i][k] < kInfinity && d[k][j] < kInfinity)
          d[i][j] = std::min(d[i][j], d[i][k] + d[k][j]);
  return d;
}

bool has_negative_cycle(const std::vector<std::vector<Time>>& d) {
  for (std::size_t i = 0; i < d.size(); ++i)
    if (d[i][i] < 0) return true;
  return false;
}

TEST(TemporalNetwork, AgreesWithFloydWarshallOnRandomNetworks) {
  std::mt19937 rng(7);
  int rejected = 0, accepted = 0;
  for (int round = 0; round < 60; ++round) {
    TemporalNetwork tn(200);
    const int n = 3 + round % 8;
    for (int i = 0; i < n; ++i) tn.add_timepoint();
    std::uniform_int_distribution<int> pick(0, n), lb(-30, 40), width(0, 50);
    for (int k = 0; k < 3 * n; ++k) {
      TimepointId a = pick(rng), b = pick(rng);
      if (a == b) continue;
      Time l = lb(rng), u = l + width(rng);
      TemporalResult r = tn.add_constraint(a, b, l, u);
      // Reference: the same network with this constraint, by Floyd-Warshall.
      auto d = floyd_warshall(tn);  // without the candidate (rejected ones are inactive)
      if (!r) {
        ++rejected;
        d[a][b] = std::min(d[a][b], u);
        d[b][a] = std::min(d[b][a], -l);
        // Close the new edges once more.
        for (std::size_t i = 0; i < d.size(); ++i)
          for (std::size_t j = 0; j < d.size(); ++j) {
            Time via_ab =
                (d[i][a] < kInfinity && d[b][j] < kInfinity) ? d[i][a] + u + d[b][j] : kInfinity;
            Time via_ba =
                (d[i][b] < kInfinity && d[a][j] < kInfinity) ? d[i][b] - l + d[a][j] : kInfinity;
            d[i][j] = std::min({d[i][j], via_ab, via_ba});
          }
        EXPECT_TRUE(has_negative_cycle(d)) << "round " << round << " constraint " << k;
        continue;
      }
      ++accepted;
      ASSERT_FALSE(has_negative_cycle(d));
      for (TimepointId t = 1; t < tn.timepoint_count(); ++t) {
        EXPECT_EQ(tn.latest(t), d[0][t]) << "round " << round << " t" << t;
        EXPECT_EQ(tn.earliest(t), -d[t][0]) << "round " << round << " t" << t;
      }
      for (TimepointId x = 0; x < tn.timepoint_count(); ++x)
        for (TimepointId y = 0; y < tn.timepoint_count(); ++y) {
          ASSERT_EQ(tn.shortest_distance(x, y), d[x][y]) << "round " << round;
          ASSERT_EQ(tn.shortest_distances(x)[y], d[x][y]);
          // With a cutoff: exact at or below it, above it otherwise.
          const Time cutoff = lb(rng);
          if (d[x][y] <= cutoff)
            ASSERT_EQ(tn.shortest_distance(x, y, cutoff), d[x][y]);
          else
            ASSERT_GT(tn.shortest_distance(x, y, cutoff), cutoff);
        }
    }
  }
  EXPECT_GT(rejected, 10);
  EXPECT_GT(accepted, 100);
}

// Issue 29: the incremental network against a from-scratch recomputation, over many
// insertions, undos and removals on random networks.
struct ReferenceBounds {
  bool consistent = true;
  std::vector<Time> earliest, latest;
};

// Bellman-Ford from the origin over the active constraints (plus `extra`, a candidate), with
// the implicit 0 <= t <= horizon edges: the bounds, or inconsistent on a negative cycle.
ReferenceBounds recompute_from_scratch(const TemporalNetwork& tn,
                                       const TemporalNetwork::Constraint* extra = nullptr) {
  struct Arc {
    std::size_t from, to;
    Time w;
  };
  const std::size_t n = tn.timepoint_count();
  std::vector<Arc> arcs;
  auto add = [&](const TemporalNetwork::Constraint& c) {
    if (c.ub < kInfinity) arcs.push_back({c.from, c.to, c.ub});
    if (c.lb > -kInfinity) arcs.push_back({c.to, c.from, -c.lb});
  };
  for (const auto& c : tn.constraints())
    if (c.active) add(c);
  if (extra) add(*extra);
  for (std::size_t t = 1; t < n; ++t) {
    if (tn.horizon() < kInfinity) arcs.push_back({0, t, tn.horizon()});
    arcs.push_back({t, 0, 0});
  }
  // dist[x]: shortest path origin -> x (latest); back[x]: shortest path x -> origin (-earliest).
  std::vector<Time> dist(n, kInfinity), back(n, kInfinity);
  dist[0] = back[0] = 0;
  for (std::size_t round = 0; round <= n; ++round) {
    bool changed = false;
    for (const Arc& a : arcs) {
      if (dist[a.from] < kInfinity && dist[a.from] + a.w < dist[a.to])
        dist[a.to] = dist[a.from] + a.w, changed = true;
      if (back[a.to] < kInfinity && back[a.to] + a.w < back[a.from])
        back[a.from] = back[a.to] + a.w, changed = true;
    }
    if (!changed) {
      ReferenceBounds r;
      r.latest = dist;
      for (Time b : back) r.earliest.push_back(-b);
      return r;
    }
  }
  return {false, {}, {}};
}

void expect_bounds_as_recomputed(const TemporalNetwork& tn, const std::string& where) {
  const ReferenceBounds ref = recompute_from_scratch(tn);
  ASSERT_TRUE(ref.consistent) << where;
  for (TimepointId t = 0; t < tn.timepoint_count(); ++t) {
    ASSERT_EQ(tn.latest(t), ref.latest[t]) << where << " t" << t;
    ASSERT_EQ(tn.earliest(t), ref.earliest[t]) << where << " t" << t;
  }
}

TEST(TemporalNetwork, IncrementalBoundsEqualRecomputationOverInsertionsUndosAndRemovals) {
  std::mt19937 rng(29);
  int added = 0, rejected = 0, undos = 0, removals = 0;
  for (int round = 0; round < 12; ++round) {
    TemporalNetwork tn(round % 3 == 0 ? kInfinity : 500);
    const int n = 20 + 5 * round;
    for (int i = 0; i < n; ++i) tn.add_timepoint();
    std::vector<TemporalNetwork::Mark> marks{tn.mark()};
    std::uniform_int_distribution<int> op(0, 19), lb(-20, 60), width(0, 80);
    for (int step = 0; step < 400; ++step) {
      const std::string where = "round " + std::to_string(round) + " step " + std::to_string(step);
      const int o = op(rng);
      if (o == 0 && marks.size() > 1) {
        // Back to a random earlier mark (a search backtracking several levels).
        const std::size_t k = std::uniform_int_distribution<std::size_t>(0, marks.size() - 1)(rng);
        tn.undo_to(marks[k]);
        marks.resize(k + 1);
        ++undos;
      } else if (o == 1) {
        std::vector<TemporalConstraintId> active;
        for (TemporalConstraintId c = 0; c < tn.constraints().size(); ++c)
          if (tn.constraints()[c].active) active.push_back(c);
        if (active.empty()) continue;
        tn.remove_constraint(
            active[std::uniform_int_distribution<std::size_t>(0, active.size() - 1)(rng)]);
        ++removals;
      } else if (o == 2) {
        marks.push_back(tn.mark());
        tn.add_timepoint();
      } else {
        const TimepointId a = std::uniform_int_distribution<TimepointId>(
                              0, tn.timepoint_count() - 1)(rng),
                          b = std::uniform_int_distribution<TimepointId>(
                              0, tn.timepoint_count() - 1)(rng);
        if (a == b) continue;
        const Time l = lb(rng), u = l + width(rng);
        const TemporalNetwork::Constraint candidate{a, b, l, u, true};
        const bool expected = recompute_from_scratch(tn, &candidate).consistent;
        if (o % 4 == 0) marks.push_back(tn.mark());
        TemporalConstraintId id;
        const TemporalResult r = tn.add_constraint(a, b, l, u, &id);
        ASSERT_EQ(bool(r), expected) << where;
        if (r) {
          ++added;
        } else {
          ++rejected;
          ASSERT_FALSE(r.conflict.empty());
          EXPECT_EQ(r.conflict.front(), id) << where;  // detected at the closing constraint
        }
      }
      expect_bounds_as_recomputed(tn, where);
      if (::testing::Test::HasFatalFailure()) return;
    }
  }
  EXPECT_GT(added, 2000);
  EXPECT_GT(rejected, 100);
  EXPECT_GT(undos, 50);
  EXPECT_GT(removals, 100);
}

TEST(TemporalNetwork, CycleIsDetectedAtTheEdgeThatClosesItWithTheConstraintsOfTheCycle) {
  for (bool explain : {false, true}) {
    TemporalNetwork tn(10000);
    tn.set_explain_conflicts(explain);
    std::vector<TimepointId> ring;
    for (int i = 0; i < 6; ++i) ring.push_back(tn.add_timepoint());
    // Bystanders on both sides of the ring, which the conflict must not name.
    const TimepointId before = tn.add_timepoint(), after = tn.add_timepoint();
    TemporalConstraintId side1, side2;
    ASSERT_TRUE(tn.add_constraint(before, ring[0], 5, 100, &side1));
    ASSERT_TRUE(tn.add_constraint(ring[5], after, 5, 100, &side2));
    std::vector<TemporalConstraintId> cycle;
    for (int i = 0; i + 1 < 6; ++i) {
      TemporalConstraintId c;
      ASSERT_TRUE(tn.add_constraint(ring[i], ring[i + 1], 10, 20, &c));
      cycle.push_back(c);
    }
    // ring[5] - ring[0] is in [50, 100]; ring[5] - ring[0] <= 40 closes a negative cycle.
    const auto mark = tn.mark();
    const auto bounds_before = tn.bounds(ring[3]);
    TemporalConstraintId closing;
    const TemporalResult r = tn.add_constraint(ring[0], ring[5], 0, 40, &closing);
    ASSERT_FALSE(r);
    EXPECT_EQ(r.conflict.front(), closing);
    std::vector<TemporalConstraintId> got(r.conflict.begin() + 1, r.conflict.end());
    std::sort(got.begin(), got.end());
    EXPECT_EQ(got, cycle) << "explain " << explain;
    // Nothing of the failed attempt is left, and the network goes on.
    EXPECT_EQ(tn.mark().trail, mark.trail);
    EXPECT_EQ(tn.bounds(ring[3]).earliest, bounds_before.earliest);
    EXPECT_EQ(tn.bounds(ring[3]).latest, bounds_before.latest);
    EXPECT_TRUE(tn.add_constraint(ring[0], ring[5], 0, 50));
    EXPECT_EQ(tn.shortest_distance(ring[0], ring[5]), 50);
    expect_bounds_as_recomputed(tn, "after the cycle");
  }
}

TEST(TemporalNetwork, AddingAConstraintVisitsOnlyWhatItChanges) {
  // A big network, then a constraint between two fresh timepoints and one that tightens a
  // short chain: the relaxations counted stay at the size of the change.
  TemporalNetwork tn(1000000);
  std::mt19937 rng(3);
  for (int i = 1; i <= 20000; ++i) {
    tn.add_timepoint();
    if (i > 1) {
      ASSERT_TRUE(tn.add_constraint(std::uniform_int_distribution<TimepointId>(1, i - 1)(rng), i,
                                    1, 50));
    }
  }
  const TimepointId a = tn.add_timepoint(), b = tn.add_timepoint(), c = tn.add_timepoint();
  const std::size_t p0 = tn.propagations();
  ASSERT_TRUE(tn.add_constraint(a, b, 10, 20));
  EXPECT_LE(tn.propagations() - p0, 10u);
  ASSERT_TRUE(tn.add_constraint(b, c, 10, 20));
  const std::size_t p1 = tn.propagations();
  const auto m = tn.mark();
  ASSERT_TRUE(tn.add_constraint(TemporalNetwork::origin(), c, 0, 100));
  // a, b and c each get a new latest time; each has at most two arcs to look along.
  EXPECT_EQ(tn.mark().trail - m.trail, 3u);
  EXPECT_LE(tn.propagations() - p1, 12u);
  EXPECT_EQ(tn.latest(a), 80);
}

TEST(TemporalNetwork, EachBoundIsTrailedOnceAfterAMark) {
  // Every link of a chain under a horizon moves the latest time of every timepoint before it:
  // the trail keeps the first change of each bound after the mark, not all of them.
  TemporalNetwork tn(1000000);
  const TimepointId first = tn.add_timepoint();
  ASSERT_TRUE(tn.add_constraint(TemporalNetwork::origin(), first, 0, 10));
  const auto m = tn.mark();
  const auto first_bounds = tn.bounds(first);
  TimepointId previous = first;
  const std::size_t length = 2000;
  for (std::size_t i = 0; i < length; ++i) {
    const TimepointId next = tn.add_timepoint();
    ASSERT_TRUE(tn.add_constraint(previous, next, 100, kInfinity));
    previous = next;
  }
  EXPECT_EQ(tn.latest(first), 10);
  EXPECT_EQ(tn.latest(previous - 1), 1000000 - 100);
  EXPECT_LE(tn.mark().trail - m.trail, 2 * length + 2);
  expect_bounds_as_recomputed(tn, "chain");
  // A link the horizon cannot hold fails and leaves every bound as it was.
  const auto before = tn.bounds(first + 1);
  EXPECT_FALSE(tn.add_constraint(previous, tn.add_timepoint(), 1000000, kInfinity));
  EXPECT_EQ(tn.bounds(first + 1).latest, before.latest);
  expect_bounds_as_recomputed(tn, "after the failed link");
  tn.undo_to(m);
  EXPECT_EQ(tn.timepoint_count(), 2u);
  EXPECT_EQ(tn.bounds(first).earliest, first_bounds.earliest);
  EXPECT_EQ(tn.bounds(first).latest, first_bounds.latest);
}

TEST(TemporalNetwork, RemovalIsUndoneByTheMarkBeforeIt) {
  TemporalNetwork tn(100);
  const TimepointId a = tn.add_timepoint(), b = tn.add_timepoint();
  TemporalConstraintId first, second;
  ASSERT_TRUE(tn.add_constraint(TemporalNetwork::origin(), a, 20, 30, &first));
  const auto m = tn.mark();
  ASSERT_TRUE(tn.add_constraint(a, b, 5, 5, &second));
  tn.remove_constraint(first);
  EXPECT_EQ(tn.earliest(b), 5);
  EXPECT_FALSE(tn.constraints()[first].active);
  tn.undo_to(m);
  EXPECT_TRUE(tn.constraints()[first].active);
  EXPECT_EQ(tn.constraints().size(), 1u);
  EXPECT_EQ(tn.earliest(a), 20);
  EXPECT_EQ(tn.latest(a), 30);
  // The restored constraint propagates again.
  ASSERT_TRUE(tn.add_constraint(a, b, 5, 5));
  EXPECT_EQ(tn.earliest(b), 25);
  EXPECT_FALSE(tn.add_constraint(TemporalNetwork::origin(), b, 0, 10));
}

TEST(TemporalNetwork, UnknownTimepointsAreRefused) {
  TemporalNetwork tn(100);
  const TimepointId a = tn.add_timepoint();
  EXPECT_THROW((void)tn.add_constraint(a, a + 1, 0, 1), std::out_of_range);
  EXPECT_THROW((void)tn.add_constraint(a + 5, a, 0, 1), std::out_of_range);
  EXPECT_TRUE(tn.constraints().empty());
}

}  // namespace
}  // namespace autonomy::planner
