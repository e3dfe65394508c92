// The C <-> C++ conversions of idl/spacecraft.idl: every field, nested blocks and sequences.
#include "common/dds/message_types.hpp"

#include <gtest/gtest.h>

namespace autonomy::dds {
namespace {

template <typename T>
T spacecraft_round_trip(const T& value) {
  typename DdsType<T>::C c{};
  Arena arena;
  DdsType<T>::to_c(value, c, arena);
  return DdsType<T>::from_c(c);
}

TEST(SpacecraftConversionsTest, CommandAndStatusRoundTrip) {
  const msg::SpacecraftCommand c{"c-1",    "executive",  42,
                                 "camera", "take_image", {"asteroid-1", "raw"}};
  const msg::SpacecraftCommand back = spacecraft_round_trip(c);
  EXPECT_EQ(back.command_id, "c-1");
  EXPECT_EQ(back.source, "executive");
  EXPECT_EQ(back.tick, 42);
  EXPECT_EQ(back.device, "camera");
  EXPECT_EQ(back.command, "take_image");
  EXPECT_EQ(back.arguments, (std::vector<std::string>{"asteroid-1", "raw"}));
  EXPECT_TRUE(spacecraft_round_trip(msg::SpacecraftCommand{}).arguments.empty());

  const msg::SpacecraftCommandStatus s{"c-1", "executive",     "camera", "take_image",
                                       false, "camera is off", 42,       7};
  const msg::SpacecraftCommandStatus sb = spacecraft_round_trip(s);
  EXPECT_EQ(sb.command_id, "c-1");
  EXPECT_EQ(sb.source, "executive");
  EXPECT_EQ(sb.device, "camera");
  EXPECT_EQ(sb.command, "take_image");
  EXPECT_FALSE(sb.accepted);
  EXPECT_EQ(sb.reason, "camera is off");
  EXPECT_EQ(sb.tick, 42);
  EXPECT_EQ(sb.sim_time_ns, 7);
  EXPECT_FALSE(sb.busy);
  msg::SpacecraftCommandStatus busy = s;
  busy.busy = true;
  EXPECT_TRUE(spacecraft_round_trip(busy).busy);
}

TEST(SpacecraftConversionsTest, FaultProtectionAndEventRoundTrip) {
  msg::SpacecraftTelemetry t;
  t.fault_protection = {true, "no command or heartbeat of executive for 600 s", 600'000'000'000,
                        2, 601.5, 600.0};
  t.commands_busy = 17;
  const msg::SpacecraftTelemetry b = spacecraft_round_trip(t);
  EXPECT_TRUE(b.fault_protection.safe_mode);
  EXPECT_EQ(b.fault_protection.reason, "no command or heartbeat of executive for 600 s");
  EXPECT_EQ(b.fault_protection.safed_at_ns, 600'000'000'000);
  EXPECT_EQ(b.fault_protection.safings, 2u);
  EXPECT_DOUBLE_EQ(b.fault_protection.commander_silent_s, 601.5);
  EXPECT_DOUBLE_EQ(b.fault_protection.commander_timeout_s, 600.0);
  EXPECT_EQ(b.commands_busy, 17u);

  const msg::SpacecraftEvent e{"ds1", 601, 600'000'000'000, "safed", "ips to standby"};
  const msg::SpacecraftEvent eb = spacecraft_round_trip(e);
  EXPECT_EQ(eb.spacecraft, "ds1");
  EXPECT_EQ(eb.tick, 601);
  EXPECT_EQ(eb.sim_time_ns, 600'000'000'000);
  EXPECT_EQ(eb.kind, "safed");
  EXPECT_EQ(eb.detail, "ips to standby");
}

TEST(SpacecraftConversionsTest, TelemetryRoundTrip) {
  msg::SpacecraftTelemetry t;
  t.spacecraft = "ds1";
  t.tick = 3;
  t.sim_time_ns = 3000000000;
  t.devices = {{"adcs", "turning", "turn", "t-1", 2}, {"ips", "standby", "", "", -1}};
  t.readings = {{"battery_soc", 0.75}, {"camera_switch_status", 1.0}};
  t.attitude = {0.5, 0.5, 0.5, 0.5, "", "asteroid-1", "thrusters", 0.2, 12.5};
  t.propulsion = {6, 1271.4, 30.0};
  t.camera = {25.0, 4, 3, "asteroid-2"};
  t.power = {2500, 1800, 0.75, 502.5};
  t.telecom = {"dss-14", 20.0, 1.5};
  t.storage = {5.0, 64.0};
  t.commands_accepted = 9;
  t.commands_rejected = 2;
  const msg::SpacecraftTelemetry b = spacecraft_round_trip(t);
  EXPECT_EQ(b.spacecraft, "ds1");
  EXPECT_EQ(b.tick, 3);
  EXPECT_EQ(b.sim_time_ns, 3000000000);
  ASSERT_EQ(b.devices.size(), 2u);
  EXPECT_EQ(b.devices[0].device, "adcs");
  EXPECT_EQ(b.devices[0].mode, "turning");
  EXPECT_EQ(b.devices[0].confirmed_command, "turn");
  EXPECT_EQ(b.devices[0].confirmed_command_id, "t-1");
  EXPECT_EQ(b.devices[0].confirmed_tick, 2);
  EXPECT_EQ(b.devices[1].confirmed_tick, -1);
  ASSERT_EQ(b.readings.size(), 2u);
  EXPECT_EQ(b.readings[1].sensor, "camera_switch_status");
  EXPECT_DOUBLE_EQ(b.readings[0].value, 0.75);
  EXPECT_DOUBLE_EQ(b.attitude.qx, 0.5);
  EXPECT_EQ(b.attitude.turn_target, "asteroid-1");
  EXPECT_EQ(b.attitude.control_mode, "thrusters");
  EXPECT_DOUBLE_EQ(b.attitude.remaining_deg, 12.5);
  EXPECT_EQ(b.propulsion.thrust_level, 6u);
  EXPECT_DOUBLE_EQ(b.propulsion.thrust_time_s, 30.0);
  EXPECT_EQ(b.camera.images_on_target, 3u);
  EXPECT_EQ(b.camera.last_image_target, "asteroid-2");
  EXPECT_DOUBLE_EQ(b.power.battery_wh, 502.5);
  EXPECT_EQ(b.telecom.ground_station, "dss-14");
  EXPECT_DOUBLE_EQ(b.storage.capacity_mb, 64.0);
  EXPECT_EQ(b.commands_accepted, 9u);
  EXPECT_EQ(b.commands_rejected, 2u);
}

TEST(SpacecraftConversionsTest, FaultInjectionAndStateRoundTrip) {
  const msg::SpacecraftFaultInjection f{"f-1", "test", "false_sensor", "camera_switch_status", 0.25,
                                        false, true};
  const auto fb = spacecraft_round_trip(f);
  EXPECT_EQ(fb.fault_id, "f-1");
  EXPECT_EQ(fb.source, "test");
  EXPECT_EQ(fb.kind, "false_sensor");
  EXPECT_EQ(fb.subject, "camera_switch_status");
  EXPECT_DOUBLE_EQ(fb.value, 0.25);
  EXPECT_FALSE(fb.reset_cures);
  EXPECT_TRUE(fb.clear);
  const msg::SpacecraftFaultState s{"f-1", "failed", "lpe", 0.0, false, "at 7200 s", "reset", 99};
  const auto sb = spacecraft_round_trip(s);
  EXPECT_EQ(sb.fault_id, "f-1");
  EXPECT_EQ(sb.kind, "failed");
  EXPECT_EQ(sb.subject, "lpe");
  EXPECT_FALSE(sb.active);
  EXPECT_EQ(sb.trigger, "at 7200 s");
  EXPECT_EQ(sb.ended_by, "reset");
  EXPECT_EQ(sb.since_ns, 99);
}

}  // namespace
}  // namespace autonomy::dds
