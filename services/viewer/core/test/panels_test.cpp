// Panels: the latest sample per group and key, as JSON.
#include "services/viewer/core/panels.hpp"

#include <gtest/gtest.h>

namespace autonomy::viewer {
namespace {

TEST(PanelsTest, KeepsTheLatestSampleOfEachKeyAndForgetsErasedOnes) {
  Panels panels;
  EXPECT_EQ(panels.frame(), (nlohmann::json{{"type", "panels"}}));
  panels.apply("faults", "f1", {{"fault_id", "f1"}, {"kind", "stuck_on"}, {"active", true}, {"ended_by", ""}});
  panels.apply("faults", "f1", {{"fault_id", "f1"}, {"kind", "stuck_on"}, {"active", false}, {"ended_by", "reset"}});
  panels.apply("executive", "main", {{"executive", "main"}, {"state", "executing"}});
  const uint64_t before = panels.version();
  EXPECT_EQ(before, 3u);

  const auto f = panels.frame();
  EXPECT_EQ(f["type"], "panels");
  ASSERT_EQ(f["faults"].size(), 1u);
  EXPECT_FALSE(f["faults"]["f1"]["active"].get<bool>());
  EXPECT_EQ(f["faults"]["f1"]["ended_by"], "reset");
  EXPECT_EQ(f["executive"]["main"]["state"], "executing");

  panels.erase("faults", "f1");
  EXPECT_GT(panels.version(), before);
  EXPECT_TRUE(panels.frame()["faults"].empty());
  panels.erase("faults", "unknown");  // nothing to forget: no change
  panels.erase("nothing", "f1");
  EXPECT_EQ(panels.version(), before + 1);
}

}  // namespace
}  // namespace autonomy::viewer
