// Spacecraft fault protection: when its commander has been silent for the timeout (simulated
// time), the spacecraft safes itself (engine to standby, camera off, attitude held), says so in
// telemetry and in its events, and a command or a heartbeat of the commander ends safe mode.
#include "simulator/spacecraft/spacecraft.hpp"

#include <gtest/gtest.h>

namespace autonomy::sim::spacecraft {
namespace {

// Star on +z (pointed at the start), asteroid on +x: a 90 degree turn at 0.2 deg/s takes 450 s.
SpacecraftSpec spec_with_timeout(double timeout_s) {
  SpacecraftSpec s;
  s.name = "ds1";
  s.targets = {{"star", {0, 0, 1}}, {"asteroid", {1, 0, 0}}};
  s.attitude.initial_target = "star";
  s.attitude.control_mode = "thrusters";
  s.attitude.thrusters = {"thruster_x"};
  s.attitude.modes = {{"thrusters", {"thruster_x"}, 0.2}};
  s.ion_engine = {10, 500, 2300};
  s.camera = {"ready", 10, 20, 5, 2.0};
  s.storage = {10, 0};
  s.fault_protection.commander_timeout_s = timeout_s;
  return s;
}

Command protection_cmd(const std::string& device, const std::string& command,
            std::vector<std::string> arguments = {}, const std::string& id = "c") {
  return {id, "test", device, command, std::move(arguments)};
}

void run_steps(Spacecraft& sc, int steps) {
  for (int i = 0; i < steps; ++i) sc.step(1.0);
}

TEST(FaultProtectionTest, SafesWhenTheCommanderIsSilentForTheTimeout) {
  Spacecraft sc(spec_with_timeout(60));
  ASSERT_TRUE(sc.submit(protection_cmd("ips", "thrust", {"5"})).accepted);  // heard at 0 s
  ASSERT_TRUE(sc.submit(protection_cmd("adcs", "turn", {"asteroid"})).accepted);
  run_steps(sc, 60);  // steps starting at 0..59 s: silent for less than 60 s at each
  EXPECT_FALSE(sc.safe_mode());
  EXPECT_EQ(sc.mode("ips"), "thrusting");
  EXPECT_EQ(sc.mode("adcs"), "turning");
  EXPECT_TRUE(sc.take_events().empty());
  EXPECT_DOUBLE_EQ(sc.telemetry().fault_protection.commander_silent_s, 60.0);

  run_steps(sc, 1);  // the step starting at 60 s safes first
  EXPECT_TRUE(sc.safe_mode());
  EXPECT_EQ(sc.mode("ips"), "standby");
  EXPECT_EQ(sc.mode("camera"), "off");
  EXPECT_EQ(sc.mode("adcs"), "pointing");
  EXPECT_EQ(sc.attitude().pointing_target(), "");  // held where the turn was: 12 deg done
  EXPECT_NEAR(sc.attitude().angle_to_deg("star"), 12.0, 1e-9);
  const msg::SpacecraftTelemetry t = sc.telemetry();
  EXPECT_TRUE(t.fault_protection.safe_mode);
  EXPECT_EQ(t.fault_protection.reason, "no command or heartbeat of executive for 60 s");
  EXPECT_EQ(t.fault_protection.safed_at_ns, 60'000'000'000);
  EXPECT_EQ(t.fault_protection.safings, 1u);
  EXPECT_DOUBLE_EQ(t.fault_protection.commander_timeout_s, 60.0);
  EXPECT_EQ(t.propulsion.thrust_level, 0u);
  const auto events = sc.take_events();
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].kind, "safed");
  EXPECT_EQ(events[0].detail,
            "no command or heartbeat of executive for 60 s: ips to standby, camera off, turn to "
            "asteroid stopped, attitude held");
  EXPECT_DOUBLE_EQ(events[0].time_s, 60.0);

  run_steps(sc, 100);  // safed once: no second safing while it lasts
  EXPECT_TRUE(sc.take_events().empty());
  EXPECT_EQ(sc.telemetry().fault_protection.safings, 1u);
}

TEST(FaultProtectionTest, AHeartbeatEndsSafeModeAndCommandsAreCarriedOutAgain) {
  Spacecraft sc(spec_with_timeout(60));
  run_steps(sc, 61);  // nobody ever spoke: the start counts as the last sign
  ASSERT_TRUE(sc.safe_mode());
  EXPECT_EQ(sc.take_events().at(0).detail,
            "no command or heartbeat of executive for 60 s: camera off, attitude held");

  sc.commander_heard("heartbeat of executive/ds1");
  EXPECT_FALSE(sc.safe_mode());
  const auto events = sc.take_events();
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].kind, "resumed");
  EXPECT_EQ(events[0].detail, "safe mode ended by heartbeat of executive/ds1");
  EXPECT_DOUBLE_EQ(events[0].time_s, 61.0);
  EXPECT_FALSE(sc.telemetry().fault_protection.safe_mode);
  EXPECT_EQ(sc.telemetry().fault_protection.reason, "");
  EXPECT_EQ(sc.telemetry().fault_protection.safings, 1u);  // the run_steps's count stays

  ASSERT_TRUE(sc.submit(protection_cmd("camera", "power_on")).accepted);
  ASSERT_TRUE(sc.submit(protection_cmd("ips", "thrust", {"3"})).accepted);
  run_steps(sc, 1);
  EXPECT_EQ(sc.mode("camera"), "ready");
  EXPECT_EQ(sc.mode("ips"), "thrusting");

  // Silent again for the timeout (from the last command at 61 s): safed a second time.
  run_steps(sc, 59);
  EXPECT_FALSE(sc.safe_mode());
  run_steps(sc, 1);
  EXPECT_TRUE(sc.safe_mode());
  EXPECT_EQ(sc.telemetry().fault_protection.safings, 2u);
  EXPECT_EQ(sc.telemetry().fault_protection.safed_at_ns, 121'000'000'000);
}

TEST(FaultProtectionTest, ACommandEndsSafeModeAndIsCheckedAsAlways) {
  Spacecraft sc(spec_with_timeout(10));
  run_steps(sc, 11);
  ASSERT_TRUE(sc.safe_mode());
  (void)sc.take_events();
  // Even a rejected command shows that somebody is commanding.
  EXPECT_EQ(sc.submit(protection_cmd("camera", "take_image", {"star"}, "img-1")).reason,
            "camera is off, not ready");
  EXPECT_FALSE(sc.safe_mode());
  const auto events = sc.take_events();
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].detail, "safe mode ended by command img-1 from test");
  EXPECT_TRUE(sc.submit(protection_cmd("ips", "thrust", {"2"})).accepted);
  EXPECT_EQ(sc.mode("ips"), "thrusting");
}

TEST(FaultProtectionTest, SignsOfTheCommanderWithinTheTimeoutKeepItFromSafing) {
  Spacecraft sc(spec_with_timeout(60));
  ASSERT_TRUE(sc.submit(protection_cmd("ips", "thrust", {"5"})).accepted);
  for (int i = 0; i < 20; ++i) {
    run_steps(sc, 59);
    sc.commander_heard("lockstep ack of executive/ds1");
  }
  EXPECT_FALSE(sc.safe_mode());
  EXPECT_EQ(sc.mode("ips"), "thrusting");
  EXPECT_TRUE(sc.take_events().empty());
  EXPECT_DOUBLE_EQ(sc.telemetry().fault_protection.commander_silent_s, 0.0);
}

TEST(FaultProtectionTest, ATimeoutOfZeroSwitchesItOff) {
  Spacecraft sc(spec_with_timeout(0));
  ASSERT_TRUE(sc.submit(protection_cmd("ips", "thrust", {"5"})).accepted);
  run_steps(sc, 100000);
  EXPECT_FALSE(sc.safe_mode());
  EXPECT_EQ(sc.mode("ips"), "thrusting");
  EXPECT_DOUBLE_EQ(sc.telemetry().fault_protection.commander_timeout_s, 0.0);
  EXPECT_THROW(Spacecraft(spec_with_timeout(-1)), std::invalid_argument);
}

TEST(FaultProtectionTest, AnEngineStuckOnStaysOnAndTheEventSaysSo) {
  Spacecraft sc(spec_with_timeout(30));
  ASSERT_TRUE(sc.submit(protection_cmd("ips", "thrust", {"4"})).accepted);
  ASSERT_TRUE(sc.inject({"stuck", FaultKind::StuckOn, "ips", 0, true, std::nullopt, ""}).accepted);
  run_steps(sc, 31);
  ASSERT_TRUE(sc.safe_mode());
  EXPECT_EQ(sc.mode("ips"), "thrusting");
  EXPECT_EQ(sc.take_events().at(0).detail,
            "no command or heartbeat of executive for 30 s: ips stuck on, still thrusting, camera "
            "off, attitude held");
}

}  // namespace
}  // namespace autonomy::sim::spacecraft
