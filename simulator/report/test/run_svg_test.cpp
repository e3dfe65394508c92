#include "simulator/report/run_svg.hpp"
#include "simulator/report/trajectory_recorder.hpp"

#include <gtest/gtest.h>

namespace autonomy::sim {
namespace {

TEST(TrajectoryRecorder, KeepsPointsSpacedApartAndTheLatest) {
  TrajectoryRecorder rec(0.5);
  for (int i = 0; i <= 10; ++i) rec.record("r1", {0.1 * i, 0.0});  // 0 .. 1.0 m in 0.1 m steps
  const auto paths = rec.paths();
  ASSERT_EQ(paths.count("r1"), 1u);
  const auto& p = paths.at("r1");
  ASSERT_EQ(p.size(), 3u);  // 0.0, 0.5 (first at >= 0.5 m), 1.0 (latest)
  EXPECT_NEAR(p[0].x(), 0.0, 1e-12);
  EXPECT_NEAR(p[1].x(), 0.5, 1e-9);
  EXPECT_NEAR(p[2].x(), 1.0, 1e-9);
}

TEST(TrajectoryRecorder, ParkedRobotKeepsOnePoint) {
  TrajectoryRecorder rec(0.05);
  for (int i = 0; i < 1000; ++i) rec.record("r2", {3.0, 4.0});
  EXPECT_EQ(rec.paths().at("r2").size(), 1u);
}

TEST(RunSvg, DrawsObstaclesPathsAndRobots) {
  WorldSpec world;
  world.name = "w";
  world.width = 10;
  world.height = 5;
  world.obstacles = {{4, 0, 5, 3}};
  RunPicture pic;
  pic.world = &world;
  pic.paths["r1"] = {{1, 1}, {2, 4}, {8, 4}};
  RobotStatus r;
  r.id = "r1";
  r.pose = {8, 4, 0};
  r.radius = 0.3;
  pic.final_robots = {r};
  pic.caption = "a <run> & more";
  const std::string svg = render_run_svg(pic);
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  EXPECT_NE(svg.find("<polyline"), std::string::npos);
  EXPECT_NE(svg.find("a &lt;run&gt; &amp; more"), std::string::npos);
  // One world outline plus one obstacle plus one legend swatch.
  size_t rects = 0;
  for (size_t at = svg.find("<rect"); at != std::string::npos; at = svg.find("<rect", at + 1)) ++rects;
  EXPECT_EQ(rects, 4u);  // background, world, obstacle, legend
}

size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(TrajectoryRecorder, KeepsAPointWhereTheConnectivityFlagChanges) {
  TrajectoryRecorder rec(1.0);
  rec.record("r1", {0.0, 0.0}, true);
  rec.record("r1", {0.2, 0.0}, true);   // too close: dropped
  rec.record("r1", {0.4, 0.0}, false);  // flag changed: kept
  rec.record("r1", {0.6, 0.0}, false);  // dropped
  rec.record("r1", {0.6, 0.0}, true);   // flag changed while parked: kept
  rec.record("r1", {0.9, 0.0}, true);   // latest
  const auto paths = rec.paths();
  const auto flags = rec.connected_flags();
  ASSERT_EQ(paths.at("r1").size(), 4u);
  EXPECT_NEAR(paths.at("r1")[1].x(), 0.4, 1e-12);
  EXPECT_NEAR(paths.at("r1")[2].x(), 0.6, 1e-12);
  EXPECT_NEAR(paths.at("r1")[3].x(), 0.9, 1e-12);
  EXPECT_EQ(flags.at("r1"), (std::vector<bool>{true, false, true, true}));
  // The old two-argument record counts as connected.
  rec.record("r2", {1.0, 1.0});
  EXPECT_EQ(rec.connected_flags().at("r2"), std::vector<bool>{true});
}

WorldSpec ten_by_five() {
  WorldSpec world;
  world.name = "w";
  world.width = 10;
  world.height = 5;
  return world;
}

TEST(RunSvg, DrawsDisconnectedStretchesDashed) {
  const WorldSpec world = ten_by_five();
  RunPicture pic;
  pic.world = &world;
  pic.paths["r1"] = {{1, 1}, {2, 1}, {3, 1}, {4, 1}, {5, 1}};
  // Segments end at points 1..4 with flags T, F, F, T: solid, dashed (two segments), solid.
  pic.path_connected["r1"] = {true, true, false, false, true};
  const std::string svg = render_run_svg(pic);
  EXPECT_EQ(count(svg, "<polyline"), 3u);
  EXPECT_EQ(count(svg, "<polyline fill=\"none\" stroke=\"#1f77b4\" stroke-width=\"1.5\""), 1u);
  EXPECT_NE(svg.find("connected to a teammate"), std::string::npos);
  EXPECT_NE(svg.find("no teammate in reach"), std::string::npos);
  // The dashed run goes from point 1 to point 3: x = 2, 3, 4 m at 60 px/m after a 20 px margin.
  EXPECT_NE(svg.find("stroke-dasharray=\"5 4\" points=\"140,306 200,306 260,306 \""), std::string::npos);
}

TEST(RunSvg, FlagsThatDoNotMatchThePathAreIgnored) {
  const WorldSpec world = ten_by_five();
  RunPicture pic;
  pic.world = &world;
  pic.paths["r1"] = {{1, 1}, {2, 1}, {3, 1}};
  pic.path_connected["r1"] = {true, false};
  const std::string svg = render_run_svg(pic);
  EXPECT_EQ(count(svg, "<polyline"), 1u);
  EXPECT_EQ(svg.find("stroke-dasharray"), std::string::npos);
  EXPECT_EQ(svg.find("connected to a teammate"), std::string::npos);  // no second legend row
}

TEST(RunSvg, DrawsDoorsAreasPolygonObstaclesAndPlaces) {
  const WorldSpec world = ten_by_five();
  RunPicture pic;
  pic.world = &world;
  pic.polygon_obstacles = {{{6, 1}, {8, 1}, {7, 3}}};
  pic.doors = {{{2, 0}, {2, 1}, true, "d-open"}, {{4, 0}, {4, 1}, false, "A-120"}};
  pic.attenuating_areas = {{{{1, 3}, {3, 3}, {3, 4}, {1, 4}}, "parked cars"}};
  pic.places = {{"anna-desk", {5, 4}, 0.5}};
  const std::string svg = render_run_svg(pic);
  EXPECT_EQ(count(svg, "fill=\"#555\""), 1u);                 // the triangle
  EXPECT_EQ(count(svg, "<polygon"), 3u);                      // triangle, area, area legend swatch
  EXPECT_EQ(count(svg, "fill-opacity=\"0.22\""), 2u);         // area and its swatch
  EXPECT_EQ(count(svg, "stroke=\"#8b0000\" stroke-width=\""), 2u);  // closed door and its legend line
  EXPECT_EQ(count(svg, "stroke=\"#2e8b57\""), 2u);             // open door and its legend line
  EXPECT_NE(svg.find(">A-120</text>"), std::string::npos);
  EXPECT_NE(svg.find(">parked cars</text>"), std::string::npos);
  EXPECT_NE(svg.find(">anna-desk</text>"), std::string::npos);
  EXPECT_NE(svg.find(">closed door</text>"), std::string::npos);
  EXPECT_NE(svg.find(">open door</text>"), std::string::npos);
  EXPECT_NE(svg.find(">attenuating area</text>"), std::string::npos);
  EXPECT_EQ(count(svg, "<rect"), 2u);  // background and world: nothing new drawn as a rect
}

}  // namespace
}  // namespace autonomy::sim
