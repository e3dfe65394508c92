// From a scenario to the radio model: occupancy rasters and door leaves attenuate, and the leaves
// follow the World's doors as they open and close.
#include "simulator/dds/radio_setup.hpp"

#include "simulator/core/world.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

namespace autonomy::sim {
namespace {

// A 20 x 10 m floor: a wall along y = 5 (0.2 m thick) with a 1 m doorway at x in [9.5, 10.5]
// closed by door A-120 hinged at x = 9.5, opening clockwise into the south room.
Scenario floor_with_door(double angle) {
  Scenario s;
  s.world.name = "floor";
  s.world.width = 20.0;
  s.world.height = 10.0;
  s.world.obstacles = {{0.0, 4.9, 9.5, 5.1}, {10.5, 4.9, 20.0, 5.1}};
  DoorSpec d;
  d.id = "A-120";
  d.position = {10.0, 5.0};
  d.width = 1.0;
  d.swing = DoorSwing::Clockwise;
  d.angle = angle;
  s.world.doors = {d};
  return s;
}

TEST(RadioSetup, DoorLeavesFollowTheWorldsDoors) {
  const Scenario scenario = floor_with_door(0.0);
  radio::RadioModel model = make_radio_model(scenario);
  ASSERT_EQ(model.walls().size(), 1u);
  World world(scenario.world);
  // Through the doorway, 6 m: 40.05 + 30 log10(6) = 63.39454 dB of distance.
  const geometry::Vec2 north(10.2, 8.0), south(10.2, 2.0);
  sync_door_leaves(world.doors(), model);
  const radio::LinkQuality closed = model.link(north, south);
  EXPECT_EQ(closed.crossings, 1);
  EXPECT_NEAR(closed.obstacle_loss_db, 12.0, 1e-12);  // the default wall loss
  EXPECT_NEAR(closed.signal_dbm, 20.0 - 63.39454 - 12.0, 1e-4);

  ASSERT_TRUE(world.set_door("A-120", M_PI / 2).accepted);
  world.step(0.1);
  ASSERT_FALSE(world.door("A-120")->closed());
  sync_door_leaves(world.doors(), model);
  const radio::LinkQuality open = model.link(north, south);
  EXPECT_EQ(open.crossings, 0);
  EXPECT_EQ(open.obstacle_loss_db, 0.0);
  EXPECT_NEAR(open.signal_dbm, 20.0 - 63.39454, 1e-4);
  // Beside the doorway the wall still costs two crossings and 0.2 m inside.
  EXPECT_NEAR(model.link({5.0, 8.0}, {5.0, 2.0}).obstacle_loss_db, 2 * 12.0 + 0.2 * 0.5, 1e-9);
}

TEST(RadioSetup, OccupancyRastersAttenuate) {
  Scenario s;
  s.world.name = "map";
  s.world.width = 20.0;
  s.world.height = 10.0;
  auto raster = std::make_shared<grid::OccupancyRaster>(40, 20, 0.5);
  for (int row = 0; row < 20; ++row) raster->set_blocked({10, row}, true);  // x in [5, 5.5]
  s.world.rasters = {{"wall.yaml", raster}};
  s.radio.wall_loss_db = 8.0;
  const radio::RadioModel model = make_radio_model(s);
  ASSERT_EQ(model.rasters().size(), 1u);
  const radio::LinkQuality l = model.link({1.0, 2.3}, {9.0, 2.3});
  EXPECT_EQ(l.crossings, 1);
  EXPECT_NEAR(l.obstacle_loss_db, 8.0 + 0.5 * 0.5, 1e-9);  // the scenario's wall loss
}

}  // namespace
}  // namespace autonomy::sim
