#include "simulator/report/run_metrics.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <stdexcept>

namespace autonomy::sim {
namespace {

using geometry::Rect;
using geometry::Vec2;

RobotTickSample robot(const std::string& id, Vec2 p, bool finished, bool connected) {
  return {id, p, finished, connected};
}

// Segment a-b against an axis-aligned rectangle (slab test): true when they share a point.
bool segment_hits(const Rect& r, const Vec2& a, const Vec2& b) {
  double t0 = 0.0, t1 = 1.0;
  const Vec2 d = b - a;
  const double lo[2] = {r.min_x, r.min_y}, hi[2] = {r.max_x, r.max_y};
  for (int k = 0; k < 2; ++k) {
    if (std::abs(d[k]) < 1e-15) {
      if (a[k] < lo[k] || a[k] > hi[k]) return false;
      continue;
    }
    double ta = (lo[k] - a[k]) / d[k], tb = (hi[k] - a[k]) / d[k];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return false;
  }
  return true;
}

// A 6 m x 3 m map with 1 m cells: 6 columns, 3 rows. A wall from x = 2.9 to 3.1, full height,
// splits it into a left part (columns 0-2) and a right part (columns 3-5).
struct WalledMap {
  Rect wall{2.9, 0.0, 3.1, 3.0};
  int sight_tests = 0;
  CoverageSettings settings() const { return {{0.0, 0.0, 6.0, 3.0}, 1.0, 3.0}; }
  LineOfSight sight() {
    return [this](const Vec2& a, const Vec2& b) {
      ++sight_tests;
      return !segment_hits(wall, a, b);
    };
  }
};

TEST(RunMetrics, TimeDistanceAndConnectivityByHand) {
  RunMetrics metrics({{0, 0, 20, 20}, 1.0, 3.0}, {});
  // Four steps of 0.5 s. r1 walks 5 m, waits, finishes during step 3, walks 5 m more after.
  // r2 appears in step 2 and walks 1 m.
  metrics.add({0.5, {robot("r1", {0, 0}, false, true)}, true});
  metrics.add({0.5, {robot("r1", {3, 4}, false, true), robot("r2", {1, 1}, false, false)}, true});
  metrics.add({0.5, {robot("r1", {3, 4}, true, false), robot("r2", {1, 2}, false, true)}, false});
  metrics.add({0.5, {robot("r1", {6, 8}, true, false), robot("r2", {1, 2}, false, true)}, true});
  const auto r = metrics.report();
  ASSERT_EQ(r.robots.size(), 2u);
  const auto& r1 = r.robots[0];
  EXPECT_EQ(r1.id, "r1");
  EXPECT_DOUBLE_EQ(r1.mission_time_s, 1.5);  // steps 1-3; finished at the end of step 3
  EXPECT_DOUBLE_EQ(r1.distance_m, 10.0);
  EXPECT_DOUBLE_EQ(r1.time_connected_s, 1.0);
  EXPECT_DOUBLE_EQ(r1.percent_time_connected, 50.0);
  EXPECT_TRUE(r1.finished);
  const auto& r2 = r.robots[1];
  EXPECT_DOUBLE_EQ(r2.mission_time_s, 1.5);
  EXPECT_DOUBLE_EQ(r2.distance_m, 1.0);
  EXPECT_DOUBLE_EQ(r2.time_connected_s, 1.0);
  EXPECT_DOUBLE_EQ(r2.present_time_s, 1.5);
  EXPECT_NEAR(r2.percent_time_connected, 200.0 / 3.0, 1e-12);
  EXPECT_FALSE(r2.finished);

  EXPECT_DOUBLE_EQ(r.team.run_time_s, 2.0);
  EXPECT_EQ(r.team.steps, 4);
  EXPECT_DOUBLE_EQ(r.team.mission_time_s, 1.5);
  EXPECT_DOUBLE_EQ(r.team.distance_m, 11.0);
  EXPECT_DOUBLE_EQ(r.team.time_fully_connected_s, 1.5);
  EXPECT_DOUBLE_EQ(r.team.percent_time_fully_connected, 75.0);
  EXPECT_FALSE(r.team.all_finished);
}

TEST(RunMetrics, ARobotGivenANewGoalCountsTimeAgain) {
  RunMetrics metrics({{0, 0, 5, 5}, 1.0, 3.0}, {});
  for (bool finished : {false, true, true, false, false})
    metrics.add({1.0, {robot("r", {1, 1}, finished, false)}, true});
  // Counted: step 1 (new), 2 (was unfinished), 5 (unfinished after step 4); not 3 and 4.
  EXPECT_DOUBLE_EQ(metrics.report().robots[0].mission_time_s, 3.0);
}

TEST(RunMetrics, EmptyRunHasZeroPercentages) {
  RunMetrics metrics({{0, 0, 5, 5}, 1.0, 3.0}, {});
  const auto r = metrics.report();
  EXPECT_EQ(r.team.steps, 0);
  EXPECT_DOUBLE_EQ(r.team.percent_time_fully_connected, 0.0);
  EXPECT_FALSE(r.team.all_finished);
  EXPECT_EQ(r.team.cells_total, 25);
}

TEST(CoverageGrid, SizesAndTheInclusiveSquare) {
  CoverageGrid grid({{0, 0, 5.5, 3}, 1.0, 3.0});
  EXPECT_EQ(grid.columns(), 6);  // the last column sticks out by 0.5 m
  EXPECT_EQ(grid.rows(), 3);
  EXPECT_TRUE(grid.centre(5, 2).isApprox(Vec2(5.5, 2.5)));
  auto count = [&](Vec2 p) {
    int n = 0;
    grid.for_each_sensed(p, [&](int, int) { ++n; });
    return n;
  };
  EXPECT_EQ(count({1.5, 1.5}), 9);   // square [0,3]^2: centres 0.5, 1.5, 2.5 each way
  EXPECT_EQ(count({1.0, 1.0}), 9);   // square [-0.5,2.5]^2: centres on its edge count
  EXPECT_EQ(count({0.2, 0.2}), 4);   // clipped by the grid: centres 0.5, 1.5 each way
  EXPECT_EQ(count({1.2, 1.5}), 9);   // [-0.3, 2.7] x [0, 3]

  CoverageGrid narrow({{0, 0, 5.5, 3}, 1.0, 2.0});
  int n = 0;
  narrow.for_each_sensed({1.2, 1.5}, [&](int, int) { ++n; });
  EXPECT_EQ(n, 6);  // [0.2, 2.2] x [0.5, 2.5]: x 0.5, 1.5; y 0.5, 1.5, 2.5
}

TEST(CoverageGrid, RejectsUnusableSettings) {
  EXPECT_THROW(CoverageGrid({{0, 0, 0, 3}, 1.0, 3.0}), std::invalid_argument);
  EXPECT_THROW(CoverageGrid({{0, 0, 3, 3}, 0.0, 3.0}), std::invalid_argument);
  EXPECT_THROW(CoverageGrid({{0, 0, 3, 3}, 1.0, -1.0}), std::invalid_argument);
}

TEST(RunMetrics, CoverageDoesNotSeeThroughAWall) {
  WalledMap map;
  RunMetrics metrics(map.settings(), map.sight());
  // r1 left of the wall sees columns 0-2 (9 cells). r2 at x = 2.5 has columns 1-3 in its
  // square, but column 3 (x = 3.5) is behind the wall: 6 cells, none new for the team.
  metrics.add({1.0, {robot("r1", {1.5, 1.5}, false, true), robot("r2", {2.5, 1.5}, false, true)}, true});
  auto r = metrics.report();
  EXPECT_EQ(r.robots[0].cells_covered, 9);
  EXPECT_EQ(r.robots[1].cells_covered, 6);
  EXPECT_EQ(r.team.cells_covered, 9);
  EXPECT_DOUBLE_EQ(r.team.area_covered_m2, 9.0);
  EXPECT_DOUBLE_EQ(r.team.percent_covered, 50.0);

  // r2 goes round to x = 4.5 (the metric does not care how): columns 3-5, 9 new cells.
  metrics.add({1.0, {robot("r1", {1.5, 1.5}, false, true), robot("r2", {4.5, 1.5}, false, true)}, true});
  r = metrics.report();
  EXPECT_EQ(r.robots[1].cells_covered, 15);
  EXPECT_EQ(r.team.cells_covered, 18);
  EXPECT_DOUBLE_EQ(r.team.percent_covered, 100.0);
  EXPECT_EQ(std::count(metrics.covered().begin(), metrics.covered().end(), true), 18);
}

TEST(RunMetrics, WithoutAWallTheSameStepSeesTheFarColumn) {
  RunMetrics metrics({{0.0, 0.0, 6.0, 3.0}, 1.0, 3.0}, {});
  metrics.add({1.0, {robot("r2", {2.5, 1.5}, false, true)}, true});
  EXPECT_EQ(metrics.report().robots[0].cells_covered, 9);
}

TEST(RunMetrics, CoveredCellsAreNotTestedForSightAgain) {
  WalledMap map;
  RunMetrics metrics(map.settings(), map.sight());
  metrics.add({1.0, {robot("r1", {1.5, 1.5}, false, true)}, true});
  EXPECT_EQ(map.sight_tests, 9);
  metrics.add({1.0, {robot("r1", {1.5, 1.5}, false, true)}, true});
  EXPECT_EQ(map.sight_tests, 9);
  // Cells behind the wall are tested every time (a door may have opened).
  metrics.add({1.0, {robot("r1", {2.5, 1.5}, false, true)}, true});
  EXPECT_EQ(map.sight_tests, 12);
  metrics.add({1.0, {robot("r1", {2.5, 1.5}, false, true)}, true});
  EXPECT_EQ(map.sight_tests, 15);
}

TEST(RunMetrics, WritesCsvAndJson) {
  WalledMap map;
  RunMetrics metrics(map.settings(), map.sight());
  metrics.add({0.5, {robot("r1", {1.5, 1.5}, false, true), robot("r2", {2.5, 1.5}, false, false)}, false});
  metrics.add({0.5, {robot("r1", {1.5, 2.5}, true, true), robot("r2", {4.5, 1.5}, true, true)}, true});
  const auto r = metrics.report();
  EXPECT_EQ(metrics_csv(r),
            "robot,mission_time_s,distance_m,time_connected_s,percent_time_connected,cells_covered,"
            "area_covered_m2,finished\n"
            "r1,1,1,1,100,9,9,true\n"
            "r2,1,2,0.5,50,15,15,true\n"
            "team,1,3,0.5,50,18,18,true\n");
  const auto j = nlohmann::json::parse(metrics_json(r));
  EXPECT_EQ(j["coverage"]["cells_total"], 18);
  EXPECT_EQ(j["coverage"]["sensor_square_m"], 3.0);
  EXPECT_EQ(j["team"]["steps"], 2);
  EXPECT_EQ(j["team"]["percent_time_fully_connected"], 50.0);
  EXPECT_EQ(j["team"]["cells_covered"], 18);
  EXPECT_EQ(j["team"]["all_finished"], true);
  ASSERT_EQ(j["robots"].size(), 2u);
  EXPECT_EQ(j["robots"][1]["id"], "r2");
  EXPECT_EQ(j["robots"][1]["distance_m"], 2.0);
  EXPECT_EQ(j["robots"][1]["percent_time_connected"], 50.0);
}

}  // namespace
}  // namespace autonomy::sim
