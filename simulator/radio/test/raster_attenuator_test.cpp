// Occupancy rasters as radio obstacles: hand-computed losses for walls of known thickness, the
// boundary rules (corners, grid lines, radios inside walls, cells outside the map), and the fast
// walk against the slow reference on random maps and segments.
#include "simulator/radio/radio_model.hpp"
#include "simulator/radio/raster_attenuator.hpp"
#include "simulator/radio/test/hand_parameters.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>
#include <stdexcept>

namespace autonomy::sim::radio {
namespace {

using geometry::Vec2;

using test::hand_parameters;

// Blocks columns [c0, c1] of every row.
void block_columns(grid::OccupancyRaster& g, int c0, int c1) {
  for (int row = 0; row < g.height(); ++row)
    for (int col = c0; col <= c1; ++col) g.set_blocked({col, row}, true);
}

std::shared_ptr<grid::OccupancyRaster> raster(int w, int h, double res, grid::RasterOrigin o = {}) {
  return std::make_shared<grid::OccupancyRaster>(w, h, res, o);
}

void expect_raster_same(const Traversal& t, int crossings, int stretches, double inside_m) {
  EXPECT_EQ(t.crossings, crossings);
  EXPECT_EQ(t.stretches, stretches);
  EXPECT_NEAR(t.inside_m, inside_m, 1e-9);
}

// A 20 x 10 m map at 0.5 m with a wall 1 m thick: columns 10 and 11, x in [5, 6].
std::shared_ptr<grid::OccupancyRaster> one_wall() {
  auto g = raster(40, 20, 0.5);
  block_columns(*g, 10, 11);
  return g;
}

TEST(RasterAttenuator, OneWallOfKnownThicknessByHand) {
  const RadioParameters p = hand_parameters();
  const RadioModel model(p, {}, {RasterAttenuator::obstacle(one_wall(), p, "wall.yaml")}, {});
  // Straight across, 8 m: one wall, 1 m inside.
  const LinkQuality l = model.link({1.0, 2.3}, {9.0, 2.3});
  const double distance = 40.05 + 30.0 * std::log10(8.0);  // 67.14270 dB
  EXPECT_NEAR(l.distance_loss_db, distance, 1e-9);
  EXPECT_EQ(l.crossings, 1);
  EXPECT_NEAR(l.inside_m, 1.0, 1e-9);
  EXPECT_NEAR(l.obstacle_loss_db, 12.0 + 0.5 * 1.0, 1e-9);  // 12.5 dB
  EXPECT_NEAR(l.signal_dbm, 20.0 - 67.14270 - 12.5, 1e-4);  // -59.6427 dBm
  EXPECT_NEAR(l.margin_db, 30.3573, 1e-4);
  EXPECT_TRUE(l.connected);
  // Slanted (dx = 8, dy = 3.2): 1 m of wall thickness is sqrt(1 + 0.4^2) = 1.07703 m of path.
  const LinkQuality s = model.link({1.0, 1.1}, {9.0, 4.3});
  EXPECT_EQ(s.crossings, 1);
  EXPECT_NEAR(s.inside_m, std::sqrt(1.16), 1e-9);
  EXPECT_NEAR(s.obstacle_loss_db, 12.0 + 0.5 * std::sqrt(1.16), 1e-9);  // 12.5385 dB
  // Both on one side: nothing.
  EXPECT_EQ(model.link({1.0, 2.3}, {4.0, 9.0}).obstacle_loss_db, 0.0);
}

TEST(RasterAttenuator, EveryBandIsOneWall) {
  const RadioParameters p = hand_parameters();
  auto g = one_wall();
  block_columns(*g, 20, 23);  // a second wall 2 m thick, x in [10, 12]
  const RadioModel model(p, {}, {RasterAttenuator::obstacle(g, p)}, {});
  const LinkQuality l = model.link({1.0, 2.3}, {15.0, 2.3});
  EXPECT_EQ(l.crossings, 2);
  EXPECT_NEAR(l.inside_m, 3.0, 1e-9);
  EXPECT_NEAR(l.obstacle_loss_db, 2 * 12.0 + 0.5 * 3.0, 1e-9);  // 25.5 dB
  // Distance 14 m: 40.05 + 30 log10(14) = 74.43384 dB; 20 - 74.43384 - 25.5 = -79.93384 dBm.
  EXPECT_NEAR(l.signal_dbm, -79.93384, 1e-4);
}

TEST(RasterAttenuator, RadiosInsideAWallPayTheWayOut) {
  const RasterAttenuator r(one_wall(), 12.0, 0.5);
  expect_raster_same(r.traverse({5.5, 2.3}, {9.0, 2.3}), 1, 1, 0.5);  // leaves the wall: 1 wall
  expect_raster_same(r.traverse({9.0, 2.3}, {5.5, 2.3}), 1, 1, 0.5);  // either way
  expect_raster_same(r.traverse({5.2, 2.3}, {5.8, 7.3}), 0, 1, std::hypot(0.6, 5.0));  // stays inside
  expect_raster_same(r.traverse({5.0, 2.3}, {6.0, 2.3}), 0, 1, 1.0);  // face to face, through the inside
  expect_raster_same(r.traverse({6.0, 2.3}, {9.0, 2.3}), 0, 0, 0.0);  // from the face outwards
  expect_raster_same(r.traverse({4.0, 2.3}, {6.0, 2.3}), 1, 1, 1.0);  // to the far face: in, then on it
}

TEST(RasterAttenuator, CornersAndGridLinesAreBoundary) {
  auto g = raster(12, 12, 1.0);
  g->set_blocked({5, 5}, true);
  const RasterAttenuator r(g, 12.0, 0.5);
  // x + y = 10 touches cell (5, 5) at its corner (5, 5) only.
  expect_raster_same(r.traverse({3.0, 7.0}, {7.0, 3.0}), 0, 0, 0.0);
  // Along the cell's lower edge (y = 5) and its left edge (x = 5): on the boundary.
  expect_raster_same(r.traverse({0.0, 5.0}, {12.0, 5.0}), 0, 0, 0.0);
  expect_raster_same(r.traverse({5.0, 0.5}, {5.0, 11.0}), 0, 0, 0.0);

  // Two cells meeting at a corner: the diagonal through it leaves one wall and enters another.
  g->set_blocked({4, 4}, true);
  const RasterAttenuator two(g, 12.0, 0.5);
  expect_raster_same(two.traverse({2.5, 2.5}, {7.5, 7.5}), 2, 2, 2.0 * std::sqrt(2.0));
  // With the other two cells of that corner blocked, it is one 2 x 2 block: one wall.
  g->set_blocked({4, 5}, true);
  g->set_blocked({5, 4}, true);
  const RasterAttenuator block(g, 12.0, 0.5);
  expect_raster_same(block.traverse({2.5, 2.5}, {7.5, 7.5}), 1, 1, 2.0 * std::sqrt(2.0));
  // Along the grid line y = 5 between two blocked rows: inside the block (x in [4, 6]).
  expect_raster_same(block.traverse({0.0, 5.0}, {12.0, 5.0}), 1, 1, 2.0);
}

TEST(RasterAttenuator, CellsOutsideTheMapAreFreeAndOriginIsHonoured) {
  // The one-wall map placed at (100, 50): the wall is x in [105, 106].
  auto g = raster(40, 20, 0.5, {100.0, 50.0, 0.0});
  block_columns(*g, 10, 11);
  const RasterAttenuator r(g, 12.0, 0.5);
  expect_raster_same(r.traverse({90.0, 52.3}, {130.0, 52.3}), 1, 1, 1.0);  // enters and leaves the map
  expect_raster_same(r.traverse({1.0, 2.3}, {9.0, 2.3}), 0, 0, 0.0);        // far from it
  expect_raster_same(r.traverse({90.0, 40.0}, {130.0, 40.0}), 0, 0, 0.0);   // below it
  // A map whose border column is blocked: entering it from outside crosses that wall.
  auto edge = raster(10, 10, 1.0);
  block_columns(*edge, 0, 0);
  expect_raster_same(RasterAttenuator(edge, 12.0, 0.5).traverse({-5.0, 5.5}, {5.0, 5.5}), 1, 1, 1.0);
}

TEST(RasterAttenuator, RejectsUnusableMaps) {
  EXPECT_THROW(RasterAttenuator(nullptr, 12.0, 0.5, "none"), std::invalid_argument);
  EXPECT_THROW(RasterAttenuator(raster(4, 4, 1.0, {0.0, 0.0, 0.3}), 12.0, 0.5), std::invalid_argument);
  EXPECT_THROW(RasterAttenuator(raster(4, 4, 1.0), -1.0, 0.5), std::invalid_argument);
  EXPECT_THROW(RasterAttenuator(raster(4, 4, 1.0), 12.0, NAN), std::invalid_argument);
}

// Random maps: blocked cells scattered, bands and a solid room, on a map with an offset origin
// and big empty stretches (the walk's block jumps). Half of the endpoints are snapped to the
// half-cell lattice so that segments run along grid lines and through lattice points.
TEST(RasterAttenuator, WalkAgreesWithTheReferenceOnRandomMaps) {
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int checked = 0, with_walls = 0;
  for (int map = 0; map < 6; ++map) {
    const double res = map % 2 == 0 ? 0.25 : 1.0;
    const int w = 40 + 37 * map, h = 30 + 29 * map;
    auto g = raster(w, h, res, {-3.0, 2.0, 0.0});
    for (int k = 0; k < w * h / 12; ++k) {
      g->set_blocked({static_cast<int>(unit(rng) * w) % (w / 3 + 1), static_cast<int>(unit(rng) * h)}, true);
    }
    for (int row = 0; row < h; ++row) g->set_blocked({w / 2, row}, true);            // a band
    for (int col = w / 2; col < w; ++col) g->set_blocked({col, h / 3}, col % 5 != 0);  // a broken band
    for (int row = 2 * h / 3; row < 2 * h / 3 + 5 && row < h; ++row)                 // a solid room
      for (int col = 2 * w / 3; col < 2 * w / 3 + 6 && col < w; ++col) g->set_blocked({col, row}, true);
    const RasterAttenuator r(g, 12.0, 0.5);
    const double x0 = -3.0 - 2.0, x1 = -3.0 + w * res + 2.0;
    const double y0 = 2.0 - 2.0, y1 = 2.0 + h * res + 2.0;
    for (int i = 0; i < 3000; ++i) {
      Vec2 a(x0 + unit(rng) * (x1 - x0), y0 + unit(rng) * (y1 - y0));
      Vec2 b(x0 + unit(rng) * (x1 - x0), y0 + unit(rng) * (y1 - y0));
      if (i % 2 == 1) {
        const auto snap = [&](double v, double origin) {
          return origin + std::round((v - origin) / (0.5 * res)) * 0.5 * res;
        };
        a = {snap(a.x(), -3.0), snap(a.y(), 2.0)};
        b = {snap(b.x(), -3.0), snap(b.y(), 2.0)};
        if (i % 6 == 1) b.y() = a.y();  // along a grid line or a row's middle
        if (i % 6 == 3) b.x() = a.x();
        if (i % 6 == 5) b = a + Vec2(1, 1) * std::round((b.x() - a.x()) / res) * res;  // diagonal
      }
      const Traversal fast = r.traverse(a, b);
      const Traversal slow = traverse_raster_reference(*g, a, b);
      ASSERT_EQ(fast.crossings, slow.crossings) << "map " << map << " from " << a.transpose() << " to " << b.transpose();
      ASSERT_EQ(fast.stretches, slow.stretches) << "map " << map << " from " << a.transpose() << " to " << b.transpose();
      ASSERT_NEAR(fast.inside_m, slow.inside_m, 1e-9) << "map " << map << " from " << a.transpose() << " to " << b.transpose();
      const Traversal back = r.traverse(b, a);
      ASSERT_EQ(back.crossings, fast.crossings);
      ASSERT_NEAR(back.inside_m, fast.inside_m, 1e-9);
      ++checked;
      with_walls += fast.crossings > 0 ? 1 : 0;
    }
  }
  EXPECT_EQ(checked, 18000);
  EXPECT_GT(with_walls, 5000);  // the maps are not trivially empty along the tested paths
}

}  // namespace
}  // namespace autonomy::sim::radio
