#include "services/behavior/core/occupancy_grid.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <memory>
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

TEST(OccupancyGrid, PolygonBlocksItsInsideAndCellsWithinTheRadiusOfAnEdge) {
  // A right triangle (2,4)-(6,4)-(2,8): its hypotenuse is the line x + y = 10.
  WorldMap world{10.0, 10.0};
  world.polygons.push_back({"wedge", {Vec2{2.0, 4.0}, Vec2{6.0, 4.0}, Vec2{2.0, 8.0}}});
  const OccupancyGrid grid(world, 1.0, 0.6);
  EXPECT_TRUE(grid.blocked({2, 4}));   // centre (2.5, 4.5): inside
  EXPECT_TRUE(grid.blocked({4, 5}));   // (4.5, 5.5): on the hypotenuse
  EXPECT_TRUE(grid.blocked({3, 3}));   // (3.5, 3.5): 0.5 m below the bottom edge
  EXPECT_FALSE(grid.blocked({3, 2}));  // (3.5, 2.5): 1.5 m below it
  // (5.5, 5.5) lies 0.707 m beyond the hypotenuse: outside the 0.6 m radius.
  EXPECT_FALSE(grid.blocked({5, 5}));
  EXPECT_FALSE(grid.blocked({6, 8}));
  // A larger radius reaches it.
  EXPECT_TRUE(OccupancyGrid(world, 1.0, 0.75).blocked({5, 5}));
}

TEST(OccupancyGrid, RasterCellsBlockLikeTheSameSquaresGivenAsRectangles) {
  // A random 20 x 15 raster of 0.5 m cells placed at (1.5, 2.0): growing its cells must give the
  // same grid as growing one rectangle per blocked cell (the interior shortcut changes nothing).
  auto raster = std::make_shared<grid::OccupancyRaster>(20, 15, 0.5, grid::RasterOrigin{1.5, 2.0, 0.0});
  WorldMap as_rects{14.0, 11.0};
  std::uint32_t state = 12345;
  for (int row = 0; row < 15; ++row) {
    for (int col = 0; col < 20; ++col) {
      state = state * 1103515245u + 12345u;
      if ((state >> 16) % 3 != 0) continue;  // about a third blocked, in clumps and alone
      raster->set_blocked({col, row}, true);
      as_rects.obstacles.push_back(Rect{1.5 + col * 0.5, 2.0 + row * 0.5, 2.0 + col * 0.5, 2.5 + row * 0.5});
    }
  }
  WorldMap as_raster{14.0, 11.0};
  as_raster.rasters.push_back(raster);
  for (const double inflation : {0.0, 0.3, 0.8}) {
    const OccupancyGrid a(as_raster, 0.25, inflation);
    const OccupancyGrid b(as_rects, 0.25, inflation);
    int blocked = 0;
    for (int row = 0; row < a.geometry().rows(); ++row) {
      for (int col = 0; col < a.geometry().cols(); ++col) {
        ASSERT_EQ(a.blocked({col, row}), b.blocked({col, row})) << col << "," << row << " at " << inflation;
        blocked += a.blocked({col, row}) ? 1 : 0;
      }
    }
    EXPECT_GT(blocked, 100);
  }
}

TEST(OccupancyGrid, RejectsACrossingPolygonAndARotatedRaster) {
  WorldMap bow{10.0, 10.0};
  bow.polygons.push_back({"bow", {Vec2{1.0, 1.0}, Vec2{5.0, 5.0}, Vec2{5.0, 1.0}, Vec2{1.0, 5.0}}});
  EXPECT_THROW(OccupancyGrid(bow, 1.0, 0.0), std::invalid_argument);
  WorldMap turned{10.0, 10.0};
  turned.rasters.push_back(std::make_shared<grid::OccupancyRaster>(2, 2, 1.0, grid::RasterOrigin{0.0, 0.0, 0.5}));
  EXPECT_THROW(OccupancyGrid(turned, 1.0, 0.0), std::invalid_argument);
}

TEST(OccupancyGrid, AreasAddedLaterBlockExactlyAsTheSameObstaclesGivenAtOnce) {
  WorldMap world{20.0, 12.0};
  world.obstacles.push_back(Rect{2.0, 2.0, 4.0, 9.0});
  world.polygons.push_back({"wedge", {Vec2{8.0, 3.0}, Vec2{14.0, 3.0}, Vec2{8.0, 10.0}}});
  const std::vector<Rect> areas = {Rect{5.0, 0.0, 7.0, 6.0}, Rect{15.2, 4.3, 18.9, 4.9}};
  WorldMap with = world;
  with.obstacles.insert(with.obstacles.end(), areas.begin(), areas.end());
  const OccupancyGrid at_once(with, 0.25, 0.55);
  const OccupancyGrid later = OccupancyGrid(world, 0.25, 0.55).with_areas(areas);
  const OccupancyGrid without(world, 0.25, 0.55);
  int added = 0;
  for (int row = 0; row < at_once.geometry().rows(); ++row) {
    for (int col = 0; col < at_once.geometry().cols(); ++col) {
      ASSERT_EQ(later.blocked({col, row}), at_once.blocked({col, row})) << col << "," << row;
      added += later.blocked({col, row}) && !without.blocked({col, row});
    }
  }
  EXPECT_GT(added, 150);  // the areas did block something
  EXPECT_THROW(without.with_areas({Rect{3.0, 3.0, 1.0, 4.0}}), std::invalid_argument);
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
