// Issue 23 for the simulated spacecraft, with the real simulator process and
// deploy/scenarios/ds1.pbtxt: fault protection safes the spacecraft when its commander goes silent
// and a command or heartbeat brings it back; no command vanishes (a burst of 3000 gets 3000
// statuses); a malformed command is rejected with its reason and still counted by the lockstep
// barrier, so its tick does not wait for it. Progress is asserted by ticks, not by wall time.
//
//   domain  test
//   ------  -----------------------------------------------------------
//    230    SpacecraftProtectionTest.SilentCommanderSafesTheSpacecraftAndCommandsAreAcceptedAgain
//    231    SpacecraftProtectionTest.ABurstOf3000CommandsGets3000Statuses
//    232    SpacecraftProtectionTest.OversizedCommandsAreRejectedAndTheirTickDoesNotStall
// (ctest names them integration.<suite>.<test>.)
#include "tests/support/process_test.hpp"
#include "tests/support/spacecraft_driver.hpp"

#include <gtest/gtest.h>

#include <set>

namespace autonomy::test {
namespace {

enum Domain : int {
  kDomainSafing = 230,
  kDomainBurst = 231,
  kDomainOversized = 232,
};

const std::string kDs1 = std::string(AUTONOMY_SOURCE_DIR) + "/deploy/scenarios/ds1.pbtxt";

class SpacecraftProtectionTest : public ProcessTest {
 protected:
  // ds1 with `extra` added to its spacecraft section, in lockstep waiting for the driver.
  void start_ds1(int domain, const std::string& extra = "") {
    join(domain);
    std::string text = read_file(kDs1);
    const std::string head = "spacecraft {\n  name: \"ds1\"\n";
    ASSERT_NE(text.find(head), std::string::npos);
    text.insert(text.find(head) + head.size(), extra);
    const std::string file = dir().file("ds1.pbtxt");
    write_file(file, text);
    start_simulator({"--config", file, "--wait-for", "test"});
    telemetry_.emplace(participant(), dds::topics::spacecraft_telemetry);
    status_.emplace(participant(), dds::topics::spacecraft_command_status);
    events_.emplace(participant(), dds::topics::spacecraft_event);
  }
  ::testing::AssertionResult run_until(const std::string& what, LockstepDriver& driver,
                                       const std::function<bool()>& condition) {
    return await(what, [&] {
      driver.poll();
      telemetry_->poll();
      status_->poll();
      events_->poll();
      return condition();
    });
  }
  std::optional<msg::SpacecraftTelemetry> at_tick(int64_t tick) const {
    return first(*telemetry_, [&](const auto& t) { return t.tick >= tick; });
  }
  std::optional<Recorder<msg::SpacecraftTelemetry>> telemetry_;
  std::optional<Recorder<msg::SpacecraftCommandStatus>> status_;
  std::optional<Recorder<msg::SpacecraftEvent>> events_;
};

TEST_F(SpacecraftProtectionTest, SilentCommanderSafesTheSpacecraftAndCommandsAreAcceptedAgain) {
  start_ds1(kDomainSafing, "  fault_protection { commander_timeout_s: 30 }\n");
  // The test is the commander here (its commands count), but not by name: its acks do not.
  LockstepDriver driver(participant());
  ASSERT_TRUE(driver.join());
  ASSERT_TRUE(run_until("tick 0", driver, [&] { return driver.poll().has_value(); }));
  driver.send("thrust-1", "ips", "thrust", {"5"});
  driver.send("turn-1", "adcs", "turn", {"braille"});
  ASSERT_TRUE(run_until("thrusting", driver, [&] {
    return !!first(*telemetry_, [](const auto& t) { return device(t, "ips")->mode == "thrusting"; });
  }));
  const int64_t k0 = driver.sent_at("thrust-1");

  // 30 s of silence (1 s ticks): safed at the step of tick k0 + 30, seen at k0 + 31.
  ASSERT_TRUE(run_until("safe mode", driver, [&] {
    return !!first(*telemetry_, [](const auto& t) { return t.fault_protection.safe_mode; });
  }));
  const auto safed = *first(*telemetry_, [](const auto& t) { return t.fault_protection.safe_mode; });
  EXPECT_EQ(safed.tick, k0 + 31);
  EXPECT_EQ(safed.fault_protection.safed_at_ns, (k0 + 30) * 1'000'000'000);
  EXPECT_EQ(safed.fault_protection.reason, "no command or heartbeat of executive for 30 s");
  EXPECT_EQ(safed.fault_protection.safings, 1u);
  EXPECT_EQ(device(safed, "ips")->mode, "standby");
  EXPECT_EQ(device(safed, "camera")->mode, "off");
  EXPECT_EQ(device(safed, "adcs")->mode, "pointing");  // the turn to braille held where it was
  EXPECT_EQ(safed.attitude.pointing_target, "");
  const auto before = at_tick(k0 + 30);
  ASSERT_TRUE(before);
  EXPECT_FALSE(before->fault_protection.safe_mode);
  EXPECT_EQ(device(*before, "ips")->mode, "thrusting");
  ASSERT_TRUE(run_until("safed event", driver, [&] { return !events_->all().empty(); }));
  EXPECT_EQ(events_->all()[0].kind, "safed");
  EXPECT_EQ(events_->all()[0].tick, k0 + 31);
  EXPECT_EQ(events_->all()[0].detail,
            "no command or heartbeat of executive for 30 s: ips to standby, camera off, turn to "
            "braille stopped, attitude held");

  // A heartbeat of the executive brings it back.
  dds::Topic<msg::Heartbeat> beat_topic(participant(), dds::topics::heartbeat);
  dds::Writer<msg::Heartbeat> beat(participant(), beat_topic);
  ASSERT_TRUE(beat.wait_for_readers(1, kDeadline));
  beat.write({"executive", "it", "localhost", 1, msg::ServiceState::Ready, 1.0, 500, {}});
  ASSERT_TRUE(run_until("resumed by the heartbeat", driver, [&] {
    return events_->all().size() >= 2 &&
           !!first(*telemetry_, [&](const auto& t) {
             return t.tick > safed.tick && !t.fault_protection.safe_mode;
           });
  }));
  EXPECT_EQ(events_->all()[1].kind, "resumed");
  EXPECT_EQ(events_->all()[1].detail, "safe mode ended by heartbeat of executive/it");
  const int64_t resumed = events_->all()[1].tick;

  // Silent again (the heartbeat was a single one): safed a second time 30 ticks later.
  ASSERT_TRUE(run_until("safed again", driver, [&] {
    return !!first(*telemetry_, [](const auto& t) { return t.fault_protection.safings == 2; });
  }));
  const auto again = *first(*telemetry_, [](const auto& t) { return t.fault_protection.safings == 2; });
  EXPECT_EQ(again.tick, resumed + 30);
  EXPECT_TRUE(again.fault_protection.safe_mode);

  // A command is accepted and carried out: safe mode ends with it.
  driver.send("thrust-2", "ips", "thrust", {"3"});
  ASSERT_TRUE(run_until("thrust-2 confirmed", driver, [&] {
    return !!first(*telemetry_, [](const auto& t) {
      return device(t, "ips")->confirmed_command_id == "thrust-2";
    });
  }));
  ASSERT_TRUE(status_of(*status_, "thrust-2"));
  EXPECT_TRUE(status_of(*status_, "thrust-2")->accepted) << status_of(*status_, "thrust-2")->reason;
  const auto flying = *first(*telemetry_, [](const auto& t) {
    return device(t, "ips")->confirmed_command_id == "thrust-2";
  });
  EXPECT_FALSE(flying.fault_protection.safe_mode);
  EXPECT_EQ(device(flying, "ips")->mode, "thrusting");
  EXPECT_EQ(flying.propulsion.thrust_level, 3u);
  ASSERT_TRUE(run_until("resumed event", driver, [&] { return events_->all().size() >= 4; }));
  EXPECT_EQ(events_->all()[3].detail, "safe mode ended by command thrust-2 from test");
}

TEST_F(SpacecraftProtectionTest, ABurstOf3000CommandsGets3000Statuses) {
  start_ds1(kDomainBurst);
  LockstepDriver driver(participant());
  ASSERT_TRUE(driver.join());
  ASSERT_TRUE(run_until("tick 0", driver, [&] { return driver.poll().has_value(); }));
  // Back to back in one tick, announced in its ack: a third accepted, a third rejected by the
  // spacecraft, a third malformed; the queue (1000 by default) turns the rest away busy.
  constexpr int kBurst = 3000;
  for (int i = 0; i < kBurst; ++i) {
    const std::string id = "c-" + std::to_string(i);
    if (i % 3 == 0)
      driver.send(id, "camera", "power_on");
    else if (i % 3 == 1)
      driver.send(id, "warp_drive", "engage");
    else
      driver.send(id, "camera", "take_image", {std::string(100, 'x')});
  }
  ASSERT_TRUE(run_until("3000 statuses", driver, [&] {
    return status_->all().size() >= static_cast<size_t>(kBurst);
  }));
  const int64_t k = driver.sent_at("c-0");
  std::set<std::string> ids;
  int accepted = 0, rejected = 0, busy = 0;
  for (const auto& s : status_->all()) {
    ids.insert(s.command_id);
    if (s.accepted) ++accepted;
    else if (s.busy) ++busy;
    else ++rejected;
  }
  EXPECT_EQ(ids.size(), static_cast<size_t>(kBurst));  // one status each, none twice
  EXPECT_EQ(accepted + rejected + busy, kBurst);
  // The malformed third is answered on arrival and never queued; of the 2000 others, the first
  // 1000 to arrive are queued and the rest are busy.
  EXPECT_EQ(busy, 1000);
  EXPECT_EQ(accepted + rejected, 2000);
  EXPECT_EQ(accepted, 500);  // arrival keeps the writer's order: c-0 .. c-2998 less the malformed
  for (const auto& s : status_->all())
    if (s.busy) {
      EXPECT_EQ(s.reason,
                "busy: 1000 commands are waiting for their step (limit 1000), send it again later");
      break;
    }
  const auto oversized = *status_of(*status_, "c-2");
  EXPECT_FALSE(oversized.accepted);
  EXPECT_EQ(oversized.reason, "argument has 100 bytes, more than 64");
  std::printf("burst of %d: %d accepted, %d rejected, %d busy\n", kBurst, accepted, rejected, busy);

  // The tick the burst was announced for completed: the world goes on, counting every command.
  ASSERT_TRUE(run_until("five ticks later", driver, [&] { return !!at_tick(k + 5); }));
  const auto after = *at_tick(k + 1);
  EXPECT_EQ(after.tick, k + 1);
  EXPECT_EQ(after.commands_accepted + after.commands_rejected, static_cast<uint64_t>(kBurst));
  EXPECT_EQ(after.commands_busy, 1000u);
  EXPECT_EQ(after.commands_accepted, static_cast<uint64_t>(accepted));
}

TEST_F(SpacecraftProtectionTest, OversizedCommandsAreRejectedAndTheirTickDoesNotStall) {
  start_ds1(kDomainOversized);
  Recorder<msg::CommandRejection> rejections(participant(), dds::topics::command_rejected);
  Recorder<msg::SimulatorStatus> sim_status(participant(), dds::topics::sim_status);
  dds::Topic<msg::VelocityCommand> cmd_topic(participant(), dds::topics::cmd_vel);
  dds::Writer<msg::VelocityCommand> cmd_vel(participant(), cmd_topic);
  LockstepDriver driver(participant());
  ASSERT_TRUE(driver.join());
  ASSERT_TRUE(cmd_vel.wait_for_readers(1, kDeadline));
  ASSERT_TRUE(run_until("tick 0", driver, [&] { return driver.poll().has_value(); }));

  // One tick's commands: a plan parameter of 100 KB, a velocity command for a robot whose name
  // is 100 KB long, and a good command; the ack announces all three.
  const std::string huge(100 * 1024, 'p');
  std::optional<int64_t> bad_tick;
  driver.also_send = [&](int64_t tick) -> uint32_t {
    if (bad_tick) return 0;
    bad_tick = tick;
    cmd_vel.write({huge, "test", tick, 0.1, 0.0, 0.0});
    return 1;
  };
  driver.send("param", "adcs", "turn", {huge});
  driver.send("good", "camera", "off");
  ASSERT_TRUE(run_until("both statuses", driver, [&] {
    return status_of(*status_, "param") && status_of(*status_, "good");
  }));
  EXPECT_FALSE(status_of(*status_, "param")->accepted);
  EXPECT_EQ(status_of(*status_, "param")->reason, "argument has 102400 bytes, more than 64");
  EXPECT_TRUE(status_of(*status_, "good")->accepted);
  ASSERT_TRUE(bad_tick);
  EXPECT_EQ(status_of(*status_, "param")->tick, *bad_tick);

  // The tick went on with the test still in step: ten more ticks, nobody dropped. (Had the
  // rejected ones not been counted, the barrier would wait for them until ack_timeout_s, 30 s in
  // ds1, and drop this participant.)
  ASSERT_TRUE(run_until("ten ticks later", driver, [&] {
    rejections.poll();
    return !!at_tick(*bad_tick + 10) && !rejections.all().empty();
  }));
  EXPECT_EQ(rejections.all()[0].reason, "robot_id has 102400 bytes, more than 64");
  EXPECT_EQ(rejections.all()[0].tick, *bad_tick);
  ASSERT_TRUE(await("simulator status", [&] {
    sim_status.poll();
    return !sim_status.matching([&](const auto& s) { return s.tick >= *bad_tick + 10; }).empty();
  }));
  const auto status = sim_status.matching([&](const auto& s) { return s.tick >= *bad_tick + 10; }).back();
  EXPECT_EQ(status.participants_dropped, 0u);
  EXPECT_EQ(status.lockstep_participants, std::vector<std::string>{"test"});
  EXPECT_EQ(device(*at_tick(*bad_tick + 1), "camera")->confirmed_command_id, "good");
}

}  // namespace
}  // namespace autonomy::test
