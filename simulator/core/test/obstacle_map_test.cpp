// ObstacleMap: exact ray distances against rectangles, polygons, rasters and the boundary, the
// grid walk agreeing with testing every edge, and disc overlap naming the obstacle.
#include "simulator/core/obstacle_map.hpp"

#include "simulator/core/random.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace autonomy::sim {
namespace {

using V = geometry::Vec2;

std::shared_ptr<const grid::OccupancyRaster> raster_with(std::vector<grid::Cell> blocked, double res,
                                                         grid::RasterOrigin origin) {
  auto g = std::make_shared<grid::OccupancyRaster>(40, 40, res, origin);
  for (const grid::Cell c : blocked) g->set_blocked(c, true);
  return g;
}

TEST(ObstacleMap, RaysStopAtRectanglesPolygonsAndTheBoundary) {
  const ObstacleMap map(20.0, 12.0, {{10.0, 4.0, 11.0, 8.0}},
                        {{"tri", {{15, 1}, {17, 1}, {16, 3}}}}, {});
  EXPECT_DOUBLE_EQ(map.cast({2, 6}, {1, 0}, 100.0), 8.0);    // rectangle face
  EXPECT_DOUBLE_EQ(map.cast({2, 6}, {-1, 0}, 100.0), 2.0);   // world boundary
  EXPECT_DOUBLE_EQ(map.cast({2, 6}, {1, 0}, 5.0), 5.0);      // nothing within range
  EXPECT_DOUBLE_EQ(map.cast({16, 0.5}, {0, 1}, 100.0), 0.5); // polygon base
  EXPECT_NEAR(map.cast({12, 2}, {1, 0}, 100.0), 15.5 - 12.0, 1e-12);  // slanted edge at y = 2
  EXPECT_TRUE(map.clear({2, 2}, {8, 2}));
  EXPECT_FALSE(map.clear({2, 6}, {12, 6}));
  EXPECT_TRUE(map.clear({2, 6}, {10, 6}));  // ends on the face: touching at the end is clear
}

TEST(ObstacleMap, RaysStopAtTheFirstBlockedRasterCell) {
  // 0.5 m cells, map origin at (2, 1): cell (6, 4) covers [5, 5.5] x [3, 3.5].
  const ObstacleMap map(30.0, 30.0, {}, {}, {{"m.yaml", raster_with({{6, 4}}, 0.5, {2.0, 1.0, 0.0})}});
  EXPECT_DOUBLE_EQ(map.cast({1.0, 3.25}, {1, 0}, 100.0), 4.0);
  EXPECT_DOUBLE_EQ(map.cast({5.25, 10.0}, {0, -1}, 100.0), 6.5);
  EXPECT_NEAR(map.cast({4.0, 2.0}, V(1, 1).normalized(), 100.0), std::sqrt(2.0), 1e-12);  // corner
  EXPECT_DOUBLE_EQ(map.cast({1.0, 3.6}, {1, 0}, 100.0), 29.0);  // passes above it to the boundary
  const auto hit = map.overlap({5.25, 2.8}, 0.3);
  ASSERT_TRUE(hit.has_value());
  EXPECT_EQ(map.describe(*hit), "map 'm.yaml' cell (6, 4)");
  EXPECT_FALSE(map.overlap({5.25, 2.75}, 0.25).has_value());  // exactly touching
}

TEST(ObstacleMap, OverlapNamesTheLowestObstacleOfEachKind) {
  const ObstacleMap map(20.0, 12.0, {{1, 1, 2, 2}, {1.5, 1.5, 3, 3}},
                        {{"hall wall", {{5, 5}, {8, 5}, {8, 6}}}}, {});
  EXPECT_EQ(map.describe(*map.overlap({1.8, 1.8}, 0.1)), "obstacle 0");
  EXPECT_EQ(map.describe(*map.overlap({2.8, 2.8}, 0.1)), "obstacle 1");
  EXPECT_EQ(map.describe(*map.overlap({7.5, 5.3}, 0.1)), "polygon 0 'hall wall'");
  EXPECT_FALSE(map.overlap({6.0, 5.9}, 0.1).has_value());
}

// The grid walk must find exactly what testing every edge finds.
TEST(ObstacleMap, GridWalkAgreesWithBruteForceOnRandomRays) {
  Rng rng(3);
  std::vector<geometry::Rect> rects;
  for (int i = 0; i < 300; ++i) {
    const double x = rng.uniform() * 480, y = rng.uniform() * 480;
    rects.push_back({x, y, x + 1 + rng.uniform() * 15, y + 1 + rng.uniform() * 15});
  }
  std::vector<Polygon> polygons;
  for (int i = 0; i < 50; ++i) {
    const double x = rng.uniform() * 480, y = rng.uniform() * 480;
    polygons.push_back({"", {{x, y}, {x + 12, y + 2}, {x + 4, y + 9}}});
  }
  const ObstacleMap map(500.0, 500.0, rects, polygons, {});
  for (int i = 0; i < 5000; ++i) {
    const V o{rng.uniform() * 500, rng.uniform() * 500};
    const double a = rng.uniform() * 2 * M_PI;
    const V d{std::cos(a), std::sin(a)};
    double brute = 60.0;
    for (const auto& r : rects) {
      const V c[4] = {{r.min_x, r.min_y}, {r.max_x, r.min_y}, {r.max_x, r.max_y}, {r.min_x, r.max_y}};
      for (int k = 0; k < 4; ++k) brute = std::min(brute, ray_segment(o, d, c[k], c[(k + 1) % 4]));
    }
    for (const auto& p : polygons) {
      for (int k = 0; k < 3; ++k) brute = std::min(brute, ray_segment(o, d, p.vertices[k], p.vertices[(k + 1) % 3]));
    }
    for (double wall : {(d.x() > 0 ? (500 - o.x()) / d.x() : -o.x() / d.x()),
                        (d.y() > 0 ? (500 - o.y()) / d.y() : -o.y() / d.y())}) {
      brute = std::min(brute, wall);
    }
    ASSERT_DOUBLE_EQ(map.cast(o, d, 60.0), brute) << "ray " << i;
  }
}

TEST(ObstacleMap, RefusesRotatedRastersAndBadPolygons) {
  EXPECT_THROW(ObstacleMap(10, 10, {}, {}, {{"r", raster_with({}, 1.0, {0, 0, 0.5})}}), std::invalid_argument);
  EXPECT_THROW(ObstacleMap(10, 10, {}, {{"p", {{0, 0}, {1, 1}}}}, {}), std::invalid_argument);
}

}  // namespace
}  // namespace autonomy::sim
