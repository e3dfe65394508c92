// Plan resource files: write -> load gives the same plans; damaged files fail with clear errors.
#include "services/behavior/core/plan_resource.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace autonomy::behavior {
namespace {

using geometry::Rect;

PlanResource two_plans() {
  const WorldMap world{10.0, 8.0, {Rect{4.8, 0.0, 5.2, 6.0}}};
  const OccupancyGrid grid(world, 0.1, 0.4);
  PlanResource r;
  r.plans.push_back(make_stored_plan("east", "obstacles", "demo", 10.0, 8.0, 0.4,
                                     CostToGoField(grid, geometry::Vec2(8.0, 1.0))));
  WorldMap walled = world;
  walled.obstacles.push_back(Rect{6.0, 0.0, 7.0, 8.0});
  r.plans.push_back(make_stored_plan("boxed", "obstacles+wall", "demo", 10.0, 8.0, 0.4,
                                     CostToGoField(OccupancyGrid(walled, 0.1, 0.4), geometry::Vec2(8.0, 1.0))));
  return r;
}

TEST(PlanResource, EncodeDecodeRoundTripIsExact) {
  const PlanResource r = two_plans();
  ASSERT_TRUE(std::isinf(r.plans[1].costs[0]));  // unreachable cells are stored too
  const std::string bytes = encode_plan_resource(r);
  // header, then per record: length, 3 name lengths, 6 doubles, cols, rows, 100 x 80 costs, crc; names.
  EXPECT_EQ(bytes.size(), 16u + 2 * (4 + 12 + 48 + 8 + 100 * 80 * 4 + 4) + (4 + 9 + 4) + (5 + 14 + 4));
  const auto loaded = decode_plan_resource(bytes, "mem");
  ASSERT_TRUE(loaded.ok()) << loaded.error;
  ASSERT_EQ(loaded.resource->plans.size(), 2u);
  EXPECT_TRUE(loaded.resource->plans[0] == r.plans[0]);
  EXPECT_TRUE(loaded.resource->plans[1] == r.plans[1]);
  // The field rebuilt from the stored costs answers like the original.
  const CostToGoField f = loaded.resource->plans[0].field();
  EXPECT_TRUE(f.has_route_anywhere());
  EXPECT_EQ(f.costs(), r.plans[0].costs);
  EXPECT_EQ(f.advice({10, 10}), CostToGoField(OccupancyGrid(WorldMap{10.0, 8.0, {Rect{4.8, 0.0, 5.2, 6.0}}}, 0.1, 0.4),
                                              geometry::Vec2(8.0, 1.0))
                                    .advice({10, 10}));
}

TEST(PlanResource, FileRoundTripAndMatch) {
  const std::string path =
      (std::filesystem::temp_directory_path() / ("plan_resource_test_" + std::to_string(::getpid()) + ".bin")).string();
  std::string error;
  ASSERT_TRUE(save_plan_resource(path, two_plans(), &error)) << error;
  const auto loaded = load_plan_resource(path);
  std::remove(path.c_str());
  ASSERT_TRUE(loaded.ok()) << loaded.error;
  const PlanResource& r = *loaded.resource;
  EXPECT_NE(r.find("boxed"), nullptr);
  EXPECT_EQ(r.find("nope"), nullptr);
  const GridGeometry g(100, 80, 0.1);
  EXPECT_EQ(r.match(geometry::Vec2(8.0, 1.0), "obstacles+wall", g, 0.4), r.find("boxed"));
  EXPECT_EQ(r.match(geometry::Vec2(8.0, 1.0), "obstacles", g, 0.4), r.find("east"));
  EXPECT_EQ(r.match(geometry::Vec2(8.0, 1.5), "obstacles", g, 0.4), nullptr);  // other goal
  EXPECT_EQ(r.match(geometry::Vec2(8.0, 1.0), "obstacles", g, 0.5), nullptr);  // other robot size
  EXPECT_EQ(r.match(geometry::Vec2(8.0, 1.0), "obstacles", GridGeometry(50, 40, 0.2), 0.4), nullptr);
}

TEST(PlanResource, DamagedFilesFailWithClearErrors) {
  const std::string good = encode_plan_resource(two_plans());

  auto error_of = [](const std::string& bytes) { return decode_plan_resource(bytes, "plans.bin").error; };
  EXPECT_EQ(error_of("hello"), "plans.bin: not a plan resource file (no AUTPLANS header)");

  std::string v2 = good;
  v2[8] = 2;
  EXPECT_EQ(error_of(v2), "plans.bin: plan resource version 2 is not supported (this build reads 1)");

  const std::string truncated = good.substr(0, good.size() - 100);
  EXPECT_NE(error_of(truncated).find("plan 2 of 2"), std::string::npos) << error_of(truncated);
  EXPECT_NE(error_of(truncated).find("truncated"), std::string::npos) << error_of(truncated);

  std::string flipped = good;
  flipped[200] = static_cast<char>(flipped[200] ^ 0x10);  // inside the first plan's costs
  EXPECT_EQ(error_of(flipped), "plans.bin: plan 1 of 2 (offset 16) 'east': checksum mismatch (corrupt file)");

  EXPECT_EQ(error_of(good + "x"), "plans.bin: 1 unexpected bytes after the last plan");

  const auto missing = load_plan_resource("/nonexistent/plans.bin");
  EXPECT_FALSE(missing.ok());
  EXPECT_EQ(missing.error, "/nonexistent/plans.bin: cannot open: No such file or directory");
}

}  // namespace
}  // namespace autonomy::behavior
