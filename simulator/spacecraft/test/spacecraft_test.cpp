// The spacecraft core: turns take angle / rate, commands are rejected with their reasons and
// confirmed in telemetry, storage fills and downlinks, power balances, and each fault of the
// Remote Agent Experiment behaves as docs/spacecraft.md says.
#include "simulator/spacecraft/spacecraft.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace autonomy::sim::spacecraft {
namespace {

// Star on +z (where the spacecraft points at the start), asteroid on +x: a 90 degree turn.
SpacecraftSpec test_spec() {
  SpacecraftSpec s;
  s.name = "ds1";
  s.targets = {{"star", {0, 0, 1}}, {"asteroid", {1, 0, 0}}, {"behind", {0, 0, -1}}};
  s.attitude.initial_target = "star";
  s.attitude.control_mode = "thrusters";
  s.attitude.thrusters = {"thruster_x", "thruster_y", "thruster_z"};
  s.attitude.modes = {{"thrusters", {"thruster_x", "thruster_y", "thruster_z"}, 0.2},
                      {"wheels_and_other_thrusters", {"thruster_y", "thruster_z"}, 0.1}};
  s.ion_engine = {10, 500, 2300};  // 200 W per level
  s.camera = {"ready", 10, 20, 5, 2.0};
  s.power.solar_array_w = 2000;
  s.power.battery_capacity_wh = 1000;
  s.power.battery_soc = 0.5;
  s.power.base_load_w = 300;
  s.power.max_discharge_w = 700;
  s.power.switches = {{"camera_switch", "camera", true}};
  s.telecom.transmit_power_w = 100;
  s.telecom.windows = {{"goldstone", 100, 200, 80}};  // 80 kbps = 0.01 MB/s
  s.storage = {10, 0};
  s.electronics = {{"lpe", {"camera"}}};
  s.fault_protection.commander_timeout_s = 0;  // these tests are about physics and faults
  return s;
}

Command cmd(const std::string& device, const std::string& command,
            std::vector<std::string> arguments = {}, const std::string& id = "c") {
  return {id, "test", device, command, std::move(arguments)};
}

void run(Spacecraft& sc, int steps, double dt = 1.0) {
  for (int i = 0; i < steps; ++i) sc.step(dt);
}

const msg::DeviceReport& report(const msg::SpacecraftTelemetry& t, const std::string& device) {
  for (const auto& d : t.devices)
    if (d.device == device) return d;
  throw std::out_of_range(device);
}

double reading(const msg::SpacecraftTelemetry& t, const std::string& sensor) {
  for (const auto& r : t.readings)
    if (r.sensor == sensor) return r.value;
  throw std::out_of_range(sensor);
}

TEST(SpacecraftTest, StartsPointedAtItsInitialTargetWithEveryDevice) {
  Spacecraft sc(test_spec());
  EXPECT_EQ(sc.attitude().pointing_target(), "star");
  EXPECT_NEAR(sc.attitude().pointing_error_deg(), 0.0, 1e-9);
  EXPECT_EQ(sc.devices(),
            (std::vector<std::string>{"adcs", "camera", "ips", "lpe", "power", "storage", "telecom",
                                      "thruster_x", "thruster_y", "thruster_z"}));
  EXPECT_EQ(sc.mode("camera"), "ready");
  EXPECT_EQ(sc.mode("ips"), "standby");
  EXPECT_EQ(sc.mode("adcs"), "pointing");
  EXPECT_EQ(sc.mode("thruster_x"), "ok");
}

TEST(SpacecraftTest, ATurnTakesItsAngleOverTheModesRate) {
  Spacecraft sc(test_spec());
  ASSERT_TRUE(sc.submit(cmd("adcs", "turn", {"asteroid"})).accepted);
  EXPECT_EQ(sc.mode("adcs"), "turning");
  EXPECT_NEAR(sc.attitude().remaining_deg(), 90.0, 1e-9);
  run(sc, 449);  // 90 deg at 0.2 deg/s: 450 s
  EXPECT_EQ(sc.mode("adcs"), "turning");
  EXPECT_NEAR(sc.attitude().remaining_deg(), 0.2, 1e-6);
  EXPECT_NEAR(sc.attitude().last_rate_deg_s(), 0.2, 1e-9);
  run(sc, 1);
  EXPECT_EQ(sc.mode("adcs"), "pointing");
  EXPECT_EQ(sc.attitude().pointing_target(), "asteroid");
  EXPECT_NEAR(sc.attitude().pointing_error_deg(), 0.0, 1e-6);
  // A half turn about some perpendicular axis is still 180 / 0.2 = 900 s.
  ASSERT_TRUE(sc.submit(cmd("adcs", "turn", {"star"})).accepted);
  run(sc, 450);
  EXPECT_EQ(sc.attitude().pointing_target(), "star");
}

TEST(SpacecraftTest, CommandsAreRejectedWithTheirReasonsAndCounted) {
  Spacecraft sc(test_spec());
  const auto reason = [&](const Command& c) {
    const CommandResult r = sc.submit(c);
    EXPECT_FALSE(r.accepted) << c.device << " " << c.command;
    return r.reason;
  };
  EXPECT_EQ(
      reason(cmd("warp_drive", "engage")).rfind("unknown device 'warp_drive' (devices: adcs,", 0),
      0u);
  EXPECT_EQ(reason(cmd("camera", "fly")),
            "camera has no command 'fly' (commands: reset, power_on, off, take_image)");
  EXPECT_EQ(reason(cmd("camera", "take_image")), "camera take_image takes 1 argument(s), got 0");
  EXPECT_EQ(reason(cmd("camera", "take_image", {"moon"})), "unknown target 'moon'");
  EXPECT_EQ(reason(cmd("ips", "thrust", {"11"})), "thrust level '11' is out of range 1..10");
  EXPECT_EQ(reason(cmd("ips", "thrust", {"2.5"})), "thrust level '2.5' is out of range 1..10");
  EXPECT_EQ(reason(cmd("adcs", "set_mode", {"magic"})),
            "unknown control mode 'magic' (modes: thrusters, wheels_and_other_thrusters)");
  ASSERT_TRUE(sc.submit(cmd("camera", "off")).accepted);
  EXPECT_EQ(reason(cmd("camera", "take_image", {"star"})), "camera is off, not ready");
  ASSERT_TRUE(sc.submit(cmd("adcs", "turn", {"asteroid"})).accepted);
  EXPECT_EQ(reason(cmd("adcs", "turn", {"star"})), "adcs is turning to asteroid (90 deg left)");
  EXPECT_EQ(reason(cmd("telecom", "downlink")),
            "no ground station in view (next: goldstone at 100 s)");
  EXPECT_EQ(sc.commands_rejected(), 10u);
  EXPECT_EQ(sc.commands_accepted(), 2u);
  const msg::SpacecraftTelemetry t = sc.telemetry();
  EXPECT_EQ(t.commands_rejected, 10u);
  EXPECT_EQ(t.commands_accepted, 2u);
}

TEST(SpacecraftTest, AcceptedCommandsAreConfirmedInTelemetry) {
  Spacecraft sc(test_spec());
  EXPECT_EQ(report(sc.telemetry(), "ips").confirmed_tick, -1);
  run(sc, 3);
  ASSERT_TRUE(sc.submit(cmd("ips", "thrust", {"4"}, "cmd-7")).accepted);
  const msg::SpacecraftTelemetry t = sc.telemetry();
  const msg::DeviceReport& ips = report(t, "ips");
  EXPECT_EQ(ips.mode, "thrusting");
  EXPECT_EQ(ips.confirmed_command, "thrust");
  EXPECT_EQ(ips.confirmed_command_id, "cmd-7");
  EXPECT_EQ(ips.confirmed_tick, 3);
  EXPECT_EQ(t.propulsion.thrust_level, 4u);
  EXPECT_DOUBLE_EQ(t.propulsion.power_w, 1100.0);
}

TEST(SpacecraftTest, ImagesFillStorageAndDownlinkEmptiesItInTheWindow) {
  Spacecraft sc(test_spec());
  for (int i = 0; i < 5; ++i) {
    ASSERT_TRUE(sc.submit(cmd("camera", "take_image", {"star"})).accepted) << i;
    EXPECT_EQ(sc.mode("camera"), "imaging");
    run(sc, 5);  // the exposure
    EXPECT_EQ(sc.mode("camera"), "ready");
  }
  msg::SpacecraftTelemetry t = sc.telemetry();
  EXPECT_DOUBLE_EQ(t.storage.used_mb, 10.0);
  EXPECT_EQ(t.camera.images_taken, 5u);
  EXPECT_EQ(t.camera.images_on_target, 5u);
  EXPECT_EQ(sc.mode("storage"), "full");
  const CommandResult full = sc.submit(cmd("camera", "take_image", {"star"}));
  EXPECT_EQ(full.reason, "storage full: 10 of 10 MB used, an image needs 2 MB");

  run(sc, 75);  // t = 100: goldstone rises
  ASSERT_TRUE(sc.submit(cmd("telecom", "downlink")).accepted);
  run(sc, 50);
  t = sc.telemetry();
  EXPECT_NEAR(t.storage.used_mb, 9.5, 1e-9);  // 50 s at 0.01 MB/s
  EXPECT_NEAR(t.telecom.downlinked_mb, 0.5, 1e-9);
  EXPECT_EQ(t.telecom.ground_station, "goldstone");
  EXPECT_DOUBLE_EQ(t.telecom.downlink_rate_kbps, 80.0);
  run(sc, 60);  // the window closes at 200
  EXPECT_EQ(sc.mode("telecom"), "idle");
  EXPECT_NEAR(sc.telemetry().storage.used_mb, 9.0, 1e-9);
}

TEST(SpacecraftTest, ImagesTakenWhileTurningAreOffTarget) {
  Spacecraft sc(test_spec());
  ASSERT_TRUE(sc.submit(cmd("adcs", "turn", {"asteroid"})).accepted);
  ASSERT_TRUE(sc.submit(cmd("camera", "take_image", {"asteroid"})).accepted);
  run(sc, 5);
  EXPECT_EQ(sc.telemetry().camera.images_taken, 1u);
  EXPECT_EQ(sc.telemetry().camera.images_on_target, 0u);
}

TEST(SpacecraftTest, PowerBalanceChargesAndDrainsTheBattery) {
  Spacecraft sc(test_spec());
  // Idle: 300 base + 10 camera = 310 W of a 2000 W array: +1690 W charges 500 Wh to full.
  run(sc, 3600);
  EXPECT_NEAR(sc.telemetry().power.battery_wh, 1000.0, 1e-6);
  // Level 10 = 2300 W + 310 W = 2610 W: -610 W drains 610 Wh per hour.
  ASSERT_TRUE(sc.submit(cmd("ips", "thrust", {"10"})).accepted);
  EXPECT_DOUBLE_EQ(sc.telemetry().power.load_w, 2610.0);
  run(sc, 1800);
  EXPECT_NEAR(sc.telemetry().power.battery_wh, 1000.0 - 305.0, 1e-6);
  EXPECT_NEAR(*sc.reading("battery_soc"), 0.695, 1e-9);
  run(sc, 5000);  // empty after 4101 s: the load the array cannot carry is a deficit
  EXPECT_DOUBLE_EQ(sc.telemetry().power.battery_wh, 0.0);
  EXPECT_EQ(sc.mode("power"), "deficit");
  // Without the battery only the array's 2000 - 310 W are left for the engine.
  ASSERT_TRUE(sc.submit(cmd("ips", "standby")).accepted);
  EXPECT_EQ(sc.submit(cmd("ips", "thrust", {"9"})).reason,
            "thrust level 9 needs 2100 W, 1690 W available");
  EXPECT_FALSE(sc.submit(cmd("ips", "thrust", {"7"})).accepted);  // 1700 W
  EXPECT_TRUE(sc.submit(cmd("ips", "thrust", {"6"})).accepted);   // 1500 W
}

TEST(SpacecraftTest, OpenBusSwitchUnpowersItsDevice) {
  Spacecraft sc(test_spec());
  ASSERT_TRUE(sc.submit(cmd("power", "switch_off", {"camera_switch"})).accepted);
  EXPECT_EQ(sc.mode("camera"), "off");
  EXPECT_EQ(sc.submit(cmd("camera", "power_on")).reason,
            "camera is unpowered (its bus switch is open)");
  EXPECT_EQ(*sc.reading("camera_switch_status"), 0.0);
  EXPECT_EQ(*sc.reading("camera_switch_voltage_a"), 0.0);
  EXPECT_EQ(sc.submit(cmd("power", "switch_on", {"heater"})).reason,
            "unknown switch 'heater' (switches: camera_switch)");
  ASSERT_TRUE(sc.submit(cmd("power", "switch_on", {"camera_switch"})).accepted);
  EXPECT_TRUE(sc.submit(cmd("camera", "power_on")).accepted);
  EXPECT_EQ(sc.mode("camera"), "ready");
}

// --- Faults ---------------------------------------------------------------------------------

TEST(SpacecraftFaultTest, CameraStuckOnStaysImagingAfterItsPicture) {
  SpacecraftSpec spec = test_spec();
  spec.faults = {
      {"micas", FaultKind::StuckOn, "camera", 0, true, std::nullopt, "camera take_image"}};
  Spacecraft sc(spec);
  run(sc, 2);
  EXPECT_TRUE(sc.take_fault_events().empty());  // armed, waiting for the command
  ASSERT_TRUE(sc.submit(cmd("camera", "take_image", {"star"})).accepted);
  const auto events = sc.take_fault_events();
  ASSERT_EQ(events.size(), 1u);
  EXPECT_TRUE(events[0].active);
  EXPECT_EQ(events[0].trigger, "on camera take_image");
  run(sc, 20);
  EXPECT_EQ(sc.mode("camera"), "imaging");  // the picture is taken, the camera stays on
  EXPECT_EQ(sc.telemetry().camera.images_taken, 1u);
  EXPECT_DOUBLE_EQ(*sc.reading("camera_power_w"), 20.0);
  // "off" is carried out and confirmed, and the camera stays on: a stuck device, not a lost
  // command.
  ASSERT_TRUE(sc.submit(cmd("camera", "off", {}, "off-1")).accepted);
  run(sc, 1);
  EXPECT_EQ(sc.mode("camera"), "imaging");
  EXPECT_EQ(report(sc.telemetry(), "camera").confirmed_command_id, "off-1");
}

TEST(SpacecraftFaultTest, FailedElectronicsUnitIsCuredByAReset) {
  SpacecraftSpec spec = test_spec();
  spec.faults = {{"lpe-fail", FaultKind::Failed, "lpe", 0, true, 5.0, ""}};
  Spacecraft sc(spec);
  run(sc, 5);
  EXPECT_EQ(sc.mode("lpe"), "ok");
  run(sc, 1);  // the step from t = 5
  EXPECT_EQ(sc.mode("lpe"), "failed");
  EXPECT_EQ(sc.take_fault_events().at(0).trigger, "at 5 s");
  EXPECT_EQ(sc.submit(cmd("camera", "off")).reason,
            "commands to camera pass through lpe, which has failed");
  EXPECT_TRUE(sc.submit(cmd("ips", "thrust", {"1"})).accepted);  // not routed through the lpe
  ASSERT_TRUE(sc.submit(cmd("lpe", "reset", {}, "r1")).accepted);
  EXPECT_EQ(sc.mode("lpe"), "ok");
  const auto events = sc.take_fault_events();
  ASSERT_EQ(events.size(), 1u);
  EXPECT_FALSE(events[0].active);
  EXPECT_EQ(events[0].ended_by, "reset");
  EXPECT_TRUE(sc.submit(cmd("camera", "off")).accepted);
  EXPECT_EQ(report(sc.telemetry(), "lpe").confirmed_command, "reset");
}

TEST(SpacecraftFaultTest, AFailureNoResetCuresStaysAndRejectsCommands) {
  Spacecraft sc(test_spec());
  ASSERT_TRUE(
      sc.inject({"cam-dead", FaultKind::Failed, "camera", 0, false, std::nullopt, ""}).accepted);
  EXPECT_EQ(sc.mode("camera"), "failed");
  EXPECT_EQ(sc.submit(cmd("camera", "off")).reason, "camera has failed (reset it)");
  EXPECT_TRUE(sc.submit(cmd("camera", "reset")).accepted);
  EXPECT_EQ(sc.mode("camera"), "failed");
  EXPECT_TRUE(sc.clear_fault("cam-dead"));
  EXPECT_EQ(sc.mode("camera"), "ready");
  EXPECT_FALSE(sc.clear_fault("cam-dead"));
}

TEST(SpacecraftFaultTest, FalseSensorReadsWrongWhileTheRedundantReadingsStayTrue) {
  Spacecraft sc(test_spec());
  ASSERT_TRUE(sc.inject({"pwr", FaultKind::FalseSensor, "camera_switch_status", 0.0, true,
                         std::nullopt, ""})
                  .accepted);
  run(sc, 3);
  const msg::SpacecraftTelemetry t = sc.telemetry();
  EXPECT_EQ(reading(t, "camera_switch_status"), 0.0);     // says open
  EXPECT_EQ(reading(t, "camera_switch_voltage_a"), 1.0);  // the bus behind it is live
  EXPECT_EQ(reading(t, "camera_switch_voltage_b"), 1.0);
  EXPECT_EQ(report(t, "camera").mode, "ready");  // and the camera works
  EXPECT_TRUE(sc.submit(cmd("camera", "take_image", {"star"})).accepted);
  EXPECT_DOUBLE_EQ(reading(t, "camera_power_w"), 10.0);
}

TEST(SpacecraftFaultTest, ThrusterStuckClosedStopsTurnsUntilAModeWithoutIt) {
  Spacecraft sc(test_spec());
  ASSERT_TRUE(
      sc.inject({"tx", FaultKind::StuckClosed, "thruster_x", 0, true, std::nullopt, ""}).accepted);
  EXPECT_EQ(sc.mode("thruster_x"), "stuck_closed");
  ASSERT_TRUE(sc.submit(cmd("adcs", "turn", {"asteroid"})).accepted);
  run(sc, 100);
  EXPECT_NEAR(sc.attitude().remaining_deg(), 90.0, 1e-9);  // no progress
  EXPECT_EQ(*sc.reading("turn_rate_deg_s"), 0.0);
  ASSERT_TRUE(sc.submit(cmd("adcs", "set_mode", {"wheels_and_other_thrusters"})).accepted);
  run(sc, 899);  // 90 deg at 0.1 deg/s
  EXPECT_EQ(sc.mode("adcs"), "turning");
  run(sc, 1);
  EXPECT_EQ(sc.mode("adcs"), "pointing");
  EXPECT_EQ(sc.telemetry().attitude.control_mode, "wheels_and_other_thrusters");
}

TEST(SpacecraftFaultTest, IonEngineCommandsAreAcceptedButNeverConfirmed) {
  SpacecraftSpec spec = test_spec();
  spec.faults = {
      {"ips-silent", FaultKind::NeverConfirmed, "ips", 0, true, std::nullopt, "ips thrust"}};
  Spacecraft sc(spec);
  EXPECT_TRUE(sc.submit(cmd("ips", "thrust", {"3"}, "t1")).accepted);
  run(sc, 10);
  const msg::SpacecraftTelemetry t = sc.telemetry();
  EXPECT_EQ(report(t, "ips").mode, "standby");
  EXPECT_EQ(report(t, "ips").confirmed_tick, -1);
  EXPECT_EQ(t.propulsion.thrust_time_s, 0.0);
  EXPECT_TRUE(sc.submit(cmd("camera", "off", {}, "c1")).accepted);  // the rest still works
  EXPECT_EQ(report(sc.telemetry(), "camera").confirmed_command_id, "c1");
}

TEST(SpacecraftFaultTest, IonEngineStuckOnKeepsThrusting) {
  Spacecraft sc(test_spec());
  ASSERT_TRUE(sc.inject({"ips-on", FaultKind::StuckOn, "ips", 0, true, std::nullopt, ""}).accepted);
  ASSERT_TRUE(sc.submit(cmd("ips", "thrust", {"2"})).accepted);
  ASSERT_TRUE(sc.submit(cmd("ips", "standby")).accepted);
  run(sc, 10);
  EXPECT_EQ(sc.mode("ips"), "thrusting");
  EXPECT_DOUBLE_EQ(sc.telemetry().propulsion.thrust_time_s, 10.0);
}

TEST(SpacecraftFaultTest, FaultsThatDoNotFitTheSpacecraftAreRejected) {
  Spacecraft sc(test_spec());
  const auto reason = [&](FaultSpec f) { return sc.inject(std::move(f)).reason; };
  EXPECT_EQ(reason({"a", FaultKind::StuckOn, "adcs", 0, true, std::nullopt, ""}),
            "stuck_on fault 'a': subject must be camera or ips, not 'adcs'");
  EXPECT_EQ(reason({"b", FaultKind::StuckClosed, "camera", 0, true, std::nullopt, ""}),
            "stuck_closed fault 'b': 'camera' is not a thruster (thrusters: thruster_x, "
            "thruster_y, thruster_z)");
  EXPECT_EQ(reason({"c", FaultKind::FalseSensor, "moon_sensor", 0, true, std::nullopt, ""}),
            "false_sensor fault 'c': unknown reading 'moon_sensor'");
  EXPECT_EQ(reason({"d", FaultKind::Failed, "warp", 0, true, std::nullopt, ""})
                .rfind("failed fault 'd': unknown device 'warp'", 0),
            0u);
  EXPECT_EQ(reason({"", FaultKind::Failed, "lpe", 0, true, std::nullopt, ""}), "fault id is empty");
  ASSERT_TRUE(sc.inject({"e", FaultKind::Failed, "lpe", 0, true, std::nullopt, ""}).accepted);
  EXPECT_EQ(reason({"e", FaultKind::Failed, "ips", 0, true, std::nullopt, ""}),
            "fault id 'e' is already in use");
  SpacecraftSpec bad = test_spec();
  bad.faults = {{"f", FaultKind::StuckClosed, "thruster_q", 0, true, 1.0, ""}};
  EXPECT_THROW(Spacecraft{bad}, std::invalid_argument);
}

}  // namespace
}  // namespace autonomy::sim::spacecraft
