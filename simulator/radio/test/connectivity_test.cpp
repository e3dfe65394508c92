#include "simulator/radio/connectivity.hpp"

#include <gtest/gtest.h>

namespace autonomy::sim::radio {
namespace {

using geometry::Vec2;

// With the defaults a free-space link reaches 214.7 m (margin 69.95 - 30 log10(d) >= 0).
RadioModel open_field() { return RadioModel(RadioParameters{}, {}); }

TEST(Connectivity, ChainIsConnectedThroughTheMiddleOnly) {
  const RadioModel model = open_field();
  const LinkTable t = model.table({{0, 0}, {150, 0}, {300, 0}});  // a - b - c
  ASSERT_TRUE(t.connected(0, 1));
  ASSERT_TRUE(t.connected(1, 2));
  ASSERT_FALSE(t.connected(0, 2));
  const Connectivity c(t);
  EXPECT_TRUE(c.fully_connected());
  EXPECT_EQ(c.components().size(), 1u);
  EXPECT_TRUE(c.reachable(0, 2));
  EXPECT_EQ(c.hop_counts(0), (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(c.route(0, 2), (std::vector<size_t>{0, 1, 2}));
  EXPECT_EQ(c.route(2, 0), (std::vector<size_t>{2, 1, 0}));
  EXPECT_EQ(c.route(1, 1), (std::vector<size_t>{1}));
  EXPECT_EQ(route_links(t, *c.route(0, 2)).size(), 2u);
}

TEST(Connectivity, RemovingTheRelaySplitsTheTeam) {
  const RadioModel model = open_field();
  const Connectivity c(model.table({{0, 0}, {1000, 0}, {300, 0}, {1100, 0}}));
  EXPECT_FALSE(c.fully_connected());
  ASSERT_EQ(c.components().size(), 3u);
  EXPECT_EQ(c.components()[0], (std::vector<size_t>{0}));
  EXPECT_EQ(c.components()[1], (std::vector<size_t>{1, 3}));
  EXPECT_EQ(c.components()[2], (std::vector<size_t>{2}));
  EXPECT_EQ(c.component_of(3), 1u);
  EXPECT_FALSE(c.route(0, 1).has_value());
  EXPECT_EQ(c.hop_counts(0), (std::vector<int>{0, -1, -1, -1}));
}

TEST(Connectivity, ABuildingCutsALinkThatDistanceAllows) {
  const RadioParameters p;
  // 100 m apart: margin 9.95 dB in the open; a 20 m building between costs 24 + 10 dB.
  const RadioModel model(p, obstacles_from_rects({{40, -10, 60, 10}}, p));
  const LinkTable t = model.table({{0, 0}, {100, 0}, {50, 60}});
  EXPECT_FALSE(t.connected(0, 1));
  const Connectivity c(t);
  EXPECT_TRUE(c.fully_connected());  // around the building through robot 2
  EXPECT_EQ(c.route(0, 1), (std::vector<size_t>{0, 2, 1}));
}

TEST(Connectivity, FewestHopsThenLowestIndices) {
  const RadioModel model = open_field();
  // A square of side 160 m: sides connected, diagonals (226 m) out of range. Two 2-hop routes
  // from 0 to 3; the one through 1 wins.
  const Connectivity c(model.table({{0, 0}, {160, 0}, {0, 160}, {160, 160}}));
  EXPECT_EQ(c.neighbours(0), (std::vector<size_t>{1, 2}));
  EXPECT_EQ(c.route(0, 3), (std::vector<size_t>{0, 1, 3}));
  EXPECT_EQ(c.route(3, 0), (std::vector<size_t>{3, 1, 0}));
}

TEST(Connectivity, EmptyAndSingleTeamsAreFullyConnected) {
  const RadioModel model = open_field();
  EXPECT_TRUE(Connectivity(model.table({})).fully_connected());
  EXPECT_TRUE(Connectivity(model.table({{5, 5}})).fully_connected());
}

}  // namespace
}  // namespace autonomy::sim::radio
