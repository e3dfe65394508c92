// Polygons and the exact ray / disc tests under ObstacleMap.
#include "simulator/core/shapes.hpp"
#include "simulator/core/random.hpp"

#include <gtest/gtest.h>

namespace autonomy::sim {
namespace {

using V = geometry::Vec2;

TEST(Shapes, PolygonProblemsAreNamed) {
  EXPECT_EQ(polygon_problem({{0, 0}, {1, 0}}), "has 2 vertices; a polygon needs at least 3");
  EXPECT_EQ(polygon_problem({{0, 0}, {1, 0}, {2, 0}}), "has zero area");
  // A bow tie: edges 0 (0,0)-(3,2) and 2 (3,0)-(0,3) cross.
  EXPECT_EQ(polygon_problem({{0, 0}, {3, 2}, {3, 0}, {0, 3}}), "edges 0 and 2 cross");
  EXPECT_EQ(polygon_problem({{0, 0}, {1, 0}, {1, 0}, {0, 1}}), "repeats vertex 1");
  // Within a nanometre is the same point, and edges that close touch.
  EXPECT_EQ(polygon_problem({{0, 0}, {1, 0}, {1, 1e-10}, {0, 1}}), "repeats vertex 1");
  EXPECT_EQ(polygon_problem({{0, 0}, {4, 0}, {4, 4}, {2, 1e-10}, {0, 4}}), "edges 0 and 2 cross");
  EXPECT_EQ(polygon_problem({{0, 0}, {4, 0}, {4, 4}, {2, 1e-3}, {0, 4}}), std::nullopt);  // 1 mm is room
  EXPECT_EQ(polygon_problem({{0, 0}, {4, 0}, {4, 4}, {2, 1}, {0, 4}}), std::nullopt);  // concave is fine
  EXPECT_EQ(polygon_problem({{0, 0}, {0, 4}, {4, 4}, {4, 0}}), std::nullopt);          // clockwise too
}

TEST(Shapes, ContainsAndDiscOverlapOnAConcavePolygon) {
  const std::vector<V> dent{{0, 0}, {4, 0}, {4, 4}, {2, 1}, {0, 4}};
  EXPECT_TRUE(polygon_contains(dent, {1, 0.5}));
  EXPECT_FALSE(polygon_contains(dent, {2, 3}));  // in the notch
  EXPECT_FALSE(disc_overlaps_polygon(dent, {2, 3}, 0.5));
  EXPECT_TRUE(disc_overlaps_polygon(dent, {2, 3}, 2.0));
  EXPECT_FALSE(disc_overlaps_polygon(dent, {5, 2}, 1.0));  // touching is free
  EXPECT_TRUE(disc_overlaps_polygon(dent, {5, 2}, 1.0001));
}

TEST(Shapes, RayMeetsSegmentAndCircle) {
  EXPECT_DOUBLE_EQ(ray_segment({0, 0}, {1, 0}, {3, -1}, {3, 1}), 3.0);
  EXPECT_EQ(ray_segment({0, 0}, {-1, 0}, {3, -1}, {3, 1}), kNoHit);
  EXPECT_EQ(ray_segment({0, 0}, {1, 0}, {3, 0.5}, {3, 1}), kNoHit);
  EXPECT_DOUBLE_EQ(ray_segment({0, 0}, {1, 0}, {2, 0}, {5, 0}), 2.0);  // collinear
  EXPECT_DOUBLE_EQ(ray_circle({0, 0}, {1, 0}, {5, 0}, 1.0), 4.0);
  EXPECT_DOUBLE_EQ(ray_circle({5, 0}, {1, 0}, {5, 0}, 1.0), 0.0);       // inside
  EXPECT_EQ(ray_circle({0, 0}, {0, 1}, {5, 0}, 1.0), kNoHit);
  EXPECT_NEAR(ray_circle({0, 0}, {1, 0}, {5, 0.6}, 1.0), 5.0 - 0.8, 1e-12);
}

TEST(Random, StreamsAreReproducibleAndIndependentOfEachOther) {
  Rng a = Rng::stream(7, "robot/r1");
  Rng b = Rng::stream(7, "robot/r1");
  Rng c = Rng::stream(7, "robot/r2");
  for (int i = 0; i < 5; ++i) {
    const std::uint64_t x = a.next();
    EXPECT_EQ(x, b.next());
    EXPECT_NE(x, c.next());
  }
  // Moments of the normal and exponential draws over many samples.
  Rng r(1);
  double sum = 0.0, sum2 = 0.0, esum = 0.0;
  constexpr int kN = 200000;
  for (int i = 0; i < kN; ++i) {
    const double z = r.normal();
    sum += z;
    sum2 += z * z;
    esum += r.exponential(4.0);
  }
  EXPECT_NEAR(sum / kN, 0.0, 0.01);
  EXPECT_NEAR(sum2 / kN, 1.0, 0.01);
  EXPECT_NEAR(esum / kN, 0.25, 0.005);
}

}  // namespace
}  // namespace autonomy::sim
