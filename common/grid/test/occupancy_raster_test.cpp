#include "common/grid/occupancy_raster.hpp"
#include "common/grid/random_map.hpp"

#include <gtest/gtest.h>

namespace autonomy::grid {
namespace {

TEST(OccupancyRaster, StartsFreeAndStoresBits) {
  OccupancyRaster r(70, 3, 0.5, {1.0, 2.0, 0.25});
  EXPECT_EQ(r.width(), 70);
  EXPECT_EQ(r.height(), 3);
  EXPECT_EQ(r.cell_count(), 210u);
  EXPECT_DOUBLE_EQ(r.origin().yaw, 0.25);
  EXPECT_EQ(r.words_per_row(), 2u);
  EXPECT_EQ(r.storage_bytes(), 48u);  // one bit per cell, rows padded to 64 bits
  EXPECT_EQ(r.blocked_count(), 0u);
  r.set_blocked({69, 2}, true);
  r.set_blocked({0, 0}, true);
  r.set_blocked({64, 1}, true);
  EXPECT_TRUE(r.blocked({69, 2}));
  EXPECT_TRUE(r.blocked({64, 1}));
  EXPECT_FALSE(r.blocked({63, 1}));
  EXPECT_EQ(r.blocked_count(), 3u);
  r.set_blocked({0, 0}, false);
  EXPECT_FALSE(r.blocked({0, 0}));
  EXPECT_EQ(r.row_words(1)[1], 1u);
}

TEST(OccupancyRaster, OutsideIsBlocked) {
  const OccupancyRaster r(4, 4, 1.0);
  EXPECT_TRUE(r.blocked({-1, 0}));
  EXPECT_TRUE(r.blocked({4, 0}));
  EXPECT_TRUE(r.blocked({0, 4}));
  EXPECT_FALSE(r.blocked({3, 3}));
}

TEST(RandomRectangles, IsDeterministicAndHitsTheFraction) {
  const auto a = random_rectangles(200, 150, 0.15, 42);
  const auto b = random_rectangles(200, 150, 0.15, 42);
  const auto c = random_rectangles(200, 150, 0.15, 43);
  EXPECT_EQ(a.blocked_count(), static_cast<std::size_t>(0.15 * 200 * 150));
  bool same = true, differs = false;
  for (int row = 0; row < 150; ++row) {
    for (int col = 0; col < 200; ++col) {
      same = same && a.blocked({col, row}) == b.blocked({col, row});
      differs = differs || a.blocked({col, row}) != c.blocked({col, row});
    }
  }
  EXPECT_TRUE(same);
  EXPECT_TRUE(differs);
  EXPECT_FALSE(a.blocked(random_map_goal(a)));
}

}  // namespace
}  // namespace autonomy::grid
