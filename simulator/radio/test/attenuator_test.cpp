#include "simulator/radio/attenuator.hpp"

#include "simulator/radio/radio_parameters.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

namespace autonomy::sim::radio {
namespace {

using geometry::Rect;
using geometry::Vec2;

// The 10 x 10 m square [0, 10] x [0, 10], as a rectangle and as a polygon: every case below must
// give the same answer for both.
const Shape& square_rect() {
  static const Shape s = Shape::rect({0.0, 0.0, 10.0, 10.0});
  return s;
}
const Shape& square_polygon() {
  static const Shape s = Shape::polygon({{0.0, 0.0}, {10.0, 0.0}, {10.0, 10.0}, {0.0, 10.0}});
  return s;
}

struct Case {
  const char* what;
  Vec2 a;
  Vec2 b;
  int crossings;
  int stretches;
  double inside_m;
};

class SquareTraversal : public ::testing::TestWithParam<Case> {};

TEST_P(SquareTraversal, RectAndPolygonAgreeWithHandCounts) {
  const Case& c = GetParam();
  for (const Shape* s : {&square_rect(), &square_polygon()}) {
    for (const auto& [a, b] : {std::pair{c.a, c.b}, std::pair{c.b, c.a}}) {
      const Traversal t = s->traverse(a, b);
      SCOPED_TRACE(std::string(c.what) + (s->is_rect() ? " (rect)" : " (polygon)"));
      EXPECT_EQ(t.crossings, c.crossings);
      EXPECT_EQ(t.stretches, c.stretches);
      EXPECT_NEAR(t.inside_m, c.inside_m, 1e-6);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(
    Cases, SquareTraversal,
    ::testing::Values(
        Case{"straight through", {-5, 5}, {15, 5}, 2, 1, 10.0},
        Case{"ends inside", {-5, 5}, {5, 5}, 1, 1, 5.0},
        Case{"both ends inside", {2, 2}, {8, 7}, 0, 1, std::hypot(6.0, 5.0)},
        Case{"misses", {-5, 12}, {15, 12}, 0, 0, 0.0},
        Case{"runs along the bottom edge", {-5, 0}, {15, 0}, 0, 0, 0.0},
        Case{"runs along the top edge, inside the edge's span", {2, 10}, {8, 10}, 0, 0, 0.0},
        Case{"touches a corner only", {-5, 5}, {5, 15}, 0, 0, 0.0},
        Case{"ends on a corner from outside", {-5, -5}, {0, 0}, 0, 0, 0.0},
        Case{"diagonal through two corners", {-1, -1}, {11, 11}, 2, 1, 10.0 * std::sqrt(2.0)},
        Case{"starts on an edge, goes in", {0, 5}, {5, 5}, 0, 1, 5.0},
        Case{"starts on an edge, goes out", {0, 5}, {-5, 5}, 0, 0, 0.0},
        Case{"edge to opposite edge", {0, 5}, {10, 5}, 0, 1, 10.0},
        Case{"enters through a corner, ends inside", {-2, -2}, {3, 3}, 1, 1, 3.0 * std::sqrt(2.0)},
        Case{"zero length inside", {5, 5}, {5, 5}, 0, 0, 0.0}));

// A U-shaped building: 30 x 20 m with a 10 x 10 m notch open to the top.
Shape u_shape() {
  return Shape::polygon(
      {{0, 0}, {30, 0}, {30, 20}, {20, 20}, {20, 10}, {10, 10}, {10, 20}, {0, 20}});
}

TEST(PolygonTraversal, NonConvexCrossesBothArms) {
  const Traversal t = u_shape().traverse({-5, 15}, {35, 15});
  EXPECT_EQ(t.crossings, 4);
  EXPECT_EQ(t.stretches, 2);
  EXPECT_NEAR(t.inside_m, 20.0, 1e-9);
}

TEST(PolygonTraversal, NonConvexThroughTheBase) {
  const Traversal t = u_shape().traverse({-5, 5}, {35, 5});
  EXPECT_EQ(t.crossings, 2);
  EXPECT_EQ(t.stretches, 1);
  EXPECT_NEAR(t.inside_m, 30.0, 1e-9);
}

TEST(PolygonTraversal, RunningAlongTheNotchFloorLeavesTheInterior) {
  // y = 10: inside the left arm, along the notch's floor (boundary: outside), inside the right arm.
  const Traversal t = u_shape().traverse({-5, 10}, {35, 10});
  EXPECT_EQ(t.crossings, 4);
  EXPECT_EQ(t.stretches, 2);
  EXPECT_NEAR(t.inside_m, 20.0, 1e-9);
}

TEST(PolygonTraversal, TouchingAReflexVertexFromInsideSplitsNothing) {
  // From the left arm to the base through the notch's corner (10, 10): inside all the way.
  const Traversal t = u_shape().traverse({5, 15}, {15, 5});
  EXPECT_EQ(t.crossings, 0);
  EXPECT_EQ(t.stretches, 1);
  EXPECT_NEAR(t.inside_m, 10.0 * std::sqrt(2.0), 1e-9);
}

TEST(PolygonTraversal, ThroughAnApexAndTheBase) {
  const Shape triangle = Shape::polygon({{0, 0}, {10, 0}, {5, 10}});
  const Traversal vertical = triangle.traverse({5, -5}, {5, 15});
  EXPECT_EQ(vertical.crossings, 2);
  EXPECT_NEAR(vertical.inside_m, 10.0, 1e-9);
  const Traversal grazing = triangle.traverse({-5, 10}, {15, 10});  // touches the apex only
  EXPECT_EQ(grazing.crossings, 0);
  EXPECT_EQ(grazing.inside_m, 0.0);
}

TEST(PolygonTraversal, OrientationDoesNotMatter) {
  const Shape cw = Shape::polygon({{0, 0}, {0, 10}, {10, 10}, {10, 0}});
  const Traversal t = cw.traverse({-5, 5}, {15, 5});
  EXPECT_EQ(t.crossings, 2);
  EXPECT_NEAR(t.inside_m, 10.0, 1e-9);
}

void expect_same(const Traversal& x, const Traversal& y, const Vec2& a, const Vec2& b) {
  ASSERT_EQ(x.crossings, y.crossings) << a.transpose() << " -> " << b.transpose();
  ASSERT_EQ(x.stretches, y.stretches) << a.transpose() << " -> " << b.transpose();
  ASSERT_NEAR(x.inside_m, y.inside_m, 1e-9) << a.transpose() << " -> " << b.transpose();
}

TEST(PolygonTraversal, AllThreeRoutinesAgreeOnRandomGridSegments) {
  // Integer end points on a small grid hit corners, edges and collinear runs all the time.
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> coord(-3, 13);
  const Shape rect = Shape::rect({0, 0, 10, 10});
  const std::vector<Vec2> square = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  const std::vector<Vec2> diamond = {{5, 0}, {10, 5}, {5, 10}, {0, 5}};
  const std::vector<Vec2> triangle = {{0, 0}, {10, 0}, {10, 10}};
  for (int i = 0; i < 20000; ++i) {
    const Vec2 a(coord(rng), coord(rng));
    const Vec2 b(coord(rng), coord(rng));
    const Traversal r = rect.traverse(a, b);
    expect_same(r, detail::traverse_any_polygon(square, a, b), a, b);
    expect_same(r, detail::traverse_convex_polygon(square, a, b), a, b);
    expect_same(r, detail::traverse_any_polygon(square, b, a), a, b);
    for (const auto* shape : {&diamond, &triangle}) {
      const Traversal any = detail::traverse_any_polygon(*shape, a, b);
      expect_same(any, detail::traverse_convex_polygon(*shape, a, b), a, b);
      expect_same(any, detail::traverse_convex_polygon(*shape, b, a), a, b);
    }
  }
}

TEST(PolygonTraversal, NonConvexLengthMatchesItsRectangles) {
  // The U is the union of a base [0,30]x[0,10] and two arms [0,10]x[10,20], [20,30]x[10,20];
  // on random (non-degenerate) segments the inside length is the sum over the three rectangles.
  const Shape u = u_shape();
  const Shape parts[] = {Shape::rect({0, 0, 30, 10}), Shape::rect({0, 10, 10, 20}),
                         Shape::rect({20, 10, 30, 20})};
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> coord(-5.0, 35.0);
  for (int i = 0; i < 20000; ++i) {
    const Vec2 a(coord(rng), coord(rng)), b(coord(rng), coord(rng));
    double sum = 0.0;
    for (const Shape& part : parts) sum += part.traverse(a, b).inside_m;
    const Traversal t = u.traverse(a, b);
    ASSERT_NEAR(t.inside_m, sum, 1e-9) << a.transpose() << " -> " << b.transpose();
    ASSERT_EQ(t.crossings % 2, (u.contains(a) ? 1 : 0) ^ (u.contains(b) ? 1 : 0));
  }
}

TEST(PolygonTraversal, NonConvexIsSymmetricOnGridSegments) {
  const Shape u = u_shape();
  std::mt19937_64 rng(22);
  std::uniform_int_distribution<int> coord(-5, 35);
  for (int i = 0; i < 20000; ++i) {
    const Vec2 a(coord(rng), coord(rng)), b(coord(rng), coord(rng));
    expect_same(u.traverse(a, b), u.traverse(b, a), a, b);
  }
}

TEST(PolygonTraversal, ConvexityIsDetected) {
  EXPECT_TRUE(Shape::polygon({{0, 0}, {0, 10}, {10, 10}, {10, 0}}).is_convex());  // clockwise
  EXPECT_FALSE(u_shape().is_convex());
}

TEST(ShapeContains, BoundaryIsOutside) {
  EXPECT_TRUE(square_rect().contains({5, 5}));
  EXPECT_FALSE(square_rect().contains({0, 5}));
  EXPECT_TRUE(u_shape().contains({5, 15}));
  EXPECT_FALSE(u_shape().contains({15, 15}));  // the notch
  EXPECT_FALSE(u_shape().contains({15, 10}));  // the notch's floor
}

TEST(PolygonProblem, RejectsUnusablePolygons) {
  EXPECT_TRUE(polygon_problem({{0, 0}, {1, 0}}).has_value());
  EXPECT_TRUE(polygon_problem({{0, 0}, {1, 0}, {2, 0}}).has_value());                 // no area
  EXPECT_TRUE(polygon_problem({{0, 0}, {10, 10}, {10, 0}, {0, 10}}).has_value());     // bow tie
  EXPECT_TRUE(polygon_problem({{0, 0}, {1, 0}, {1, 0}, {0, 1}}).has_value());         // repeated
  EXPECT_TRUE(polygon_problem({{0, 0}, {NAN, 0}, {0, 1}}).has_value());
  EXPECT_FALSE(polygon_problem({{0, 0}, {30, 0}, {30, 20}, {20, 20}, {20, 10}, {10, 10},
                                {10, 20}, {0, 20}})
                   .has_value());
  EXPECT_THROW(Shape::polygon({{0, 0}, {1, 0}}), std::invalid_argument);
  EXPECT_THROW(Shape::rect({0, 0, 0, 1}), std::invalid_argument);
}

TEST(Attenuator, ObstacleChargesPerWallAndPerMetre) {
  RadioParameters p;
  p.wall_loss_db = 12.0;
  p.inside_loss_db_per_m = 0.5;
  const Attenuator building = Attenuator::obstacle(Shape::rect({0, 0, 10, 10}), p);
  // Through: 2 walls + 10 m inside = 24 + 5.
  EXPECT_NEAR(building.loss_db(building.shape.traverse({-5, 5}, {15, 5})), 29.0, 1e-9);
  // From inside: 1 wall + 5 m.
  EXPECT_NEAR(building.loss_db(building.shape.traverse({5, 5}, {15, 5})), 14.5, 1e-9);
}

TEST(Attenuator, AreaChargesPerEntryAndPerMetreWhicheverWay) {
  const Attenuator alley = Attenuator::area(Shape::rect({0, 0, 40, 6}), 3.0, 0.2, "alley");
  const Traversal along = alley.shape.traverse({-10, 3}, {50, 3});  // the whole 40 m
  EXPECT_NEAR(alley.loss_db(along), 3.0 + 0.2 * 40.0, 1e-9);
  // A radio standing in the alley: one stretch of 10 m, same cost both ways.
  EXPECT_NEAR(alley.loss_db(alley.shape.traverse({30, 3}, {50, 3})), 3.0 + 2.0, 1e-9);
  EXPECT_NEAR(alley.loss_db(alley.shape.traverse({50, 3}, {30, 3})), 3.0 + 2.0, 1e-9);
}

TEST(Attenuator, ProblemRejectsNegativeLoss) {
  Attenuator a = Attenuator::area(Shape::rect({0, 0, 1, 1}), -1.0, 0.0, "bad");
  EXPECT_TRUE(attenuator_problem(a).has_value());
  a.loss_per_stretch_db = 1.0;
  EXPECT_FALSE(attenuator_problem(a).has_value());
}

}  // namespace
}  // namespace autonomy::sim::radio
