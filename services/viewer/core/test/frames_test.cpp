// The JSON frames pushed to the pages: contents from samples.
#include "services/viewer/core/frames.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace autonomy::viewer {
namespace {

// A 1.6 m doorway centred at (10, 3) along +y (hinge at (10, 2.2)), opening clockwise.
msg::WorldMap corridor_with_door() {
  msg::WorldMap m;
  m.name = "door-corridor";
  m.width = 20.0;
  m.height = 6.0;
  m.obstacles.push_back({9.9, 0.0, 10.1, 2.2});
  m.doors.push_back({"d1", 10.0, 3.0, 1.6, M_PI / 2, -M_PI / 2});
  m.polygons.push_back({"west", {{0, 0}, {10, 0}, {10, 6}, {0, 6}}});
  return m;
}

TEST(FramesTest, MapFrameCarriesObstaclesRoomsAndDoorways) {
  WorldView view;
  EXPECT_FALSE(map_frame(view)["known"].get<bool>());
  view.apply(corridor_with_door());
  const auto f = map_frame(view);
  EXPECT_EQ(f["type"], "map");
  EXPECT_EQ(f["name"], "door-corridor");
  ASSERT_EQ(f["obstacles"].size(), 1u);
  EXPECT_DOUBLE_EQ(f["obstacles"][0][3].get<double>(), 2.2);
  ASSERT_EQ(f["polygons"].size(), 1u);
  EXPECT_EQ(f["polygons"][0]["name"], "west");
  EXPECT_EQ(f["polygons"][0]["points"].size(), 8u);
  ASSERT_EQ(f["doors"].size(), 1u);
  EXPECT_EQ(f["doors"][0]["id"], "d1");
}

TEST(FramesTest, ClosedDoorLeafLiesInTheDoorwayAndOpenOneTurnsToItsSide) {
  const msg::MapDoor door{"d1", 10.0, 3.0, 1.6, M_PI / 2, -M_PI / 2};
  const LeafSegment closed = door_leaf(door, 0.0);
  EXPECT_NEAR(closed.hinge_x, 10.0, 1e-9);
  EXPECT_NEAR(closed.hinge_y, 2.2, 1e-9);
  EXPECT_NEAR(closed.tip_x, 10.0, 1e-9);
  EXPECT_NEAR(closed.tip_y, 3.8, 1e-9);
  const LeafSegment open = door_leaf(door, M_PI / 2);  // clockwise from +y: towards +x
  EXPECT_NEAR(open.tip_x, 11.6, 1e-9);
  EXPECT_NEAR(open.tip_y, 2.2, 1e-9);
}

TEST(FramesTest, StateFrameHasRobotsDoorsLinksAndJobs) {
  WorldView view;
  view.apply(corridor_with_door());
  msg::RobotState s;
  s.robot_id = "r1";
  s.tick = 40;
  s.sim_time_ns = 2'000'000'000;
  s.x = 2.00049;
  s.y = 3.0;
  s.radius = 0.3;
  view.apply(s);
  view.apply(msg::NavGoal{"r1", "far", 18.0, 3.0, 0.2, ""});
  msg::DoorState d;
  d.door_id = "d1";
  d.closed = true;
  view.apply(d);
  msg::RadioLink l;
  l.robot_a = "r1";
  l.robot_b = "r2";
  l.signal_dbm = -71.25;
  l.connected = true;
  view.apply(l);
  msg::CourierJobStatus j;
  j.job_id = "job-1";
  j.state = msg::JobState::Underway;
  j.robot_id = "r1";
  j.reason = "";
  view.apply(j);

  const auto f = state_frame(view, 7);
  EXPECT_EQ(f["type"], "state");
  EXPECT_EQ(f["seq"], 7);
  EXPECT_EQ(f["tick"], 40);
  EXPECT_DOUBLE_EQ(f["sim_time_s"].get<double>(), 2.0);
  ASSERT_EQ(f["robots"].size(), 1u);
  const auto& r = f["robots"][0];
  EXPECT_EQ(r["id"], "r1");
  EXPECT_DOUBLE_EQ(r["x"].get<double>(), 2.0);  // rounded to mm
  EXPECT_EQ(r["trail"].size(), 2u);  // one position: x, y
  EXPECT_EQ(r["goal"]["id"], "far");
  EXPECT_DOUBLE_EQ(r["goal"]["x"].get<double>(), 18.0);
  EXPECT_FALSE(r["goal"].contains("state"));  // no status heard yet
  ASSERT_EQ(f["doors"].size(), 1u);
  EXPECT_TRUE(f["doors"][0]["closed"].get<bool>());
  ASSERT_EQ(f["doors"][0]["leaf"].size(), 4u);
  EXPECT_DOUBLE_EQ(f["doors"][0]["leaf"][3].get<double>(), 3.8);
  ASSERT_EQ(f["links"].size(), 1u);
  EXPECT_DOUBLE_EQ(f["links"][0]["signal_dbm"].get<double>(), -71.25);
  ASSERT_EQ(f["jobs"].size(), 1u);
  EXPECT_EQ(f["jobs"][0]["state"], "underway");
  EXPECT_EQ(f["jobs"][0]["history"].size(), 1u);
}

TEST(FramesTest, RobotKnownOnlyByItsGoalIsNotDrawn) {
  WorldView view;
  view.apply(msg::NavGoal{"r7", "g", 1.0, 1.0, 0.1, ""});
  EXPECT_TRUE(state_frame(view, 1)["robots"].empty());
}

TEST(FramesTest, DoorWithoutMapHasNoLeaf) {
  WorldView view;
  msg::DoorState d;
  d.door_id = "d9";
  view.apply(d);
  EXPECT_FALSE(state_frame(view, 1)["doors"][0].contains("leaf"));
}

TEST(FramesTest, RasterRunsAlternateFromFree) {
  msg::MapRaster r;
  r.cols = 3;
  r.rows = 2;
  r.blocked = {1, 1, 0, 0, 0, 1};
  EXPECT_EQ(raster_runs(r), (std::vector<uint32_t>{0, 2, 3, 1}));
  r.blocked = {0, 0, 0, 0, 0, 0};
  EXPECT_EQ(raster_runs(r), (std::vector<uint32_t>{6}));
}

}  // namespace
}  // namespace autonomy::viewer
