// Travel times from a raster: a wall with a one-cell door between two rooms.
#include "services/courier/core/scheduler/travel_times.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace autonomy::courier::scheduling {
namespace {

// 20 x 10 cells of 0.5 m; a wall at col 10 except the door cell (10, 5).
grid::OccupancyRaster two_rooms() {
  grid::OccupancyRaster r(20, 10, 0.5);
  for (int row = 0; row < 10; ++row)
    if (row != 5) r.set_blocked({10, row}, true);
  return r;
}

TEST(TravelTimes, StraightThroughTheDoorAndCutOffWhenItCloses) {
  const auto raster = two_rooms();
  // Cell centres of (2, 5), (6, 5) and (17, 5).
  const std::vector<MapPosition> places{{1.25, 2.75}, {3.25, 2.75}, {8.75, 2.75}};
  const auto open = travel_times_from_map(raster, places, /*speed_mps=*/0.5);
  ASSERT_TRUE(open.ok()) << open.error;
  EXPECT_EQ(open.cells[2].col, 17);
  EXPECT_EQ(open.cells[2].row, 5);
  EXPECT_NEAR(open.matrix.at(0, 1), 4 * 0.5 / 0.5, 1e-5);   // 4 cells
  EXPECT_NEAR(open.matrix.at(0, 2), 15 * 0.5 / 0.5, 1e-5);  // 15 cells along row 5
  EXPECT_NEAR(open.matrix.at(2, 0), 15.0, 1e-5);
  EXPECT_DOUBLE_EQ(open.matrix.at(1, 1), 0.0);

  const auto closed = travel_times_from_map(raster, places, 0.5, {{10, 5}});
  ASSERT_TRUE(closed.ok());
  EXPECT_NEAR(closed.matrix.at(0, 1), 4.0, 1e-5);
  EXPECT_EQ(closed.matrix.at(0, 2), kNoRoute);
  EXPECT_EQ(closed.matrix.at(2, 1), kNoRoute);
}

TEST(TravelTimes, PlaceInsideTheClosedDoorIsCutOff) {
  const auto raster = two_rooms();
  const auto t = travel_times_from_map(raster, {{1.25, 2.75}, {5.25, 2.75}}, 1.0, {{10, 5}});
  ASSERT_TRUE(t.ok()) << t.error;
  EXPECT_EQ(t.matrix.at(0, 1), kNoRoute);
  EXPECT_EQ(t.matrix.at(1, 0), kNoRoute);
}

TEST(TravelTimes, BadPlacesAndSpeedAreErrors) {
  const auto raster = two_rooms();
  auto t = travel_times_from_map(raster, {{5.2, 1.0}}, 1.0);  // col 10: the wall
  EXPECT_NE(t.error.find("place 0"), std::string::npos);
  EXPECT_NE(t.error.find("occupied"), std::string::npos);
  t = travel_times_from_map(raster, {{50.0, 1.0}}, 1.0);
  EXPECT_NE(t.error.find("outside"), std::string::npos);
  t = travel_times_from_map(raster, {{1.0, 1.0}}, 0.0);
  EXPECT_NE(t.error.find("speed"), std::string::npos);
}

TEST(TravelTimes, RotatedOriginIsHonoured) {
  grid::OccupancyRaster r(10, 10, 1.0, {5.0, 0.0, M_PI / 2});  // x axis of the raster = map +y
  const auto cell = cell_at(r, {4.5, 2.5});                    // 2.5 along raster x, 0.5 along y
  ASSERT_TRUE(cell.has_value());
  EXPECT_EQ(cell->col, 2);
  EXPECT_EQ(cell->row, 0);
}

}  // namespace
}  // namespace autonomy::courier::scheduling
