// Integration tests of the simulated spacecraft over DDS: the real simulator process with
// deploy/scenarios/ds1.pbtxt, this test as a lockstep participant sending device commands on
// autonomy/spacecraft/command and reading telemetry, command status and fault truth.
//
//   domain  test
//   ------  -----------------------------------------------------------
//    200    SpacecraftTest.LockstepCommandsAreConfirmedInTelemetry
//    201    SpacecraftTest.BadCommandsAreRejectedWithTheirReasons
//    202    SpacecraftTest.InjectedFaultsShowInTelemetryAndTruth
//    203    SpacecraftTest.ScenarioFaultOnACommandInPacedTime
//    204    SpacecraftTest.BadSpacecraftSectionStopsTheSimulatorWithItsPosition
// (ctest names them integration.<suite>.<test>.)
#include "tests/support/process_test.hpp"
#include "tests/support/spacecraft_driver.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace autonomy::test {
namespace {

enum Domain : int {
  kDomainConfirmed = 200,
  kDomainRejected = 201,
  kDomainInjected = 202,
  kDomainPaced = 203,
  kDomainBadFile = 204,
};

const std::string kDs1 = std::string(AUTONOMY_SOURCE_DIR) + "/deploy/scenarios/ds1.pbtxt";
constexpr const char* kName = "test";  // this test's lockstep participant name (the driver's)

class SpacecraftTest : public ProcessTest {
 protected:
  void start_ds1(int domain, const std::string& scenario = kDs1,
                 std::vector<std::string> extra = {}) {
    join(domain);
    std::vector<std::string> args{"--config", scenario, "--wait-for", kName};
    args.insert(args.end(), extra.begin(), extra.end());
    start_simulator(args);
  }
  // Polls the driver and the recorders until `condition` holds.
  ::testing::AssertionResult run_until(const std::string& what, LockstepDriver& driver,
                                       const std::function<bool()>& condition) {
    return await(what, [&] {
      driver.poll();
      telemetry_->poll();
      status_->poll();
      return condition();
    });
  }
  void record() {
    telemetry_.emplace(participant(), dds::topics::spacecraft_telemetry);
    status_.emplace(participant(), dds::topics::spacecraft_command_status);
  }
  std::optional<Recorder<msg::SpacecraftTelemetry>> telemetry_;
  std::optional<Recorder<msg::SpacecraftCommandStatus>> status_;
};

TEST_F(SpacecraftTest, LockstepCommandsAreConfirmedInTelemetry) {
  start_ds1(kDomainConfirmed);
  record();
  LockstepDriver driver(participant());
  ASSERT_TRUE(driver.join());
  ASSERT_TRUE(run_until("tick 0", driver, [&] { return driver.poll().has_value(); }));
  driver.send("turn-1", "adcs", "turn", {"braille"});

  // Confirmed at the tick it was sent for, seen in the next tick's telemetry, turning.
  ASSERT_TRUE(run_until("turn-1 confirmed", driver, [&] {
    return !!first(*telemetry_, [](const auto& t) {
      return device(t, "adcs")->confirmed_command_id == "turn-1";
    });
  }));
  const int64_t k0 = driver.sent_at("turn-1");
  const auto confirmed = *first(*telemetry_, [](const auto& t) {
    return device(t, "adcs")->confirmed_command_id == "turn-1";
  });
  EXPECT_EQ(confirmed.tick, k0 + 1);
  EXPECT_EQ(device(confirmed, "adcs")->confirmed_tick, k0);
  EXPECT_EQ(device(confirmed, "adcs")->mode, "turning");
  EXPECT_EQ(confirmed.attitude.turn_target, "braille");
  ASSERT_TRUE(status_of(*status_, "turn-1"));
  EXPECT_TRUE(status_of(*status_, "turn-1")->accepted);
  EXPECT_EQ(status_of(*status_, "turn-1")->tick, k0);

  // 41.03 deg (earth to braille) at 0.5 deg/s: 83 one-second steps.
  ASSERT_TRUE(run_until("pointing at braille", driver, [&] {
    return !!first(*telemetry_,
                   [](const auto& t) { return t.attitude.pointing_target == "braille"; });
  }));
  const auto pointed =
      *first(*telemetry_, [](const auto& t) { return t.attitude.pointing_target == "braille"; });
  EXPECT_EQ(pointed.tick - k0, 83);
  EXPECT_EQ(device(pointed, "adcs")->mode, "pointing");
  EXPECT_LT(*reading(pointed, "pointing_error_deg"), 1e-6);

  driver.send("img-1", "camera", "take_image", {"braille"});
  ASSERT_TRUE(run_until("image on target", driver, [&] {
    return !!first(*telemetry_, [](const auto& t) { return t.camera.images_on_target == 1; });
  }));
  const auto imaged =
      *first(*telemetry_, [](const auto& t) { return t.camera.images_on_target == 1; });
  EXPECT_EQ(imaged.tick - driver.sent_at("img-1"), 20);  // the exposure
  EXPECT_DOUBLE_EQ(imaged.storage.used_mb, 5.0);         // 4 MB at the start + 1
  EXPECT_EQ(device(imaged, "camera")->mode, "ready");
  EXPECT_EQ(imaged.commands_rejected, 0u);
}

TEST_F(SpacecraftTest, BadCommandsAreRejectedWithTheirReasons) {
  start_ds1(kDomainRejected);
  record();
  LockstepDriver driver(participant());
  ASSERT_TRUE(driver.join());
  ASSERT_TRUE(run_until("tick 0", driver, [&] { return driver.poll().has_value(); }));
  driver.send("bad-device", "warp_drive", "engage");
  driver.send("bad-target", "camera", "take_image", {"moon"});
  driver.send("bad-level", "ips", "thrust", {"99"});
  driver.send("bad-mode", "telecom", "downlink");  // no station in view at t = 0
  driver.send("good", "ips", "thrust", {"5"});
  ASSERT_TRUE(run_until("five statuses", driver, [&] { return status_->all().size() >= 5; }));
  const auto reason = [&](const std::string& id) {
    const auto s = status_of(*status_, id);
    EXPECT_TRUE(s && !s->accepted) << id;
    return s ? s->reason : "";
  };
  EXPECT_EQ(reason("bad-device")
                .rfind("unknown device 'warp_drive' (devices: adcs, camera, ips, lpe,", 0),
            0u);
  EXPECT_EQ(reason("bad-target"), "unknown target 'moon'");
  EXPECT_EQ(reason("bad-level"), "thrust level '99' is out of range 1..15");
  EXPECT_EQ(reason("bad-mode"), "no ground station in view (next: dsn-1 at 4800 s)");
  ASSERT_TRUE(status_of(*status_, "good"));
  EXPECT_TRUE(status_of(*status_, "good")->accepted);
  ASSERT_TRUE(run_until("counts in telemetry", driver, [&] {
    return !!first(*telemetry_, [](const auto& t) {
      return t.commands_rejected == 4 && t.commands_accepted == 1;
    });
  }));
  const auto t = *first(*telemetry_, [](const auto& t) { return t.commands_rejected == 4; });
  EXPECT_EQ(device(t, "ips")->mode, "thrusting");
  EXPECT_EQ(t.propulsion.thrust_level, 5u);
}

TEST_F(SpacecraftTest, InjectedFaultsShowInTelemetryAndTruth) {
  start_ds1(kDomainInjected);
  record();
  Recorder<msg::SpacecraftFaultState> truth(participant(), dds::topics::truth_spacecraft_fault);
  dds::Topic<msg::SpacecraftFaultInjection> inject_topic(participant(),
                                                         dds::topics::spacecraft_fault_injection);
  dds::Writer<msg::SpacecraftFaultInjection> inject(participant(), inject_topic);
  LockstepDriver driver(participant());
  ASSERT_TRUE(driver.join());
  ASSERT_TRUE(inject.wait_for_readers(1, kDeadline));
  ASSERT_TRUE(run_until("tick 0", driver, [&] { return driver.poll().has_value(); }));
  inject.write({"tx", "test", "stuck_closed", "thruster_x", 0, true, false});
  inject.write({"pwr", "test", "false_sensor", "camera_switch_status", 0, true, false});
  inject.write({"lpe", "test", "failed", "lpe", 0, true, false});
  inject.write({"boom", "test", "explode", "camera", 0, true, false});

  ASSERT_TRUE(run_until("faults in telemetry", driver, [&] {
    truth.poll();
    return !!first(*telemetry_, [](const auto& t) {
      return device(t, "thruster_x")->mode == "stuck_closed" &&
             device(t, "lpe")->mode == "failed" && reading(t, "camera_switch_status") == 0.0;
    });
  }));
  const auto t =
      *first(*telemetry_, [](const auto& t) { return device(t, "lpe")->mode == "failed"; });
  EXPECT_EQ(reading(t, "camera_switch_voltage_a"), 1.0);  // the redundant readings stay true
  EXPECT_EQ(reading(t, "camera_switch_voltage_b"), 1.0);
  EXPECT_EQ(device(t, "camera")->mode, "ready");
  EXPECT_EQ(device(t, "thruster_y")->mode, "ok");
  ASSERT_TRUE(status_of(*status_, "boom"));
  EXPECT_FALSE(status_of(*status_, "boom")->accepted);
  EXPECT_EQ(status_of(*status_, "boom")->reason,
            "unknown fault kind 'explode' (stuck_on, failed, false_sensor, stuck_closed, "
            "never_confirmed)");

  // The failed unit refuses what passes through it until a reset cures it.
  driver.send("cam-1", "camera", "off");
  driver.send("reset-1", "lpe", "reset");
  ASSERT_TRUE(run_until("lpe reset", driver, [&] {
    truth.poll();
    return !!first(*telemetry_, [](const auto& t) {
      return device(t, "lpe")->confirmed_command_id == "reset-1";
    });
  }));
  EXPECT_EQ(status_of(*status_, "cam-1")->reason,
            "commands to camera pass through lpe, which has failed");
  const auto reset = *first(*telemetry_, [](const auto& t) {
    return device(t, "lpe")->confirmed_command_id == "reset-1";
  });
  EXPECT_EQ(device(reset, "lpe")->mode, "ok");
  ASSERT_TRUE(await("fault truth", [&] {
    truth.poll();
    return !truth.matching([](const auto& f) { return f.fault_id == "lpe" && !f.active; }).empty();
  }));
  const auto ended =
      truth.matching([](const auto& f) { return f.fault_id == "lpe" && !f.active; }).front();
  EXPECT_EQ(ended.ended_by, "reset");
  const auto tx = truth.matching([](const auto& f) { return f.fault_id == "tx"; });
  ASSERT_FALSE(tx.empty());
  EXPECT_TRUE(tx.front().active);
  EXPECT_EQ(tx.front().trigger, "injected by test");
}

TEST_F(SpacecraftTest, ScenarioFaultOnACommandInPacedTime) {
  join(kDomainPaced);
  // ds1 with its ion-engine fault switched on, run paced at 50x by a sender outside lockstep.
  std::string text = read_file(kDs1);
  const std::string fault = "# faults { id: \"ips-unconfirmed\"";
  const std::string clock =
      "simulation { mode: LOCKSTEP step_s: 1.0 seed: 1999 ack_timeout_s: 30.0 }";
  ASSERT_NE(text.find(fault), std::string::npos);
  ASSERT_NE(text.find(clock), std::string::npos);
  text.replace(text.find(fault), 2, "");
  text.replace(text.find(clock), clock.size(), "simulation { mode: PACED step_s: 1.0 warp: 50 }");
  const std::string file = dir().file("ds1-ips.pbtxt");
  write_file(file, text);
  start_simulator({"--config", file});
  record();
  Recorder<msg::SpacecraftFaultState> truth(participant(), dds::topics::truth_spacecraft_fault);
  dds::Topic<msg::SpacecraftCommand> topic(participant(), dds::topics::spacecraft_command);
  dds::Writer<msg::SpacecraftCommand> commands(participant(), topic);
  ASSERT_TRUE(commands.wait_for_readers(1, kDeadline));
  commands.write({"thrust-1", "tool", 0, "ips", "thrust", {"6"}});
  ASSERT_TRUE(await("thrust-1 accepted", [&] {
    status_->poll();
    return status_of(*status_, "thrust-1").has_value();
  }));
  const auto accepted = *status_of(*status_, "thrust-1");
  EXPECT_TRUE(accepted.accepted) << accepted.reason;
  commands.write({"cam-1", "tool", 0, "camera", "off", {}});
  // Twenty ticks later the engine still has not done it; the camera did.
  ASSERT_TRUE(await("20 ticks after the thrust", [&] {
    telemetry_->poll();
    return !!first(*telemetry_, [&](const auto& t) { return t.tick >= accepted.tick + 20; });
  }));
  const auto later =
      *first(*telemetry_, [&](const auto& t) { return t.tick >= accepted.tick + 20; });
  EXPECT_EQ(device(later, "ips")->mode, "standby");
  EXPECT_EQ(device(later, "ips")->confirmed_tick, -1);
  EXPECT_EQ(device(later, "camera")->confirmed_command_id, "cam-1");
  EXPECT_EQ(device(later, "camera")->mode, "off");
  ASSERT_TRUE(await("fault truth", [&] {
    truth.poll();
    return !truth.all().empty();
  }));
  EXPECT_EQ(truth.all()[0].fault_id, "ips-unconfirmed");
  EXPECT_EQ(truth.all()[0].trigger, "on ips thrust");
  // Paced: the clock ran without anyone acknowledging it.
  EXPECT_GE(later.tick, 20);
}

TEST_F(SpacecraftTest, BadSpacecraftSectionStopsTheSimulatorWithItsPosition) {
  join(kDomainBadFile);
  std::string text = read_file(kDs1);
  const std::string target = "initial_target: \"earth\"";
  ASSERT_NE(text.find(target), std::string::npos);
  text.replace(text.find(target), target.size(), "initial_target: \"pluto\"");
  const std::string file = dir().file("bad-ds1.pbtxt");
  write_file(file, text);
  ChildProcess& sim = start_simulator({"--config", file}, false);
  ASSERT_TRUE(await("simulator ended", [&] { return !sim.running(); }));
  ASSERT_TRUE(sim.status()->exited);
  EXPECT_NE(sim.status()->code, 0);
  const std::string out = read_file(sim.log_file());
  EXPECT_NE(out.find(file + ":31:5: attitude: initial_target 'pluto' is not a target"),
            std::string::npos)
      << out;
}

}  // namespace
}  // namespace autonomy::test
