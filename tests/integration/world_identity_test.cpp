// Issue 22 without DDS Security: one world per domain, and no stray or forged sample breaks a
// mission. Real processes over Cyclone DDS on loopback; every outcome is polled for.
//
// One DDS domain per test (ctest runs them in parallel); this file uses 110-115:
//
//   domain  test
//   ------  -----------------------------------------------------------
//    110    WorldIdentityTest.SecondSimulatorOnTheDomainRefusesAndNamesTheFirst
//    111    WorldIdentityTest.ForgedClockSamplesAreIgnoredCountedAndTheRunFinishes
//    112    WorldIdentityTest.TelemetryOfAnotherSpacecraftDoesNotReachTheExecutive
//    113    WorldIdentityTest.LauncherDoesNotTakeAnotherSetsProcessForItsOwn
//    114    WorldIdentityTest.GoalForARobotNobodyDrivesGetsAnAnswer
//    115    WorldIdentityTest.NodeListFlagsEveryProcessOfADuplicatedName
//    116    WorldIdentityTest.TwoWorldsThatStartedTogetherReportEachOther
#include "common/service/heartbeat.hpp"
#include "tests/support/executive_watch.hpp"
#include "tests/support/process_test.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <limits>
#include <string>
#include <vector>

namespace autonomy::test {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

class WorldIdentityTest : public ProcessTest {
 protected:
  // The newest heartbeat of the process with this pid whose field satisfies `pred`.
  ::testing::AssertionResult await_beat(Recorder<msg::Heartbeat>& beats, pid_t pid, const std::string& what,
                                        const std::function<bool(const msg::Heartbeat&)>& pred,
                                        msg::Heartbeat* out = nullptr) {
    return await(what, [&] {
      beats.poll();
      for (const auto& b : beats.matching([&](const msg::Heartbeat& h) { return h.pid == pid; }))
        if (pred(b)) {
          if (out) *out = b;
          return true;
        }
      return false;
    });
  }

  // `autonomy ARGS --domain D` to its end: exit code, stderr in `err`.
  int cli(const std::string& name, std::vector<std::string> args, std::string& err) {
    args.insert(args.end(), {"--domain", std::to_string(domain_)});
    auto& c = start(name, AUTONOMY_AUTONOMY_BIN, args, false, true);
    const auto status = c.wait_for_exit(kDeadline);
    err = read_file(c.stderr_file());
    if (!status || !status->exited) return -1;
    return status->code;
  }
};

// Two simulators on one domain used to run side by side, their robots' states alternating. The
// second one now listens first, hears the first world, and refuses with its host, pid, scenario.
TEST_F(WorldIdentityTest, SecondSimulatorOnTheDomainRefusesAndNamesTheFirst) {
  join(110);
  Recorder<msg::Heartbeat> beats(participant(), dds::topics::heartbeat);
  auto& first = start_simulator({"--mode", "paced"});
  msg::Heartbeat first_beat;
  ASSERT_TRUE(await_beat(beats, first.pid(), "the first simulator runs a world", [](const msg::Heartbeat& b) {
    return b.world_id != 0 && b.state == msg::ServiceState::Ready;
  }, &first_beat));
  EXPECT_EQ(first_beat.detail, "builtin:demo.pbtxt");

  const std::string scenario = std::string(AUTONOMY_SOURCE_DIR) + "/deploy/scenarios/field.pbtxt";
  auto& second = start_simulator({"--config", scenario, "--world-check", "1"}, false, "simulator-2");
  const auto ended = second.wait_for_exit(kDeadline);
  ASSERT_TRUE(ended.has_value()) << "the second simulator still runs";
  EXPECT_TRUE(ended->exited && ended->code == 1) << ended->describe();
  const std::string out = read_file(second.log_file());
  EXPECT_TRUE(contains(out, "another world runs on DDS domain 110: simulator on host " + service::host_name() +
                                ", pid " + std::to_string(first.pid()) + ", scenario builtin:demo.pbtxt (world " +
                                std::to_string(first_beat.world_id) + ")"))
      << out;
  // It never published a world of its own.
  beats.poll();
  EXPECT_TRUE(beats.matching([&](const msg::Heartbeat& h) { return h.pid == second.pid() && h.world_id != 0; })
                  .empty());
  EXPECT_TRUE(first.running());
}

// The forged sample of issue 22 (tick 2^63-1) froze every later tick of a service; a clock of
// another world was followed as readily as its own. Both are now ignored with a warning and
// counted in the heartbeat, and the run goes on to its end (the simulator stops when r1 reached
// its goal: --stop-when-finished).
TEST_F(WorldIdentityTest, ForgedClockSamplesAreIgnoredCountedAndTheRunFinishes) {
  join(111);
  Recorder<msg::Heartbeat> beats(participant(), dds::topics::heartbeat);
  Recorder<msg::GoalStatus> goals(participant(), dds::topics::goal_status);
  dds::Topic<msg::SimClock> clock_topic(participant(), dds::topics::clock);
  dds::Writer<msg::SimClock> forger(participant(), clock_topic);
  dds::Topic<msg::NavGoal> goal_topic(participant(), dds::topics::nav_goal);
  dds::Writer<msg::NavGoal> goal_writer(participant(), goal_topic);

  // No --max-ticks: an idle lockstep world races through quiet ticks (millions a second) and
  // would reach any modest end before the goal is sent.
  auto& sim = start_simulator({"--wait-for", "behavior/r1", "--stop-when-finished"}, false);
  auto& r1 = start_behavior("r1");
  msg::Heartbeat joined;
  ASSERT_TRUE(await_beat(beats, r1.pid(), "r1 joined a world", [](const msg::Heartbeat& b) {
    return b.world_id != 0 && b.state == msg::ServiceState::Ready;
  }, &joined));

  // One at a time: the clock is a keep-last state topic, a second forged sample could replace
  // the first before it is read.
  constexpr int64_t kMax = std::numeric_limits<int64_t>::max();
  forger.write({kMax, kMax, 1, msg::ClockMode::Lockstep, 1.0, joined.world_id});
  ASSERT_TRUE(await_beat(beats, r1.pid(), "r1 counts the forged tick 2^63-1",
                         [](const msg::Heartbeat& b) { return b.clock_samples_ignored >= 1; }));
  forger.write({1, 100'000'000, 100'000'000, msg::ClockMode::Lockstep, 1.0, joined.world_id ^ 0x5a5a5a5aULL});
  ASSERT_TRUE(await_beat(beats, r1.pid(), "r1 counts another world's clock",
                         [](const msg::Heartbeat& b) { return b.clock_samples_ignored >= 2; }));

  ASSERT_TRUE(goal_writer.wait_for_readers(1, kDeadline));
  goal_writer.write({"r1", "after-forgery", 18.0, 2.0, 0.0, ""});
  const auto ended = sim.wait_for_exit(60s);
  ASSERT_TRUE(ended.has_value()) << "the run did not finish";
  EXPECT_TRUE(ended->exited && ended->code == 0) << ended->describe();
  ASSERT_TRUE(await("r1's goal reached", [&] {
    goals.poll();
    return !goals.matching([](const msg::GoalStatus& s) {
                   return s.goal_id == "after-forgery" && s.state == msg::GoalState::Reached;
                 })
                .empty();
  }));
  const std::string log = read_file(dir().file("behavior-r1.log"));
  EXPECT_TRUE(contains(log, "clock sample ignored (1 so far): tick 9223372036854775807")) << log;
  EXPECT_TRUE(contains(log, "belongs to another world than the one joined")) << log;
  // Still in the world it joined first.
  beats.poll();
  EXPECT_EQ(beats.matching([&](const msg::Heartbeat& h) { return h.pid == r1.pid(); }).back().world_id,
            joined.world_id);
}

// Telemetry of another spacecraft on the domain used to be mixed into DS1's (the real unit was
// reset twice and given up). Here every DS1 telemetry sample is echoed as spacecraft "intruder"
// with its electronics unit lpe failed, from the moment the first plan executes: the executive,
// started without --spacecraft, follows the spacecraft it heard first (ds1), flies the four hours
// with no fault response and every goal achieved, and says what it ignored. (ds1.set passes
// --spacecraft ds1, which leaves nothing to chance.)
TEST_F(WorldIdentityTest, TelemetryOfAnotherSpacecraftDoesNotReachTheExecutive) {
  join(112);
  ExecutiveWatch watch(participant());
  Recorder<msg::SpacecraftTelemetry> telemetry(participant(), dds::topics::spacecraft_telemetry);
  dds::Topic<msg::SpacecraftTelemetry> telemetry_topic(participant(), dds::topics::spacecraft_telemetry);
  dds::Writer<msg::SpacecraftTelemetry> intruder(participant(), telemetry_topic);
  const std::string source = AUTONOMY_SOURCE_DIR;
  start("planner", AUTONOMY_PLANNER_BIN, {"--domain", std::to_string(domain_), "--log-dir", dir().path()});
  start("executive", AUTONOMY_EXECUTIVE_BIN,
        {"--config", source + "/services/executive/examples/ds1-4h.pbtxt", "--domain",
         std::to_string(domain_), "--log-dir", dir().path(), "--report-dir", dir().file("report")});
  start_simulator({"--config", source + "/deploy/scenarios/ds1.pbtxt", "--wait-for", "executive/main"});

  size_t echoed = 0;
  ASSERT_TRUE(await("the executive finished the four hours", [&] {
    watch.poll();
    for (msg::SpacecraftTelemetry t : telemetry.poll()) {
      if (t.spacecraft != "ds1" || watch.events("plan_executing").empty()) continue;
      t.spacecraft = "intruder";
      for (auto& d : t.devices)
        if (d.device == "lpe") d.mode = "failed";
      intruder.write(t);
      ++echoed;
    }
    return watch.finished();
  }, 120s)) << watch.story(false);
  EXPECT_GT(echoed, 0u);
  EXPECT_TRUE(watch.events("fault reset").empty()) << watch.story(false);
  EXPECT_TRUE(watch.events("aborted").empty()) << watch.story(false);
  EXPECT_EQ(watch.achieved().size(), 16u) << watch.story(false);
  EXPECT_TRUE(watch.lost().empty()) << watch.story(false);
  const std::string log = read_file(dir().file("executive-main.log"));
  EXPECT_TRUE(contains(log, "telemetry of spacecraft 'intruder' ignored (1 so far): this executive commands 'ds1'"))
      << log.substr(0, 4000);
}

// Two simulators that start within one listen window both start (neither runs a world yet); the
// race is made certain here with --world-check 0 for the second. Each then hears the other's
// clock: an error in its log, a count in its heartbeat, and `autonomy node list` says that the
// processes follow two worlds.
TEST_F(WorldIdentityTest, TwoWorldsThatStartedTogetherReportEachOther) {
  join(116);
  Recorder<msg::Heartbeat> beats(participant(), dds::topics::heartbeat);
  auto& first = start_simulator({"--mode", "paced"});
  msg::Heartbeat first_beat, second_beat;
  ASSERT_TRUE(await_beat(beats, first.pid(), "the first simulator runs a world",
                         [](const msg::Heartbeat& b) { return b.world_id != 0; }, &first_beat));
  auto& second = start_simulator({"--mode", "paced", "--world-check", "0"}, true, "simulator-2");
  ASSERT_TRUE(await_beat(beats, second.pid(), "the second simulator runs a world",
                         [](const msg::Heartbeat& b) { return b.world_id != 0; }, &second_beat));
  ASSERT_NE(first_beat.world_id, second_beat.world_id);
  for (auto* sim : {&first, &second})
    EXPECT_TRUE(await_beat(beats, sim->pid(), sim->name() + " counts the other world's clock",
                           [](const msg::Heartbeat& b) { return b.clock_samples_ignored > 0; }));
  const std::string first_log = read_file(first.log_file());
  EXPECT_TRUE(contains(first_log, "a clock of world " + std::to_string(second_beat.world_id))) << first_log;
  std::string err;
  EXPECT_EQ(cli("list", {"node", "list"}, err), 0) << err;
  EXPECT_TRUE(contains(err, "processes follow 2 worlds on domain 116")) << err;
}

// A launcher waits for its own child, by pid: a ready process of the same name from another set
// on the domain (here started first, by hand) is reported, not taken for it.
TEST_F(WorldIdentityTest, LauncherDoesNotTakeAnotherSetsProcessForItsOwn) {
  join(113);
  Recorder<msg::Heartbeat> beats(participant(), dds::topics::heartbeat);
  auto& other = start("other-set-twin", AUTONOMY_FAKE_SERVICE_BIN,
                      {"--instance", "twin", "--domain", std::to_string(domain_), "--log-dir", dir().path()});
  ASSERT_TRUE(await_ready(beats, other));

  const std::string set = dir().file("mine.set");
  write_file(set, "fake/twin  fake_service --instance twin --ready-after 2\n");
  const std::string run = dir().file("run");
  const std::string bin = fs::path(AUTONOMY_AUTONOMY_BIN).parent_path().string();
  auto& launcher = start("launcher", "/bin/bash",
                         {std::string(AUTONOMY_SOURCE_DIR) + "/deploy/launch.sh", "--domain", std::to_string(domain_),
                          "--bin", bin, "--run-dir", run, "--timeout", "30", set},
                         false);
  ASSERT_TRUE(await("the launcher says the set is ready",
                    [&] { return contains(read_file(launcher.log_file()), "launch: set 'mine' ready"); }));
  const std::string own_pid = read_file(run + "/fake-twin.pid");
  ASSERT_FALSE(own_pid.empty());
  const std::string out = read_file(launcher.log_file());
  EXPECT_TRUE(contains(out, "fake/twin ready (pid " + std::to_string(std::stol(own_pid)) + " ")) << out;
  EXPECT_FALSE(contains(out, "fake/twin ready (pid " + std::to_string(other.pid()) + " ")) << out;
  EXPECT_TRUE(contains(out, "fake/twin (pid " + std::to_string(other.pid()) + " on ")) << out;
  EXPECT_TRUE(contains(out, "is not the process awaited")) << out;
  // The other set's process is left alone.
  EXPECT_TRUE(other.running());
  launcher.kill_and_wait();
  ::kill(static_cast<pid_t>(std::stol(own_pid)), SIGKILL);
}

// A goal for a robot that no behavior drives used to vanish: no status ever came. The CLI now
// answers (exit 1, the robots that are served) and publishes nothing; a served robot's goal
// goes through as before.
TEST_F(WorldIdentityTest, GoalForARobotNobodyDrivesGetsAnAnswer) {
  join(114);
  Recorder<msg::Heartbeat> beats(participant(), dds::topics::heartbeat);
  Recorder<msg::GoalStatus> goals(participant(), dds::topics::goal_status);
  start_simulator({"--mode", "paced"});
  auto& r1 = start_behavior("r1");
  ASSERT_TRUE(await_ready(beats, r1));

  std::string err;
  EXPECT_EQ(cli("pub-ghost", {"topic", "pub", "autonomy/nav/goal", R"({"robot_id":"ghost","goal_id":"g-ghost","x":3,"y":3})",
                              "--wait", "2"},
                err),
            1)
      << err;
  EXPECT_TRUE(contains(err, "no behavior process serves robot \"ghost\" on domain 114 (behavior runs for: r1)"))
      << err;
  EXPECT_EQ(cli("pub-r1", {"topic", "pub", "autonomy/nav/goal", R"({"robot_id":"r1","goal_id":"g-r1","x":3,"y":3})"},
                err),
            0)
      << err;
  ASSERT_TRUE(await("r1 answers its goal", [&] {
    goals.poll();
    return !goals.matching([](const msg::GoalStatus& s) { return s.goal_id == "g-r1"; }).empty();
  }));
  goals.poll();
  EXPECT_TRUE(goals.matching([](const msg::GoalStatus& s) { return s.goal_id == "g-ghost"; }).empty());
}

// `autonomy node list` shows every process of a name and flags each of them as a duplicate.
TEST_F(WorldIdentityTest, NodeListFlagsEveryProcessOfADuplicatedName) {
  join(115);
  Recorder<msg::Heartbeat> beats(participant(), dds::topics::heartbeat);
  auto fake = [&](const std::string& name, const std::string& instance) -> ChildProcess& {
    return start(name, AUTONOMY_FAKE_SERVICE_BIN,
                 {"--instance", instance, "--domain", std::to_string(domain_), "--log-dir", dir().path()});
  };
  auto& a = fake("twin-a", "twin");
  auto& b = fake("twin-b", "twin");
  auto& single = fake("single", "single");
  for (auto* c : {&a, &b, &single}) ASSERT_TRUE(await_ready(beats, *c));

  std::string err;
  auto& list = start("list", AUTONOMY_AUTONOMY_BIN, {"node", "list", "--json", "--domain", std::to_string(domain_)},
                     false, true);
  const auto status = list.wait_for_exit(kDeadline);
  ASSERT_TRUE(status && status->exited && status->code == 0) << list.log_tail();
  const auto rows = nlohmann::json::parse(read_file(list.log_file()), nullptr, false);
  ASSERT_TRUE(rows.is_array()) << read_file(list.log_file());
  std::map<pid_t, bool> duplicate;
  for (const auto& r : rows) duplicate[r.value("pid", 0)] = r.value("duplicate", false);
  ASSERT_EQ(duplicate.size(), 3u) << rows.dump();
  EXPECT_TRUE(duplicate[a.pid()]) << rows.dump();
  EXPECT_TRUE(duplicate[b.pid()]) << rows.dump();
  EXPECT_FALSE(duplicate[single.pid()]) << rows.dump();

  auto& text = start("list-text", AUTONOMY_AUTONOMY_BIN, {"node", "list", "--domain", std::to_string(domain_)}, false);
  ASSERT_TRUE(text.wait_for_exit(kDeadline));
  const std::string table = read_file(text.log_file());
  size_t flagged = 0;
  for (size_t at = table.find("DUPLICATE"); at != std::string::npos; at = table.find("DUPLICATE", at + 1)) ++flagged;
  EXPECT_EQ(flagged, 2u) << table;
}

}  // namespace
}  // namespace autonomy::test
