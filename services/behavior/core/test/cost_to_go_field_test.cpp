#include "services/behavior/core/cost_to_go_field.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace autonomy::behavior {
namespace {

using geometry::Vec2;

constexpr float kInf = std::numeric_limits<float>::infinity();
const float kSqrt2 = static_cast<float>(std::sqrt(2.0));

TEST(CostToGoField, OpenGridHasOctileCosts) {
  const auto grid = OccupancyGrid::from_picture({"...", "...", "..."}, 1.0);
  const CostToGoField field(grid, Vec2(0.5, 0.5));
  ASSERT_TRUE(field.has_route_anywhere());
  EXPECT_EQ(field.goal_cell(), (GridCell{0, 0}));
  // Hand-computed: row 0 = 0 1 2; row 1 = 1 r2 1+r2; row 2 = 2 1+r2 2*r2.
  EXPECT_FLOAT_EQ(field.cost({0, 0}), 0.0f);
  EXPECT_FLOAT_EQ(field.cost({1, 0}), 1.0f);
  EXPECT_FLOAT_EQ(field.cost({2, 0}), 2.0f);
  EXPECT_FLOAT_EQ(field.cost({0, 1}), 1.0f);
  EXPECT_FLOAT_EQ(field.cost({1, 1}), kSqrt2);
  EXPECT_FLOAT_EQ(field.cost({2, 1}), 1.0f + kSqrt2);
  EXPECT_FLOAT_EQ(field.cost({0, 2}), 2.0f);
  EXPECT_FLOAT_EQ(field.cost({1, 2}), 1.0f + kSqrt2);
  EXPECT_FLOAT_EQ(field.cost({2, 2}), 2.0f * kSqrt2);
}

TEST(CostToGoField, CostsScaleWithResolution) {
  const auto grid = OccupancyGrid::from_picture({"...", "...", "..."}, 0.25);
  const CostToGoField field(grid, Vec2(0.7, 0.7));  // cell (2, 2)
  EXPECT_FLOAT_EQ(field.cost({0, 0}), 0.5f * kSqrt2);
  EXPECT_FLOAT_EQ(field.cost({0, 2}), 0.5f);
  EXPECT_FLOAT_EQ(field.cost({0, 1}), 0.25f + 0.25f * kSqrt2);
}

TEST(CostToGoField, HandComputedWallDetour) {
  // Goal G at the bottom left; the wall forces the right column to go over the top.
  //   row 2:  . . .
  //   row 1:  . # .
  //   row 0:  G # .
  const auto grid = OccupancyGrid::from_picture({"...", ".#.", ".#."}, 1.0);
  const CostToGoField field(grid, Vec2(0.5, 0.5));
  EXPECT_FLOAT_EQ(field.cost({0, 1}), 1.0f);
  EXPECT_FLOAT_EQ(field.cost({0, 2}), 2.0f);
  EXPECT_FLOAT_EQ(field.cost({1, 2}), 3.0f);  // the diagonal from (0,1) would clip the wall
  EXPECT_FLOAT_EQ(field.cost({2, 2}), 4.0f);
  EXPECT_FLOAT_EQ(field.cost({2, 1}), 5.0f);
  EXPECT_FLOAT_EQ(field.cost({2, 0}), 6.0f);
  EXPECT_EQ(field.cost({1, 0}), kInf);
  EXPECT_EQ(field.cost({1, 1}), kInf);
}

TEST(CostToGoField, NoCornerCutting) {
  //   row 1:  . .
  //   row 0:  G #
  const auto grid = OccupancyGrid::from_picture({"..", ".#"}, 1.0);
  const CostToGoField field(grid, Vec2(0.5, 0.5));
  EXPECT_FLOAT_EQ(field.cost({1, 1}), 2.0f);  // not sqrt(2): the diagonal passes the blocked corner
}

TEST(CostToGoField, DiagonalGapIsClosed) {
  //   row 1:  # .
  //   row 0:  G #
  const auto grid = OccupancyGrid::from_picture({"#.", ".#"}, 1.0);
  const CostToGoField field(grid, Vec2(0.5, 0.5));
  EXPECT_EQ(field.cost({1, 1}), kInf);
  EXPECT_FALSE(field.reachable({1, 1}));
}

TEST(CostToGoField, EnclosedPocketIsUnreachable) {
  const auto grid = OccupancyGrid::from_picture({"..#.", "..#.", "..#."}, 1.0);
  const CostToGoField field(grid, Vec2(0.5, 0.5));
  for (int row = 0; row < 3; ++row) {
    EXPECT_EQ(field.cost({3, row}), kInf);
    EXPECT_EQ(field.cost({2, row}), kInf);
    EXPECT_TRUE(field.reachable({1, row}));
  }
  EXPECT_EQ(field.cost({-1, 0}), kInf);  // outside the grid
  EXPECT_EQ(field.cost_at(Vec2(9.0, 9.0)), kInf);
}

TEST(CostToGoField, BlockedOrOutsideGoalHasNoRouteAnywhere) {
  const auto grid = OccupancyGrid::from_picture({"..#", "..."}, 1.0);
  const CostToGoField blocked(grid, Vec2(2.5, 1.5));
  EXPECT_FALSE(blocked.has_route_anywhere());
  for (float c : blocked.costs()) EXPECT_EQ(c, kInf);
  const CostToGoField outside(grid, Vec2(7.0, 0.5));
  EXPECT_FALSE(outside.has_route_anywhere());
  EXPECT_FALSE(outside.goal_cell());
  for (float c : outside.costs()) EXPECT_EQ(c, kInf);
}

// An independent reference: Bellman-Ford relaxation in double precision until nothing changes.
std::vector<double> bellman_ford(const OccupancyGrid& grid, GridCell goal) {
  const auto& g = grid.geometry();
  const double res = g.resolution_m();
  std::vector<double> cost(g.cell_count(), std::numeric_limits<double>::infinity());
  if (grid.blocked(goal)) return cost;
  cost[g.index(goal)] = 0.0;
  auto free = [&](int c, int r) { return !grid.blocked({c, r}); };
  for (bool changed = true; changed;) {
    changed = false;
    for (int r = 0; r < g.rows(); ++r) {
      for (int c = 0; c < g.cols(); ++c) {
        if (!free(c, r)) continue;
        for (int dr = -1; dr <= 1; ++dr) {
          for (int dc = -1; dc <= 1; ++dc) {
            if ((dr == 0 && dc == 0) || !free(c + dc, r + dr)) continue;
            const bool diagonal = dr != 0 && dc != 0;
            if (diagonal && (!free(c + dc, r) || !free(c, r + dr))) continue;
            const double via = cost[g.index({c + dc, r + dr})] + (diagonal ? res * std::sqrt(2.0) : res);
            if (via < cost[g.index({c, r})] - 1e-12) {
              cost[g.index({c, r})] = via;
              changed = true;
            }
          }
        }
      }
    }
  }
  return cost;
}

OccupancyGrid random_map(unsigned seed, int cols, int rows, int blocked_percent) {
  std::mt19937 rng(seed);  // mt19937's output sequence is fixed by the standard
  std::vector<std::string> picture(static_cast<std::size_t>(rows), std::string(static_cast<std::size_t>(cols), '.'));
  for (auto& line : picture) {
    for (auto& ch : line) ch = static_cast<int>(rng() % 100) < blocked_percent ? '#' : '.';
  }
  // Keep a 3 x 3 patch around the goal cell (0, 0) free so that the goal is not walled in.
  for (std::size_t r = picture.size() - 3; r < picture.size(); ++r) picture[r].replace(0, 3, "...");
  return OccupancyGrid::from_picture(picture, 0.2);
}

TEST(CostToGoField, EqualsBellmanFordOnRandomMaps) {
  for (unsigned seed : {1u, 2u, 3u, 4u, 5u, 6u}) {
    const auto grid = random_map(seed, 17, 13, 12 + static_cast<int>(seed) * 2);
    const CostToGoField field(grid, Vec2(0.1, 0.1));
    const auto reference = bellman_ford(grid, {0, 0});
    int reachable = 0;
    for (std::size_t i = 0; i < reference.size(); ++i) {
      if (std::isinf(reference[i])) {
        EXPECT_EQ(field.costs()[i], kInf) << "seed " << seed << " cell " << i;
      } else {
        ++reachable;
        EXPECT_NEAR(field.costs()[i], reference[i], 1e-4) << "seed " << seed << " cell " << i;
      }
    }
    EXPECT_GT(reachable, 20) << "seed " << seed << " makes a trivial map";
  }
}

TEST(CostToGoField, IsBitIdenticalToTheTextbookFloatDijkstra) {
  // The first version of this class was a textbook float Dijkstra; the fast field must reproduce
  // its costs exactly, on an inflated world map as well as on pictures.
  WorldMap world;
  world.width_m = 30.0;
  world.height_m = 20.0;
  world.obstacles = {{4.0, 3.0, 6.0, 15.0}, {10.0, 0.0, 11.0, 12.0}, {15.0, 8.0, 25.0, 9.0}};
  const OccupancyGrid inflated(world, 0.1, 0.3);
  std::vector<std::pair<const OccupancyGrid*, Vec2>> cases = {{&inflated, Vec2(2.0, 2.0)}};
  const auto noisy = random_map(21, 120, 90, 30);
  cases.push_back({&noisy, Vec2(0.1, 0.1)});
  for (const auto& [grid, goal] : cases) {
    const CostToGoField field(*grid, goal);
    const auto& g = grid->geometry();
    grid::OccupancyRaster raster(g.cols(), g.rows(), g.resolution_m());
    for (int r = 0; r < g.rows(); ++r) {
      for (int c = 0; c < g.cols(); ++c) raster.set_blocked({c, r}, grid->blocked({c, r}));
    }
    const auto goal_cell = *g.cell_at(goal);
    const auto textbook = grid::reference_dijkstra<float>(raster, {goal_cell.col, goal_cell.row});
    ASSERT_EQ(field.costs().size(), textbook.size());
    std::size_t differ = 0;
    for (std::size_t i = 0; i < textbook.size(); ++i) differ += field.costs()[i] != textbook[i];
    EXPECT_EQ(differ, 0u);
  }
}

TEST(CostToGoField, AdviceDirections) {
  const auto open = OccupancyGrid::from_picture({"...", "...", "..."}, 1.0);
  const CostToGoField field(open, Vec2(0.5, 0.5));
  EXPECT_TRUE(field.advice({2, 2}).isApprox(Vec2(-1.0, -1.0).normalized()));
  EXPECT_EQ(field.advice({2, 0}), Vec2(-1.0, 0.0));
  EXPECT_EQ(field.advice({0, 2}), Vec2(0.0, -1.0));
  EXPECT_EQ(field.advice({0, 0}), Vec2::Zero());  // at the goal

  const auto corner = OccupancyGrid::from_picture({"..", ".#"}, 1.0);
  const CostToGoField around(corner, Vec2(0.5, 0.5));
  EXPECT_EQ(around.advice({1, 1}), Vec2(-1.0, 0.0));  // not the diagonal past the blocked corner
  EXPECT_EQ(around.advice({1, 0}), Vec2::Zero());     // blocked

  const auto pocket = OccupancyGrid::from_picture({".#."}, 1.0);
  const CostToGoField cut_off(pocket, Vec2(0.5, 0.5));
  EXPECT_EQ(cut_off.advice({2, 0}), Vec2::Zero());  // unreachable
}

TEST(CostToGoField, AdviceAlwaysLeadsDownhillOnRandomMaps) {
  for (unsigned seed : {11u, 12u, 13u}) {
    const auto grid = random_map(seed, 15, 15, 25);
    const CostToGoField field(grid, Vec2(0.1, 0.1));
    const auto& g = field.geometry();
    for (std::size_t i = 0; i < g.cell_count(); ++i) {
      const GridCell c = g.cell(i);
      const Vec2 a = field.advice(c);
      if (!field.reachable(c) || field.cost(c) == 0.0f) {
        EXPECT_EQ(a, Vec2::Zero());
        continue;
      }
      ASSERT_NEAR(a.norm(), 1.0, 1e-12);
      const auto step = [](double v) { return v > 0.5 ? 1 : (v < -0.5 ? -1 : 0); };
      const GridCell next{c.col + step(a.x()), c.row + step(a.y())};
      EXPECT_LT(field.cost(next), field.cost(c)) << "seed " << seed << " cell " << i;
    }
  }
}

TEST(CostToGoField, NearestReachableCell) {
  const auto grid = OccupancyGrid::from_picture({"....", "..##", "..##"}, 1.0);
  const CostToGoField field(grid, Vec2(0.5, 0.5));
  EXPECT_EQ(field.nearest_reachable(Vec2(2.6, 0.5), 1.5), (GridCell{1, 0}));   // 1.1 m away
  EXPECT_EQ(field.nearest_reachable(Vec2(3.5, 0.9), 2.0), (GridCell{3, 2}));   // 1.6 m away
  EXPECT_FALSE(field.nearest_reachable(Vec2(3.5, 0.9), 1.0));
  EXPECT_EQ(field.nearest_reachable(Vec2(0.6, 0.4), 1.0), (GridCell{0, 0}));  // its own cell
  EXPECT_FALSE(field.nearest_reachable(Vec2(1e300, 0.5), 1.0));
}

}  // namespace
}  // namespace autonomy::behavior
