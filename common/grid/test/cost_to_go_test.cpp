#include "common/grid/cost_to_go.hpp"
#include "common/grid/map_classes.hpp"
#include "common/grid/random_map.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace autonomy::grid {
namespace {

const float kSqrt2 = static_cast<float>(std::sqrt(2.0));

// Rows top first, '#' blocked; raster row 0 is the last string.
OccupancyRaster picture(const std::vector<std::string>& rows, double res = 1.0) {
  const int h = static_cast<int>(rows.size());
  const int w = static_cast<int>(rows.front().size());
  OccupancyRaster r(w, h, res);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      if (rows[static_cast<std::size_t>(y)][static_cast<std::size_t>(x)] == '#')
        r.set_blocked({x, h - 1 - y}, true);
    }
  }
  return r;
}

// Independent cells dropped with probability `percent`; goal patch kept free.
OccupancyRaster noise(int w, int h, int percent, unsigned seed, Cell goal) {
  OccupancyRaster r(w, h, 0.2);
  std::mt19937 rng(seed);
  for (int row = 0; row < h; ++row) {
    for (int col = 0; col < w; ++col) {
      const bool near_goal = std::abs(col - goal.col) <= 1 && std::abs(row - goal.row) <= 1;
      if (!near_goal && static_cast<int>(rng() % 100) < percent) r.set_blocked({col, row}, true);
    }
  }
  return r;
}

std::vector<float> layer_for(const OccupancyRaster& r, unsigned seed, float max_value) {
  std::mt19937 rng(seed);
  std::vector<float> v(r.cell_count());
  for (auto& x : v) x = max_value * static_cast<float>(rng() % 1000) / 1000.0f;
  return v;
}

// The contract: bit-identical to the float textbook Dijkstra, float rounding away from the double
// one, and the same +inf pattern.
void expect_matches_references(const OccupancyRaster& r, Cell goal,
                               const std::vector<CostLayer>& layers, const std::string& what) {
  const auto fast = compute_cost_to_go(r, goal, layers);
  ASSERT_TRUE(fast.ok()) << what << ": " << fast.reason;
  const auto ref_f = reference_dijkstra<float>(r, goal, layers);
  const auto ref_d = reference_dijkstra<double>(r, goal, layers);
  const auto& c = fast.field.costs();
  ASSERT_EQ(c.size(), ref_f.size());
  std::size_t reachable = 0, float_mismatches = 0;
  double max_rel = 0.0;
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (c[i] != ref_f[i]) ++float_mismatches;
    ASSERT_EQ(std::isinf(c[i]), std::isinf(ref_d[i])) << what << " cell " << i;
    if (std::isinf(c[i])) continue;
    ++reachable;
    if (ref_d[i] > 0) max_rel = std::max(max_rel, std::abs(c[i] - ref_d[i]) / ref_d[i]);
  }
  EXPECT_EQ(float_mismatches, 0u) << what;
  EXPECT_LT(max_rel, 1e-5) << what;  // float accumulation along paths of a few hundred steps
  EXPECT_EQ(fast.stats.reachable, reachable) << what;
  EXPECT_LE(fast.stats.work_bytes, 8 * c.size() + 16384) << what;  // + the ring's fixed overhead
}

TEST(CostToGo, OpenGridHasOctileCosts) {
  const auto r = picture({"...", "...", "..."});
  const auto f = compute_cost_to_go(r, {0, 0});
  ASSERT_TRUE(f.ok());
  EXPECT_EQ(f.field.cost({0, 0}), 0.0f);
  EXPECT_EQ(f.field.cost({2, 0}), 2.0f);
  EXPECT_EQ(f.field.cost({1, 1}), kSqrt2);
  EXPECT_EQ(f.field.cost({2, 1}), 1.0f + kSqrt2);
  EXPECT_EQ(f.field.cost({2, 2}), kSqrt2 + kSqrt2);
  EXPECT_EQ(f.stats.reachable, 9u);
  EXPECT_EQ(f.stats.expanded, 9u);
}

TEST(CostToGo, ResolutionScalesSteps) {
  const auto r = picture({"...", "...", "..."}, 0.25);
  const auto f = compute_cost_to_go(r, {2, 2});
  EXPECT_EQ(f.field.cost({0, 2}), 0.5f);
  EXPECT_EQ(f.field.cost({0, 1}), 0.25f + static_cast<float>(0.25 * std::sqrt(2.0)));
}

TEST(CostToGo, NoCornerCuttingAndClosedDiagonalGaps) {
  //   . .
  //   G #
  auto f = compute_cost_to_go(picture({"..", ".#"}), {0, 0});
  EXPECT_EQ(f.field.cost({1, 1}), 2.0f);
  //   # .
  //   G #
  f = compute_cost_to_go(picture({"#.", ".#"}), {0, 0});
  EXPECT_EQ(f.field.cost({1, 1}), kUnreachable);
  EXPECT_FALSE(f.field.reachable({1, 1}));
  EXPECT_EQ(f.stats.reachable, 1u);
}

TEST(CostToGo, WallDetour) {
  //   . . .
  //   . # .
  //   G # .
  const auto f = compute_cost_to_go(picture({"...", ".#.", ".#."}), {0, 0});
  EXPECT_EQ(f.field.cost({1, 2}), 3.0f);
  EXPECT_EQ(f.field.cost({2, 0}), 6.0f);
  EXPECT_EQ(f.field.cost({1, 0}), kUnreachable);
}

TEST(CostToGo, GoalOutsideOrBlockedIsAReasonedResult) {
  const auto r = picture({"..#", "..."});
  auto f = compute_cost_to_go(r, {2, 1});
  EXPECT_EQ(f.status, FieldStatus::kGoalBlocked);
  EXPECT_NE(f.reason.find("(2, 1) is blocked"), std::string::npos) << f.reason;
  for (float c : f.field.costs()) EXPECT_EQ(c, kUnreachable);
  f = compute_cost_to_go(r, {3, 0});
  EXPECT_EQ(f.status, FieldStatus::kGoalOutside);
  EXPECT_EQ(f.field.costs().size(), 6u);
}

TEST(CostToGo, BadLayersAreRejected) {
  const auto r = picture({"...", "..."});
  std::vector<float> short_layer(5, 1.0f);
  EXPECT_EQ(compute_cost_to_go(r, {0, 0}, {CostLayer(short_layer, 1.0f)}).status,
            FieldStatus::kBadLayer);
  std::vector<float> layer(6, 1.0f);
  EXPECT_EQ(compute_cost_to_go(r, {0, 0}, {CostLayer(layer, -1.0f)}).status,
            FieldStatus::kBadLayer);
  layer[3] = std::nanf("");
  const auto nan = compute_cost_to_go(r, {0, 0}, {CostLayer(layer, 1.0f)});
  EXPECT_EQ(nan.status, FieldStatus::kBadLayer);
  EXPECT_NE(nan.reason.find("index 3"), std::string::npos) << nan.reason;
  layer[3] = kUnreachable;
  EXPECT_EQ(compute_cost_to_go(r, {0, 0}, {CostLayer(layer, 1.0f)}).status, FieldStatus::kBadLayer);
}

TEST(CostToGo, LayerPricesTheEnteredCell) {
  // One row: G . .   layer 0 5 1, gain 2 -> steps cost 1 + 2 * layer(entered).
  const auto r = picture({"..."});
  std::vector<float> layer = {100.0f, 5.0f, 1.0f};  // the goal's own value is never paid
  const auto f = compute_cost_to_go(r, {0, 0}, {CostLayer(layer, 2.0f)});
  ASSERT_TRUE(f.ok());
  EXPECT_EQ(f.field.cost({1, 0}), 11.0f);
  EXPECT_EQ(f.field.cost({2, 0}), 14.0f);
}

TEST(CostToGo, LayerSteersAroundExpensiveCells) {
  //   . . .
  //   . . .
  //   G . .   the middle column is expensive except at the top
  const auto r = picture({"...", "...", "..."});
  std::vector<float> layer(9, 0.0f);
  layer[1] = layer[4] = 10.0f;  // cells (1,0) and (1,1)
  const auto f = compute_cost_to_go(r, {0, 0}, {CostLayer(layer, 1.0f)});
  // From (2,0): over the top, (2,0)->(2,1)->(1,2)->(0,1)->(0,0) = 1 + 2 sqrt2 + 1.
  EXPECT_NEAR(f.field.cost({2, 0}), 2.0 + 2.0 * std::sqrt(2.0), 1e-5);
  EXPECT_EQ(f.field.downhill_step({2, 0}), (Step{0, 1}));
}

TEST(CostToGo, EqualsTextbookDijkstraOnRandomMaps) {
  for (int size : {1, 2, 7, 40, 129, 300}) {
    for (int percent : {0, 10, 25, 40}) {
      const Cell goal{size / 3, size / 2};
      const auto r =
          noise(size, size + 3, percent, static_cast<unsigned>(size * 100 + percent), goal);
      expect_matches_references(r, goal, {},
                                "noise " + std::to_string(size) + "/" + std::to_string(percent));
    }
  }
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    const auto r = random_rectangles(500, 320, 0.15 + 0.1 * static_cast<double>(seed), seed, 0.05);
    expect_matches_references(r, random_map_goal(r), {}, "rectangles seed " + std::to_string(seed));
  }
}

// The map classes of field_bench (building floors, SLAM-like, mazes, clutter, blocks) at small
// and odd sizes (partial tiles at the right and top edges), each goal placement.
TEST(CostToGo, EqualsTextbookDijkstraOnEveryMapClass) {
  for (MapClass c : kAllMapClasses) {
    for (const auto& [w, h] : {std::pair{250, 250}, std::pair{203, 131}, std::pair{61, 97}}) {
      const auto r = make_map(c, w, h, 11, 0.05);
      for (GoalPlacement g : kAllGoalPlacements) {
        const auto goal = place_goal(r, g);
        ASSERT_TRUE(goal.has_value()) << to_string(c);
        expect_matches_references(r, *goal, {},
                                  std::string(to_string(c)) + " " + std::to_string(w) + "x" +
                                      std::to_string(h) + " " + to_string(g));
      }
    }
  }
}

// Goals on the raster's edges and corners, where tiles and their rings are cut off.
TEST(CostToGo, EqualsTextbookDijkstraWithGoalsOnTheEdges) {
  const auto r = make_map(MapClass::kClutter, 77, 45, 5, 1.0);
  for (const Cell goal : {Cell{0, 0}, Cell{76, 44}, Cell{0, 44}, Cell{76, 0}, Cell{40, 0},
                          Cell{0, 20}, Cell{76, 23}, Cell{39, 44}}) {
    OccupancyRaster open = r;
    open.set_blocked(goal, false);
    expect_matches_references(open, goal, {},
                              "goal " + std::to_string(goal.col) + "," + std::to_string(goal.row));
  }
}

TEST(CostToGo, EqualsTextbookDijkstraWithCostLayers) {
  for (int size : {9, 64, 257}) {
    const Cell goal{1, 1};
    const auto r = noise(size, size, 20, static_cast<unsigned>(size), goal);
    const auto a = layer_for(r, 1, 3.0f);
    const auto b = layer_for(r, 2, 0.5f);
    expect_matches_references(r, goal, {CostLayer(a, 0.7f)}, "one layer " + std::to_string(size));
    expect_matches_references(r, goal, {CostLayer(a, 0.2f), CostLayer(b, 4.0f)},
                              "two layers " + std::to_string(size));
    // Steps up to 400 resolutions would need a 2048-bucket ring: too much for these small maps,
    // so the heap runs.
    const auto steep = layer_for(r, 3, 400.0f);
    expect_matches_references(r, goal, {CostLayer(steep, 1.0f)},
                              "steep layer " + std::to_string(size));
    EXPECT_TRUE(compute_cost_to_go(r, goal, {CostLayer(steep, 1.0f)}).stats.heap_fallback);
  }
  // A map large enough for that ring.
  const auto big = random_rectangles(700, 700, 0.2, 9);
  const auto steep = layer_for(big, 4, 400.0f);
  expect_matches_references(big, random_map_goal(big), {CostLayer(steep, 1.0f)},
                            "steep layer, 700");
  const auto f = compute_cost_to_go(big, random_map_goal(big), {CostLayer(steep, 1.0f)});
  EXPECT_FALSE(f.stats.heap_fallback);
  EXPECT_EQ(f.stats.buckets, 2048u);
}

TEST(CostToGo, HugeLayerCostsUseTheExactHeapFallback) {
  const Cell goal{3, 3};
  const auto r = noise(90, 70, 20, 5, goal);
  const auto a = layer_for(r, 3, 1e5f);
  const auto f = compute_cost_to_go(r, goal, {CostLayer(a, 1.0f)});
  EXPECT_TRUE(f.stats.heap_fallback);
  expect_matches_references(r, goal, {CostLayer(a, 1.0f)}, "heap fallback");
}

TEST(CostToGo, MemoryStaysUnderEightBytesPerCell) {
  const auto r = random_rectangles(1000, 1000, 0.15, 7);
  const auto f = compute_cost_to_go(r, random_map_goal(r));
  ASSERT_TRUE(f.ok());
  const double per_cell =
      static_cast<double>(f.stats.work_bytes) / static_cast<double>(f.stats.cells);
  EXPECT_LT(per_cell, 8.0);
  EXPECT_GE(per_cell, 4.0);  // the output floats at least
  EXPECT_GT(f.stats.buckets, 0u);
}

TEST(CostToGo, AdviceFollowsTheLowestNeighbour) {
  const auto open = compute_cost_to_go(picture({"...", "...", "..."}), {0, 0});
  EXPECT_TRUE(open.field.advice({2, 2}).isApprox(geometry::Vec2(-1.0, -1.0).normalized()));
  EXPECT_EQ(open.field.advice({2, 0}), geometry::Vec2(-1.0, 0.0));
  EXPECT_EQ(open.field.advice({0, 2}), geometry::Vec2(0.0, -1.0));
  EXPECT_EQ(open.field.advice({0, 0}), geometry::Vec2::Zero());  // at the goal
  EXPECT_EQ(open.field.advice({5, 5}), geometry::Vec2::Zero());  // outside

  const auto corner = compute_cost_to_go(picture({"..", ".#"}), {0, 0});
  EXPECT_EQ(corner.field.advice({1, 1}), geometry::Vec2(-1.0, 0.0));  // not past the blocked corner
  EXPECT_EQ(corner.field.advice({1, 0}), geometry::Vec2::Zero());     // blocked

  const auto pocket = compute_cost_to_go(picture({".#."}), {0, 0});
  EXPECT_EQ(pocket.field.advice({2, 0}), geometry::Vec2::Zero());  // unreachable
}

TEST(CostToGo, AdviceTiesGoToTheFirstMoveInOrder) {
  //   . X .    X = (1, 2): W and E both lead around the wall at cost 3; the diagonals
  //   . # .    towards (0, 1) and (2, 1) would clip the wall. E comes first in E, N, W, S.
  //   . G .
  const auto f = compute_cost_to_go(picture({"...", ".#.", "..."}), {1, 0});
  EXPECT_EQ(f.field.cost({0, 2}), 3.0f);
  EXPECT_EQ(f.field.cost({2, 2}), 3.0f);
  EXPECT_EQ(f.field.downhill_step({1, 2}), (Step{1, 0}));
  // Lowest wins over order: from (2, 1) on an open 3 x 2 map with the goal at (1, 0), the
  // diagonal SW reaches the goal itself.
  const auto open = compute_cost_to_go(picture({"...", "..."}), {1, 0});
  EXPECT_EQ(open.field.downhill_step({2, 1}), (Step{-1, -1}));
}

TEST(MapClasses, DeterministicAndShaped) {
  for (MapClass c : kAllMapClasses) {
    const auto a = make_map(c, 300, 200, 3);
    const auto b = make_map(c, 300, 200, 3);
    ASSERT_EQ(a.width(), 300);
    ASSERT_EQ(a.height(), 200);
    std::size_t differ = 0;
    for (int row = 0; row < 200; ++row)
      for (int col = 0; col < 300; ++col) differ += a.blocked({col, row}) != b.blocked({col, row});
    EXPECT_EQ(differ, 0u) << to_string(c);
    const double blocked = static_cast<double>(a.blocked_count()) / 60000.0;
    if (c == MapClass::kArena) {  // mostly unknown space, like Nav2's tb3_sandbox (94.6 %)
      EXPECT_GT(blocked, 0.93) << to_string(c);
      EXPECT_LT(blocked, 0.985) << to_string(c);
    } else {
      EXPECT_GT(blocked, 0.05) << to_string(c);
      EXPECT_LT(blocked, 0.8) << to_string(c);
    }
    EXPECT_EQ(map_class_from_string(to_string(c)), c);
  }
  EXPECT_FALSE(map_class_from_string("office").has_value());
  EXPECT_EQ(goal_placement_from_string("narrow"), GoalPlacement::kNarrow);
}

// The arena: a few percent of a large grid reachable, the rest never touched by the search.
TEST(CostToGo, ArenaInALargeUnknownGridIsExactAndSmall) {
  for (int n : {384, 1000}) {
    const auto r = make_map(MapClass::kArena, n, n, 4, 0.05);
    for (GoalPlacement g : kAllGoalPlacements) {
      const auto goal = place_goal(r, g);
      ASSERT_TRUE(goal.has_value());
      expect_matches_references(r, *goal, {}, "arena " + std::to_string(n) + " " + to_string(g));
      const auto f = compute_cost_to_go(r, *goal);
      const double reached =
          static_cast<double>(f.stats.reachable) / static_cast<double>(f.stats.cells);
      EXPECT_GT(reached, 0.03);
      EXPECT_LT(reached, 0.06);
      if (f.stats.tiles > 0) {
        EXPECT_LT(f.stats.tile_runs, f.stats.tiles / 10);  // only the arena's tiles ran
      }
    }
  }
}

TEST(MapClasses, GoalsAreFreeAndPlacedAsAsked) {
  const auto r = make_map(MapClass::kMaze, 400, 400, 1);
  const auto centre = place_goal(r, GoalPlacement::kCentre);
  const auto corner = place_goal(r, GoalPlacement::kCorner);
  const auto narrow = place_goal(r, GoalPlacement::kNarrow);
  ASSERT_TRUE(centre && corner && narrow);
  for (const Cell& g : {*centre, *corner, *narrow}) EXPECT_FALSE(r.blocked(g));
  EXPECT_LT(std::abs(centre->col - 200) + std::abs(centre->row - 200), 12);
  EXPECT_LT(corner->col + corner->row, 60);
  OccupancyRaster full(5, 5, 1.0);
  for (int y = 0; y < 5; ++y)
    for (int x = 0; x < 5; ++x) full.set_blocked({x, y}, true);
  EXPECT_FALSE(place_goal(full, GoalPlacement::kCentre).has_value());
}

}  // namespace
}  // namespace autonomy::grid
