#include "temporal_network.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

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

}  // namespace
}  // namespace autonomy::planner
