// The spacecraft section of scenario files: a valid section's values and defaults, and the exact
// position and text of its errors.
#include "simulator/scenario/scenario_loader.hpp"
#include "simulator/spacecraft/spacecraft.hpp"

#include <gtest/gtest.h>

namespace autonomy::sim {
namespace {

using Errors = std::vector<std::string>;

// Line 1 "spacecraft {", then the lines of `body`, then "}".
std::string section(const std::string& body) {
  return "spacecraft {\n" + body + "}\n";
}

const std::string kMinimal = R"(  name: "ds1"
  targets { name: "star" direction { z: 1 } }
  targets { name: "rock" direction { x: 1 } }
  attitude {
    initial_target: "star"
    control_mode: "thrusters"
    thrusters: "tx"
    modes { name: "thrusters" actuators: "tx" max_rate_deg_s: 0.2 }
  }
)";

Errors section_errors_of(const std::string& text) {
  const ScenarioLoadResult result = load_scenario_text(text, "s.pbtxt");
  EXPECT_FALSE(result.ok());
  Errors out;
  for (const ScenarioError& e : result.errors) out.push_back(e.to_string());
  return out;
}

TEST(SpacecraftSection, MinimalSectionNeedsNoWorldAndTakesTheDefaults) {
  const ScenarioLoadResult r = load_scenario_text(section(kMinimal), "s.pbtxt");
  ASSERT_TRUE(r.ok()) << r.error_text();
  ASSERT_TRUE(r.scenario->spacecraft.has_value());
  const spacecraft::SpacecraftSpec& s = *r.scenario->spacecraft;
  EXPECT_EQ(s.name, "ds1");
  EXPECT_EQ(s.targets.size(), 2u);
  EXPECT_EQ(s.attitude.thrusters, std::vector<std::string>{"tx"});
  EXPECT_DOUBLE_EQ(s.attitude.modes[0].max_rate_deg_s, 0.2);
  EXPECT_EQ(s.ion_engine.max_level, 10);
  EXPECT_EQ(s.camera.initial_mode, "ready");
  EXPECT_DOUBLE_EQ(s.power.battery_soc, 1.0);
  EXPECT_DOUBLE_EQ(r.scenario->world.width, 1.0);  // the empty stand-in world
  EXPECT_TRUE(r.scenario->world.robots_at_start.empty());
  EXPECT_DOUBLE_EQ(s.fault_protection.commander_timeout_s, 600.0);
  EXPECT_EQ(s.fault_protection.commander, "executive");
  EXPECT_EQ(s.command_queue_limit, 1000u);
}

TEST(SpacecraftSection, FaultProtectionAndQueueLimitAreReadAndChecked) {
  const ScenarioLoadResult r = load_scenario_text(
      section(kMinimal + "  fault_protection { commander_timeout_s: 30 commander: \"exec\" }\n"
                         "  command_queue_limit: 5\n"),
      "s.pbtxt");
  ASSERT_TRUE(r.ok()) << r.error_text();
  EXPECT_DOUBLE_EQ(r.scenario->spacecraft->fault_protection.commander_timeout_s, 30.0);
  EXPECT_EQ(r.scenario->spacecraft->fault_protection.commander, "exec");
  EXPECT_EQ(r.scenario->spacecraft->command_queue_limit, 5u);
  EXPECT_EQ(section_errors_of(section(
                kMinimal + "  fault_protection { commander_timeout_s: -1 commander: \"\" }\n"
                           "  command_queue_limit: 0\n")),
            (Errors{"s.pbtxt:11:22: fault_protection: commander_timeout_s must be >= 0 (0: off) "
                    "(got -1.0)",
                    "s.pbtxt:11:46: fault_protection: commander must be a service name of 1..64 "
                    "characters",
                    "s.pbtxt:12:3: command_queue_limit must be at least 1 (got 0)"}));
}

TEST(SpacecraftSection, FaultsWithTimesAndEventsAreRead) {
  const ScenarioLoadResult r =
      load_scenario_text(section(kMinimal + R"(  electronics { name: "lpe" devices: "camera" }
  power { switches { name: "cam_sw" device: "camera" } }
  faults { id: "a" kind: STUCK_ON subject: "camera" on_command: "camera take_image" }
  faults { id: "b" kind: FAILED subject: "lpe" at_s: 7200 reset_cures: false }
  faults { id: "c" kind: FALSE_SENSOR subject: "cam_sw_status" value: 0 at_s: 10 }
  faults { id: "d" kind: STUCK_CLOSED subject: "tx" }
  faults { id: "e" kind: NEVER_CONFIRMED subject: "ips" on_command: "ips thrust" }
)"),
                         "s.pbtxt");
  ASSERT_TRUE(r.ok()) << r.error_text();
  const auto& f = r.scenario->spacecraft->faults;
  ASSERT_EQ(f.size(), 5u);
  EXPECT_EQ(f[0].kind, spacecraft::FaultKind::StuckOn);
  EXPECT_EQ(f[0].on_command, "camera take_image");
  EXPECT_EQ(f[1].at_s, 7200.0);
  EXPECT_FALSE(f[1].reset_cures);
  EXPECT_EQ(f[2].subject, "cam_sw_status");
  EXPECT_FALSE(f[3].at_s.has_value());
  EXPECT_EQ(f[4].kind, spacecraft::FaultKind::NeverConfirmed);
}

TEST(SpacecraftSection, ErrorsNameTheirLineAndColumn) {
  EXPECT_EQ(section_errors_of(section(R"(  name: "ds1"
  targets { name: "star" direction { z: 1 } }
  attitude {
    initial_target: "moon"
    control_mode: "thrusters"
    modes { name: "thrusters" actuators: "ty" max_rate_deg_s: 0.2 }
  }
)")),
            (Errors{"s.pbtxt:5:5: attitude: initial_target 'moon' is not a target",
                    "s.pbtxt:7:31: control mode 'thrusters': actuator 'ty' is not one of "
                    "attitude.thrusters"}));
  EXPECT_EQ(
      section_errors_of(section(kMinimal + R"(  ion_engine { max_level: 0 }
  camera { initial_mode: "imaging" exposure_s: -1 }
  telecom {
    windows { station: "dss-14" start_s: 100 end_s: 200 rate_kbps: 10 }
    windows { station: "dss-43" start_s: 150 end_s: 120 rate_kbps: 0 }
  }
)")),
      (Errors{"s.pbtxt:11:16: ion_engine: max_level must be in 1..1000 (got 0)",
              "s.pbtxt:12:12: camera: initial_mode must be \"off\" or \"ready\" (got \"imaging\")",
              "s.pbtxt:12:36: camera: exposure_s must be positive (got -1.0)",
              "s.pbtxt:15:33: window 1 (dss-43): starts at 150.0 s, before the previous window "
              "ends (200.0 s)",
              "s.pbtxt:15:46: window 1 (dss-43): end_s must be after start_s (got 120.0)",
              "s.pbtxt:15:57: window 1 (dss-43): rate_kbps must be positive (got 0.0)"}));
  EXPECT_EQ(
      section_errors_of(
          section(kMinimal + R"(  faults { id: "x" kind: STUCK_CLOSED subject: "camera" at_s: 5 }
  faults { id: "y" subject: "ips" }
  faults { id: "z" kind: FAILED subject: "ips" on_command: "warp engage" }
)")),
      (Errors{
          "s.pbtxt:11:39: stuck_closed fault 'x': 'camera' is not a thruster (thrusters: tx)",
          "s.pbtxt:12:3: fault 'y': kind is missing (STUCK_ON, FAILED, FALSE_SENSOR, STUCK_CLOSED, "
          "NEVER_CONFIRMED)",
          "s.pbtxt:13:48: failed fault 'z': on_command names unknown device 'warp'"}));
  EXPECT_EQ(section_errors_of("spacecraft { name: \"x\" }\n"),
            (Errors{"s.pbtxt:1:1: spacecraft: at least one target is needed",
                    "s.pbtxt:1:1: spacecraft: attitude is missing"}));
}

}  // namespace
}  // namespace autonomy::sim
