// Every mission in deploy/missions loads, and its plans build on a 250 x 250 m map.
#include "services/behavior/core/mission/mission_executor.hpp"
#include "services/behavior/core/mission/mission_loader.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

namespace autonomy::behavior {
namespace {

std::vector<std::string> mission_files() {
  std::vector<std::string> out;
  for (const auto& entry : std::filesystem::directory_iterator(AUTONOMY_MISSIONS_DIR)) {
    if (entry.path().extension() == ".pbtxt") out.push_back(entry.path().string());
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(ExampleMissions, AllSixConfigurationsForThreeRobotsLoad) {
  const auto files = mission_files();
  EXPECT_EQ(files.size(), 18u);
  const WorldMap open_map{250.0, 250.0, {}};
  for (const std::string& path : files) {
    SCOPED_TRACE(path);
    const MissionLoadResult r = load_mission_file(path);
    ASSERT_TRUE(r.ok()) << r.error_text();
    // Coarse cells keep the test fast; the node uses the map's own resolution.
    PlanLibrary plans = build_plan_library(*r.mission, open_map, 2.0, 1.0);
    MissionExecutor executor(*r.mission, std::move(plans));
    Perception p;
    p.pose = {125.0, 3.0, M_PI / 2};
    p.limits = {1.0, 1.0};
    for (const std::string& id : r.mission->teammates) p.teammates.push_back({id, std::nullopt, true});
    const MissionStep s = executor.step(p);
    EXPECT_FALSE(s.events.empty());
    EXPECT_LE(s.velocity.norm(), 1.0);
  }
}

}  // namespace
}  // namespace autonomy::behavior
