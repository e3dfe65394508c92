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

}  // namespace
}  // namespace autonomy::sim
