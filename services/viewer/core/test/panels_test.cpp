// Panels: the latest sample per group and key, as JSON.
#include "services/viewer/core/panels.hpp"

#include <gtest/gtest.h>

namespace autonomy::viewer {
namespace {

TEST(PanelsTest, KeepsTheLatestSampleOfEachKeyAndForgetsErasedOnes) {
  Panels panels;
  EXPECT_EQ(panels.frame(), (nlohmann::json{{"type", "panels"}}));
  msg::SpacecraftFaultState fault;
  fault.fault_id = "f1";
  fault.kind = "stuck_on";
  fault.active = true;
  panels.apply(fault);
  fault.active = false;
  fault.ended_by = "reset";
  panels.apply(fault);
  msg::ExecutiveStatus status;
  status.executive = "main";
  status.state = "executing";
  panels.apply(status);
  const uint64_t before = panels.version();

  const auto f = panels.frame();
  EXPECT_EQ(f["type"], "panels");
  EXPECT_FALSE(f["faults"]["f1"]["active"].get<bool>());
  EXPECT_EQ(f["faults"]["f1"]["ended_by"], "reset");
  EXPECT_EQ(f["executive"]["main"]["state"], "executing");

  panels.erase("faults", "f1");
  EXPECT_GT(panels.version(), before);
  EXPECT_TRUE(panels.frame()["faults"].empty());
  panels.erase("faults", "unknown");  // nothing to forget: no change
  EXPECT_EQ(panels.version(), before + 1);
}

}  // namespace
}  // namespace autonomy::viewer
