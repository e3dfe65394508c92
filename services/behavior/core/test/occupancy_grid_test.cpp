#include "services/behavior/core/occupancy_grid.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace autonomy::behavior {
namespace {

using geometry::Rect;
using geometry::Vec2;

TEST(OccupancyGrid, SizeCoversTheWorldWithoutARoundingExtraColumn) {
  const OccupancyGrid grid(WorldMap{10.0, 3.0, {}}, 0.1, 0.0);
  EXPECT_EQ(grid.geometry().cols(), 100);
  EXPECT_EQ(grid.geometry().rows(), 30);
  const OccupancyGrid partial(WorldMap{1.05, 1.0, {}}, 0.5, 0.0);
  EXPECT_EQ(partial.geometry().cols(), 3);  // a partial last column still exists
}

TEST(OccupancyGrid, BorderBlocksCellsCloserThanTheInflationRadius) {
  // Centres at 0.25, 0.75, 1.25, 1.75; radius 0.3 leaves only the middle two in each axis.
  const OccupancyGrid grid(WorldMap{2.0, 2.0, {}}, 0.5, 0.3);
  for (int row = 0; row < 4; ++row) {
    for (int col = 0; col < 4; ++col) {
      const bool inner = col >= 1 && col <= 2 && row >= 1 && row <= 2;
      EXPECT_EQ(grid.blocked({col, row}), !inner) << col << "," << row;
    }
  }
}

TEST(OccupancyGrid, ObstacleWithoutInflationBlocksTheCellsItCovers) {
  const OccupancyGrid grid(WorldMap{4.0, 4.0, {Rect{1.0, 1.0, 2.0, 2.0}}}, 1.0, 0.0);
  int blocked = 0;
  for (int row = 0; row < 4; ++row) {
    for (int col = 0; col < 4; ++col) blocked += grid.blocked({col, row}) ? 1 : 0;
  }
  EXPECT_EQ(blocked, 1);
  EXPECT_TRUE(grid.blocked({1, 1}));
}

TEST(OccupancyGrid, InflationIsADistanceSoCornersAreRounded) {
  const OccupancyGrid grid(WorldMap{6.0, 6.0, {Rect{2.0, 2.0, 3.0, 3.0}}}, 1.0, 0.6);
  EXPECT_TRUE(grid.blocked({2, 2}));   // the obstacle itself
  EXPECT_TRUE(grid.blocked({1, 2}));   // centre (1.5, 2.5) is 0.5 m from its side
  EXPECT_TRUE(grid.blocked({3, 2}));   // centre (3.5, 2.5), 0.5 m
  EXPECT_FALSE(grid.blocked({1, 1}));  // centre (1.5, 1.5) is 0.707 m from its corner
  EXPECT_FALSE(grid.blocked({4, 4}));
  EXPECT_TRUE(grid.blocked({0, 3}));  // border: centre x = 0.5 < 0.6
}

TEST(OccupancyGrid, OutsideTheGridCountsAsBlocked) {
  const OccupancyGrid grid(WorldMap{2.0, 2.0, {}}, 1.0, 0.0);
  EXPECT_TRUE(grid.blocked({-1, 0}));
  EXPECT_TRUE(grid.blocked({0, 2}));
  EXPECT_FALSE(grid.blocked({1, 1}));
}

TEST(OccupancyGrid, CellAtPutsTheFarBorderInTheLastCell) {
  const OccupancyGrid grid(WorldMap{2.0, 1.0, {}}, 0.5, 0.0);
  const auto& g = grid.geometry();
  EXPECT_EQ(g.cell_at(Vec2(0.0, 0.0)), (GridCell{0, 0}));
  EXPECT_EQ(g.cell_at(Vec2(0.74, 0.26)), (GridCell{1, 0}));
  EXPECT_EQ(g.cell_at(Vec2(2.0, 1.0)), (GridCell{3, 1}));
  EXPECT_FALSE(g.cell_at(Vec2(2.01, 0.5)));
  EXPECT_FALSE(g.cell_at(Vec2(-0.01, 0.5)));
  EXPECT_FALSE(g.cell_at(Vec2(std::nan(""), 0.5)));
  EXPECT_EQ(g.centre({3, 1}), Vec2(1.75, 0.75));
}

TEST(OccupancyGrid, PictureTopRowIsTheHighestY) {
  const auto grid = OccupancyGrid::from_picture({"#..", "..."}, 0.5);
  EXPECT_EQ(grid.geometry().cols(), 3);
  EXPECT_EQ(grid.geometry().rows(), 2);
  EXPECT_TRUE(grid.blocked({0, 1}));
  EXPECT_FALSE(grid.blocked({0, 0}));
  EXPECT_DOUBLE_EQ(grid.width_m(), 1.5);
  EXPECT_DOUBLE_EQ(grid.height_m(), 1.0);
}

TEST(OccupancyGrid, MalformedInputsThrow) {
  EXPECT_THROW(OccupancyGrid(WorldMap{0.0, 1.0, {}}, 0.1, 0.0), std::invalid_argument);
  EXPECT_THROW(OccupancyGrid(WorldMap{1.0, 1.0, {}}, 0.0, 0.0), std::invalid_argument);
  EXPECT_THROW(OccupancyGrid(WorldMap{1.0, 1.0, {}}, 0.1, -0.1), std::invalid_argument);
  EXPECT_THROW(OccupancyGrid(WorldMap{1.0, 1.0, {Rect{0.5, 0.5, 0.2, 0.8}}}, 0.1, 0.0),
               std::invalid_argument);
  EXPECT_THROW(OccupancyGrid(WorldMap{1e6, 1e6, {}}, 0.01, 0.0), std::invalid_argument);
  EXPECT_THROW(OccupancyGrid::from_picture({"..", "."}, 1.0), std::invalid_argument);
}

}  // namespace
}  // namespace autonomy::behavior
