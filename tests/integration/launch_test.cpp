// Integration tests of deploy/launch.sh: the real script starting the real simulator and behavior
// (--bin: the build's bin folder) over Cyclone DDS on loopback, a second launch.sh as "another
// terminal", kill -9 as a crash; every outcome is polled for with a deadline.
//
// One DDS domain per test (ctest runs them in parallel); this file uses 150-159 and 185-186:
//
//   domain  test
//   ------  -----------------------------------------------------------
//    150    LaunchTest.StopFromAnotherTerminalEndsTheForegroundLauncher
//    151    LaunchTest.KilledProcessIsReportedAndRespawned
//    152    LaunchTest.KilledProcessUnderPolicyStopStopsTheSet
//    153    LaunchTest.RespawnGivesUpAfterItsMaximum
//    154    LaunchTest.IgnoredExitIsReportedAndTheRestGoesOn
//    155    LaunchTest.DetachedSetIsSupervisedAndStoppedFromAnotherTerminal
//    156    LaunchTest.SetFileMistakesAreReportedAtFileLineBeforeAnythingStarts
//    157    LaunchTest.HungProcessIsReportedWithItsLastLinesAndRespawned
//    158    LaunchTest.ProcessResumedBeforeItsHangLimitIsLeftAlone
//    159    LaunchTest.HungProcessUnderPolicyStopStopsTheSet
//    185    LaunchTest.NodeListShowsAStoppedProcessAsStaleAndIgnoreOnlyReportsIt
//    186    LaunchTest.NodeListShowsEveryProcessOfOneName
#include "tests/support/process_test.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace autonomy::test {
namespace {

namespace fs = std::filesystem;

// The build's bin folder, where launch.sh finds the programs of a set and the autonomy CLI.
std::string bin_dir() {
  return fs::path(AUTONOMY_AUTONOMY_BIN).parent_path().string();
}
std::string launch_script() {
  return std::string(AUTONOMY_SOURCE_DIR) + "/deploy/launch.sh";
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// Alive and not a zombie (an ended child of a launcher that has not collected it yet).
bool process_running(pid_t pid) {
  if (pid <= 0) return false;
  const std::string stat = read_file("/proc/" + std::to_string(pid) + "/stat");
  const auto paren = stat.rfind(')');
  if (paren == std::string::npos || paren + 2 >= stat.size()) return false;
  const char state = stat[paren + 2];
  return state != 'Z' && state != 'X';
}

class LaunchTest : public ProcessTest {
 protected:
  void TearDown() override {
    // The launchers first (no respawn while their sets are cleared), then whatever a pid file of
    // the run still names: the detached launcher and the set's processes, checked to be ours.
    for (auto* l : launchers_) l->kill_and_wait();
    if (!run_.empty()) {
      for (const char* file :
           {"launch.pid", "simulator-main.pid", "behavior-r1.pid", "behavior-r9.pid"}) {
        const pid_t pid = pid_in(file);
        if (pid <= 0) continue;
        std::error_code ec;
        const auto exe = fs::read_symlink("/proc/" + std::to_string(pid) + "/exe", ec).string();
        const auto cmdline = read_file("/proc/" + std::to_string(pid) + "/cmdline");
        if (contains(exe, bin_dir()) || contains(cmdline, "launch.sh")) ::kill(pid, SIGKILL);
      }
    }
    ProcessTest::TearDown();
  }

  // The set file `text` in the test's folder; the run folder is the test's too.
  std::string write_set(const std::string& name, const std::string& text) {
    const std::string path = dir().file(name + ".set");
    write_file(path, text);
    run_ = dir().file("run");
    return path;
  }

  // launch.sh [extra...] SET_FILE with this test's domain, bin and run folders. must_keep_running:
  // await() fails at once if the launcher ends (until stop_watching).
  ChildProcess& launch(const std::string& set_file, std::vector<std::string> extra = {},
                       const std::string& name = "launcher", bool must_keep_running = false) {
    std::vector<std::string> args = {
        launch_script(), "--domain", std::to_string(domain_), "--bin", bin_dir(), "--run-dir", run_,
        "--timeout",     "30"};
    args.insert(args.end(), extra.begin(), extra.end());
    args.push_back(set_file);
    auto& l = start(name, "/bin/bash", args, must_keep_running);
    launchers_.push_back(&l);
    return l;
  }
  ChildProcess& stop_from_another_terminal() {
    return start("stop", "/bin/bash", {launch_script(), "stop", run_}, false);
  }

  pid_t pid_in(const std::string& file) const {
    const std::string text = read_file(run_ + "/" + file);
    return text.empty() ? 0 : static_cast<pid_t>(std::stol(text));
  }

  ::testing::AssertionResult await_text(const std::string& file, const std::string& part) {
    return await(file + " says \"" + part + "\"", [&] { return contains(read_file(file), part); });
  }
  ::testing::AssertionResult await_ended(ChildProcess& child, int code) {
    const auto status = child.wait_for_exit(kDeadline);
    if (!status) return ::testing::AssertionFailure() << child.name() << " still runs";
    if (!status->exited || status->code != code)
      return ::testing::AssertionFailure() << child.name() << " ended with " << status->describe()
                                           << ", expected exit code " << code << "; its output:\n"
                                           << child.log_tail();
    return ::testing::AssertionSuccess();
  }
  ::testing::AssertionResult await_gone(pid_t pid, const std::string& what) {
    return await(what + " (pid " + std::to_string(pid) + ") ended",
                 [&] { return !process_running(pid); });
  }
  // A new pid in NAME.pid, other than `old`, whose heartbeat says ready (0 when none came).
  pid_t await_respawned_ready(Recorder<msg::Heartbeat>& beats, const std::string& file, pid_t old) {
    pid_t fresh = 0;
    const auto respawned = await(file + " names a new process", [&] {
      fresh = pid_in(file);
      return fresh > 0 && fresh != old;
    });
    EXPECT_TRUE(respawned);
    if (!respawned) return 0;
    EXPECT_TRUE(await(
        "heartbeat of the respawned process (pid " + std::to_string(fresh) + ") says ready", [&] {
          beats.poll();
          return !beats
                      .matching([&](const msg::Heartbeat& h) {
                        return h.pid == fresh && h.state == msg::ServiceState::Ready;
                      })
                      .empty();
        }));
    return fresh;
  }

  // `autonomy node list --json` on this test's domain: its rows, or a failure with its output.
  ::testing::AssertionResult node_list(nlohmann::json& rows, const std::string& name = "node-list") {
    auto& cli = start(name, AUTONOMY_AUTONOMY_BIN, {"node", "list", "--json", "--domain", std::to_string(domain_)},
                      false, true);
    const auto status = cli.wait_for_exit(kDeadline);
    if (!status || !status->exited || status->code != 0)
      return ::testing::AssertionFailure() << "autonomy node list did not succeed: " << cli.log_tail();
    rows = nlohmann::json::parse(read_file(cli.log_file()), nullptr, false);
    if (!rows.is_array()) return ::testing::AssertionFailure() << "not a JSON array: " << read_file(cli.log_file());
    return ::testing::AssertionSuccess();
  }
  // The row of `node list --json` for this pid (null when none).
  static nlohmann::json row_of(const nlohmann::json& rows, pid_t pid) {
    for (const auto& r : rows)
      if (r.value("pid", 0) == pid) return r;
    return nullptr;
  }

  std::string run_;

 private:
  std::vector<ChildProcess*> launchers_;
};

constexpr const char* kSimulatorLine = "simulator/main  simulator --mode paced\n";

// The user's case: launch.sh SET in one terminal, launch.sh stop RUN_DIR in another. The stop
// returns once the foreground launcher has stopped the set and ended (cleanly, exit code 0).
TEST_F(LaunchTest, StopFromAnotherTerminalEndsTheForegroundLauncher) {
  join(150);
  const auto set =
      write_set("pair", std::string(kSimulatorLine) + "behavior/r1  behavior --robot r1\n");
  auto& launcher = launch(set, {}, "launcher", true);
  ASSERT_TRUE(await_text(launcher.log_file(), "launch: set 'pair' ready on domain 150"));
  const pid_t simulator = pid_in("simulator-main.pid"), behavior = pid_in("behavior-r1.pid");
  ASSERT_GT(simulator, 0);
  ASSERT_GT(behavior, 0);
  EXPECT_EQ(pid_in("launch.pid"), launcher.pid());

  stop_watching(launcher);
  auto& stop = stop_from_another_terminal();
  // The stopping side waits for the launcher: reap it meanwhile, as its terminal's shell would.
  ASSERT_TRUE(await("the stop command ends", [&] {
    launcher.running();
    return !stop.running();
  }));
  ASSERT_TRUE(stop.status()->exited);
  EXPECT_EQ(stop.status()->code, 0) << stop.log_tail();
  EXPECT_TRUE(contains(read_file(stop.log_file()), "has ended")) << stop.log_tail();
  ASSERT_TRUE(await_ended(launcher, 0));
  const std::string out = read_file(launcher.log_file());
  EXPECT_TRUE(contains(out, "launch: SIGTERM: stopping the set")) << out;
  EXPECT_TRUE(contains(out, "launch: stopped the set in " + run_)) << out;
  EXPECT_FALSE(process_running(simulator));
  EXPECT_FALSE(process_running(behavior));
  EXPECT_FALSE(fs::exists(run_ + "/behavior-r1.pid"));
  EXPECT_FALSE(fs::exists(run_ + "/launch.pid"));
}

// kill -9 of a process under on-exit=respawn: reported with its signal and its last output,
// started again (new pid file) and ready again, the rest of the set untouched; Ctrl-C then stops
// everything.
TEST_F(LaunchTest, KilledProcessIsReportedAndRespawned) {
  join(151);
  Recorder<msg::Heartbeat> beats(participant(), dds::topics::heartbeat);
  const auto set = write_set(
      "respawn", std::string(kSimulatorLine) +
                     "behavior/r1  on-exit=respawn:max=3:backoff=0.2  behavior --robot r1\n");
  auto& launcher = launch(set, {}, "launcher", true);
  ASSERT_TRUE(await_text(launcher.log_file(), "ready on domain 151"));
  const pid_t simulator = pid_in("simulator-main.pid"), first = pid_in("behavior-r1.pid");
  ASSERT_GT(first, 0);

  ASSERT_EQ(::kill(first, SIGKILL), 0);
  ASSERT_TRUE(await_text(launcher.log_file(), "launch: behavior/r1 (pid " + std::to_string(first) +
                                                  ") ended: killed by SIGKILL"));
  ASSERT_TRUE(await_text(launcher.log_file(),
                         "launch: behavior/r1: respawning in 0.2 s (respawn 1 of at most 3)"));
  const pid_t second = await_respawned_ready(beats, "behavior-r1.pid", first);
  // The launcher's own readiness check (autonomy node wait) names the new process.
  ASSERT_TRUE(await_text(launcher.log_file(), "behavior/r1 ready (pid " + std::to_string(second)));

  const std::string out = read_file(launcher.log_file());
  // The report quotes the dead process's output: its own last log lines.
  const auto report = out.find("killed by SIGKILL");
  const auto quoted = out.find("  | ", report);
  ASSERT_NE(quoted, std::string::npos) << out;
  EXPECT_TRUE(contains(out.substr(quoted, out.find('\n', quoted) - quoted), "[behavior/r1]"))
      << out;
  EXPECT_TRUE(contains(out, "launch: started behavior/r1 (pid " + std::to_string(second) + ")"))
      << out;
  EXPECT_FALSE(contains(out, "stopping the set")) << out;
  EXPECT_EQ(pid_in("simulator-main.pid"), simulator);
  EXPECT_TRUE(process_running(simulator));
  EXPECT_TRUE(launcher.running());

  stop_watching(launcher);
  launcher.signal(SIGINT);  // Ctrl-C
  ASSERT_TRUE(await_ended(launcher, 0));
  EXPECT_TRUE(contains(read_file(launcher.log_file()), "launch: SIGINT: stopping the set"));
  EXPECT_FALSE(process_running(second));
  EXPECT_FALSE(process_running(simulator));
}

// The default policy (stop): the killed process is reported and the whole set stops, the
// launcher ending with exit code 1.
TEST_F(LaunchTest, KilledProcessUnderPolicyStopStopsTheSet) {
  join(152);
  const auto set = write_set(
      "stop", std::string(kSimulatorLine) + "behavior/r1  on-exit=stop  behavior --robot r1\n");
  auto& launcher = launch(set);
  ASSERT_TRUE(await_text(launcher.log_file(), "ready on domain 152"));
  const pid_t simulator = pid_in("simulator-main.pid"), behavior = pid_in("behavior-r1.pid");

  ASSERT_EQ(::kill(behavior, SIGKILL), 0);
  ASSERT_TRUE(await_ended(launcher, 1));
  const std::string out = read_file(launcher.log_file());
  EXPECT_TRUE(contains(
      out, "launch: behavior/r1 (pid " + std::to_string(behavior) + ") ended: killed by SIGKILL"))
      << out;
  EXPECT_TRUE(contains(out, "launch: behavior/r1: on-exit=stop, stopping the set")) << out;
  EXPECT_FALSE(contains(out, "respawning")) << out;
  EXPECT_FALSE(process_running(simulator));
  EXPECT_FALSE(fs::exists(run_ + "/simulator-main.pid"));
}

// respawn:max=1: the first crash is respawned, the second stops the set.
TEST_F(LaunchTest, RespawnGivesUpAfterItsMaximum) {
  join(153);
  Recorder<msg::Heartbeat> beats(participant(), dds::topics::heartbeat);
  const auto set = write_set(
      "once", std::string(kSimulatorLine) +
                  "behavior/r1  on-exit=respawn:max=1:backoff=0.1  behavior --robot r1\n");
  auto& launcher = launch(set);
  ASSERT_TRUE(await_text(launcher.log_file(), "ready on domain 153"));
  const pid_t simulator = pid_in("simulator-main.pid"), first = pid_in("behavior-r1.pid");

  ASSERT_EQ(::kill(first, SIGKILL), 0);
  const pid_t second = await_respawned_ready(beats, "behavior-r1.pid", first);
  ASSERT_GT(second, 0);
  ASSERT_EQ(::kill(second, SIGKILL), 0);
  ASSERT_TRUE(await_ended(launcher, 1));
  const std::string out = read_file(launcher.log_file());
  EXPECT_TRUE(contains(
      out, "launch: behavior/r1 (pid " + std::to_string(second) + ") ended: killed by SIGKILL"))
      << out;
  EXPECT_TRUE(
      contains(out, "launch: behavior/r1: no respawn left (max=1 reached), stopping the set"))
      << out;
  EXPECT_FALSE(contains(out, "respawn 2 of")) << out;
  EXPECT_FALSE(process_running(simulator));
}

// on-exit=ignore: a process that exits by itself (bad argument: CLI11's exit code 109) is
// reported with its exit code and output, the set becomes ready without it and keeps running
// until stopped (then exit code 0: the launcher did not stop on its own).
TEST_F(LaunchTest, IgnoredExitIsReportedAndTheRestGoesOn) {
  join(154);
  const auto set = write_set(
      "ignore", std::string(kSimulatorLine) +
                    "behavior/r1  behavior --robot r1\n"
                    "behavior/r9  on-exit=ignore  behavior --robot r9 --no-such-option\n");
  auto& launcher = launch(set, {}, "launcher", true);
  ASSERT_TRUE(await_text(launcher.log_file(), "ready on domain 154"));
  const pid_t simulator = pid_in("simulator-main.pid"), behavior = pid_in("behavior-r1.pid");
  const std::string out = read_file(launcher.log_file());
  EXPECT_TRUE(contains(out, ") ended: exit code 109")) << out;
  EXPECT_TRUE(contains(out, "  | The following argument was not expected: --no-such-option"))
      << out;
  EXPECT_TRUE(contains(out, "launch: behavior/r9: on-exit=ignore, the rest of the set goes on"))
      << out;
  EXPECT_TRUE(contains(out, "(without behavior/r9, which ended)")) << out;
  EXPECT_TRUE(process_running(simulator));
  EXPECT_TRUE(process_running(behavior));
  EXPECT_TRUE(launcher.running());

  stop_watching(launcher);
  launcher.signal(SIGTERM);
  ASSERT_TRUE(await_ended(launcher, 0));
  EXPECT_FALSE(process_running(behavior));
}

// --detach returns once ready; the launcher left in the background (launch.pid) still
// supervises (a crash is reported in launch.log and respawned) and 'stop' ends it with the set.
TEST_F(LaunchTest, DetachedSetIsSupervisedAndStoppedFromAnotherTerminal) {
  join(155);
  Recorder<msg::Heartbeat> beats(participant(), dds::topics::heartbeat);
  const auto set = write_set(
      "detached", std::string(kSimulatorLine) +
                      "behavior/r1  on-exit=respawn:max=2:backoff=0.2  behavior --robot r1\n");
  auto& front = launch(set, {"--detach"});
  ASSERT_TRUE(await_ended(front, 0));
  EXPECT_TRUE(
      contains(read_file(front.log_file()), "launch: stop it with: deploy/launch.sh stop " + run_));
  const pid_t supervisor = pid_in("launch.pid"), first = pid_in("behavior-r1.pid"),
              simulator = pid_in("simulator-main.pid");
  ASSERT_GT(supervisor, 0);
  EXPECT_NE(supervisor, front.pid());
  EXPECT_TRUE(process_running(supervisor));

  ASSERT_EQ(::kill(first, SIGKILL), 0);
  const std::string log = run_ + "/launch.log";
  ASSERT_TRUE(await_text(
      log, "launch: behavior/r1 (pid " + std::to_string(first) + ") ended: killed by SIGKILL"));
  const pid_t second = await_respawned_ready(beats, "behavior-r1.pid", first);

  auto& stop = stop_from_another_terminal();
  ASSERT_TRUE(await_ended(stop, 0));
  EXPECT_FALSE(process_running(supervisor));
  EXPECT_FALSE(process_running(second));
  EXPECT_FALSE(process_running(simulator));
  EXPECT_TRUE(contains(read_file(log), "launch: SIGTERM: stopping the set"));
  EXPECT_EQ(read_file(run_ + "/launch.state"), "stopped\n");
}

// Mistakes in a set file: exit code 2, FILE:LINE and what is wrong, and nothing started.
TEST_F(LaunchTest, SetFileMistakesAreReportedAtFileLineBeforeAnythingStarts) {
  join(156);
  struct Case {
    std::string name, text, message;
  };
  const std::vector<Case> cases = {
      {"policy",
       std::string(kSimulatorLine) + "# r1\nbehavior/r1  on-exit=sometimes  behavior --robot r1\n",
       ":3: unknown on-exit policy 'sometimes'"},
      {"option",
       std::string(kSimulatorLine) + "behavior/r1  on-exit=respawn:max=0  behavior --robot r1\n",
       ":2: respawn max must be 1..1000, got '0'"},
      {"backoff",
       std::string(kSimulatorLine) +
           "behavior/r1  on-exit=respawn:backoff=-1  behavior --robot r1\n",
       ":2: respawn backoff must be seconds in (0, 60], got '-1'"},
      {"twice", std::string(kSimulatorLine) + "simulator  simulator\n",
       ":2: simulator/main is already line 1's process"},
      {"program", std::string(kSimulatorLine) + "behavior/r1  no-such-program\n",
       ":2: program " + bin_dir() + "/no-such-program not found"},
      {"empty", std::string(kSimulatorLine) + "behavior/r1  on-exit=ignore\n",
       ":2: expected NAME [on-exit=POLICY] [hang-after=S] PROGRAM"},
      {"hang", std::string(kSimulatorLine) + "behavior/r1  hang-after=soon  behavior --robot r1\n",
       ":2: hang-after must be seconds (0: never), got 'soon'"},
      {"hang-twice",
       std::string(kSimulatorLine) + "behavior/r1  hang-after=1  on-exit=ignore  hang-after=2  behavior --robot r1\n",
       ":2: hang-after is given twice"},
  };
  for (const auto& c : cases) {
    const auto set = write_set(c.name, c.text);
    auto& launcher = launch(set, {}, "launcher-" + c.name);
    ASSERT_TRUE(await_ended(launcher, 2)) << c.name;
    const std::string out = read_file(launcher.log_file());
    EXPECT_TRUE(contains(out, "launch: " + set + c.message)) << c.name << ": " << out;
    EXPECT_FALSE(contains(out, "started")) << c.name << ": " << out;
    EXPECT_FALSE(fs::exists(run_ + "/simulator-main.pid")) << c.name;
  }
}

// Issue 23: a process that hangs (SIGSTOP here) under on-exit=respawn. The launcher says it went
// silent, then, at its hang limit, that it is hung, with its last output lines; kills it
// (SIGKILL), respawns it with the usual back-off, and says when the set is ready again. The rest
// of the set is untouched.
TEST_F(LaunchTest, HungProcessIsReportedWithItsLastLinesAndRespawned) {
  join(157);
  Recorder<msg::Heartbeat> beats(participant(), dds::topics::heartbeat);
  const auto set = write_set(
      "hang", std::string(kSimulatorLine) +
                  "behavior/r1  on-exit=respawn:max=3:backoff=0.2  hang-after=3  behavior --robot r1\n");
  auto& launcher = launch(set, {}, "launcher", true);
  ASSERT_TRUE(await_text(launcher.log_file(), "launch: set 'hang' ready on domain 157"));
  const pid_t simulator = pid_in("simulator-main.pid"), first = pid_in("behavior-r1.pid");
  ASSERT_GT(first, 0);
  const std::string who = "launch: behavior/r1 (pid " + std::to_string(first) + ")";

  ASSERT_EQ(::kill(first, SIGSTOP), 0);
  ASSERT_TRUE(await_text(launcher.log_file(), who + " is silent: not heard for"));
  ASSERT_TRUE(await_text(launcher.log_file(), who + " is hung: not heard for"));
  ASSERT_TRUE(await_text(launcher.log_file(),
                         "launch: behavior/r1: on-exit=respawn, killing it (SIGKILL) to start it again"));
  ASSERT_TRUE(await_text(launcher.log_file(), who + " ended: killed by SIGKILL by the launcher (hung)"));
  ASSERT_TRUE(await_text(launcher.log_file(),
                         "launch: behavior/r1: respawning in 0.2 s (respawn 1 of at most 3)"));
  const pid_t second = await_respawned_ready(beats, "behavior-r1.pid", first);
  ASSERT_GT(second, 0);
  ASSERT_TRUE(await_text(launcher.log_file(), "launch: set 'hang' ready again (behavior/r1 respawned as pid " +
                                                  std::to_string(second) + ")"));

  const std::string out = read_file(launcher.log_file());
  // In order: silent, hung with the quoted output (the process's own log lines), killed, ended.
  const auto silent = out.find(who + " is silent"), hung = out.find(who + " is hung");
  const auto killed = out.find("killing it (SIGKILL)"), ended = out.find(who + " ended");
  ASSERT_LT(silent, hung) << out;
  ASSERT_LT(hung, killed) << out;
  ASSERT_LT(killed, ended) << out;
  const auto quoted = out.find("  | ", hung);
  ASSERT_LT(quoted, killed) << out;
  EXPECT_TRUE(contains(out.substr(quoted, killed - quoted), "[behavior/r1]")) << out;
  EXPECT_TRUE(contains(out, "hung after 3 s")) << out;
  EXPECT_FALSE(contains(out, "stopping the set")) << out;
  EXPECT_FALSE(process_running(first));
  EXPECT_EQ(pid_in("simulator-main.pid"), simulator);
  EXPECT_TRUE(process_running(simulator));
  EXPECT_TRUE(contains(read_file(run_ + "/launch.watch"), "hung behavior/r1 pid " + std::to_string(first)));

  stop_watching(launcher);
  launcher.signal(SIGINT);
  ASSERT_TRUE(await_ended(launcher, 0));
  EXPECT_FALSE(process_running(second));
}

// SIGSTOP, then SIGCONT before the hang limit: the launcher says it was silent and is heard
// again, and touches nothing: same pid, no hung report, no respawn.
TEST_F(LaunchTest, ProcessResumedBeforeItsHangLimitIsLeftAlone) {
  join(158);
  const auto set = write_set(
      "pause", std::string(kSimulatorLine) +
                   "behavior/r1  on-exit=respawn:max=3:backoff=0.2  hang-after=25  behavior --robot r1\n");
  auto& launcher = launch(set, {}, "launcher", true);
  ASSERT_TRUE(await_text(launcher.log_file(), "launch: set 'pause' ready on domain 158"));
  const pid_t behavior = pid_in("behavior-r1.pid");
  ASSERT_GT(behavior, 0);
  const std::string who = "launch: behavior/r1 (pid " + std::to_string(behavior) + ")";

  ASSERT_EQ(::kill(behavior, SIGSTOP), 0);
  ASSERT_TRUE(await_text(launcher.log_file(), who + " is silent: not heard for"));
  ASSERT_EQ(::kill(behavior, SIGCONT), 0);
  ASSERT_TRUE(await_text(launcher.log_file(), who + " is heard again after"));
  EXPECT_TRUE(contains(read_file(launcher.log_file()), "; left running")) << read_file(launcher.log_file());

  // A second pause, now past the DDS lease (2 s): it is rediscovered and left alone too.
  ASSERT_EQ(::kill(behavior, SIGSTOP), 0);
  ASSERT_TRUE(await("behavior/r1 silent a second time", [&] {
    const std::string out = read_file(launcher.log_file());
    return out.find(who + " is silent", out.find(who + " is heard again")) != std::string::npos;
  }));
  std::this_thread::sleep_for(std::chrono::seconds(3));  // the pause itself, not a wait for an outcome
  ASSERT_EQ(::kill(behavior, SIGCONT), 0);
  ASSERT_TRUE(await("behavior/r1 heard again a second time", [&] {
    const std::string out = read_file(launcher.log_file());
    const auto first = out.find(who + " is heard again");
    return first != std::string::npos && out.find(who + " is heard again", first + 1) != std::string::npos;
  }));

  const std::string out = read_file(launcher.log_file());
  EXPECT_FALSE(contains(out, "is hung")) << out;
  EXPECT_FALSE(contains(out, "ended")) << out;
  EXPECT_FALSE(contains(out, "respawn")) << out;
  EXPECT_EQ(pid_in("behavior-r1.pid"), behavior);
  EXPECT_TRUE(process_running(behavior));
  EXPECT_TRUE(launcher.running());
}

// on-exit=stop: a hung process is killed and the set stopped, as for a crash (exit code 1).
TEST_F(LaunchTest, HungProcessUnderPolicyStopStopsTheSet) {
  join(159);
  const auto set = write_set(
      "stopping", std::string(kSimulatorLine) + "behavior/r1  hang-after=2  behavior --robot r1\n");
  auto& launcher = launch(set);
  ASSERT_TRUE(await_text(launcher.log_file(), "ready on domain 159"));
  const pid_t simulator = pid_in("simulator-main.pid"), behavior = pid_in("behavior-r1.pid");

  ASSERT_EQ(::kill(behavior, SIGSTOP), 0);
  ASSERT_TRUE(await_ended(launcher, 1));
  const std::string out = read_file(launcher.log_file());
  EXPECT_TRUE(contains(out, "launch: behavior/r1 (pid " + std::to_string(behavior) + ") is hung: not heard for"))
      << out;
  EXPECT_TRUE(contains(out, "launch: behavior/r1: on-exit=stop, killing it (SIGKILL) and stopping the set")) << out;
  EXPECT_FALSE(contains(out, "respawning")) << out;
  EXPECT_FALSE(process_running(behavior));
  EXPECT_FALSE(process_running(simulator));
}

// `autonomy node list` started after a process went silent still lists it, as stale, with how
// long ago it was last heard (the launcher's watcher remembers it); under on-exit=ignore the
// launcher only reports it hung. Resumed, it is listed as ready again.
TEST_F(LaunchTest, NodeListShowsAStoppedProcessAsStaleAndIgnoreOnlyReportsIt) {
  join(185);
  const auto set = write_set(
      "listed", std::string(kSimulatorLine) + "behavior/r1  on-exit=ignore  hang-after=2  behavior --robot r1\n");
  auto& launcher = launch(set, {}, "launcher", true);
  ASSERT_TRUE(await_text(launcher.log_file(), "ready on domain 185"));
  const pid_t simulator = pid_in("simulator-main.pid"), behavior = pid_in("behavior-r1.pid");
  const std::string who = "launch: behavior/r1 (pid " + std::to_string(behavior) + ")";

  nlohmann::json rows;
  ASSERT_TRUE(node_list(rows, "list-before"));
  ASSERT_FALSE(row_of(rows, behavior).is_null()) << rows.dump();
  EXPECT_EQ(row_of(rows, behavior)["state"], "ready") << rows.dump();

  ASSERT_EQ(::kill(behavior, SIGSTOP), 0);
  ASSERT_TRUE(await_text(launcher.log_file(), who + " is hung: not heard for"));
  ASSERT_TRUE(await_text(launcher.log_file(), "launch: behavior/r1: on-exit=ignore, left as it is"));
  // Hung is reported after 2 s of silence: past the DDS lease (2 s), so a new participant can no
  // longer discover the stopped one; the listing has it from the watcher.
  ASSERT_TRUE(node_list(rows, "list-stopped"));
  const auto stale = row_of(rows, behavior);
  ASSERT_FALSE(stale.is_null()) << rows.dump();
  EXPECT_EQ(stale["state"], "stale") << rows.dump();
  EXPECT_EQ(stale["last_state"], "ready") << rows.dump();
  EXPECT_EQ(stale["service"], "behavior");
  EXPECT_EQ(stale["instance"], "r1");
  EXPECT_GE(stale["age_s"].get<double>(), 1.0) << rows.dump();
  EXPECT_EQ(row_of(rows, simulator)["state"], "ready") << rows.dump();
  // The table says it too, with the age.
  auto& text = start("list-text", AUTONOMY_AUTONOMY_BIN, {"node", "list", "--domain", std::to_string(domain_)}, false);
  ASSERT_TRUE(text.wait_for_exit(kDeadline));
  std::string stale_line;
  for (std::istringstream lines(read_file(text.log_file())); std::getline(lines, stale_line);)
    if (contains(stale_line, " " + std::to_string(behavior) + " ")) break;
  EXPECT_TRUE(contains(stale_line, "stale")) << read_file(text.log_file());
  EXPECT_TRUE(contains(stale_line, "last heard")) << read_file(text.log_file());

  ASSERT_EQ(::kill(behavior, SIGCONT), 0);
  ASSERT_TRUE(await_text(launcher.log_file(), who + " is heard again after"));
  ASSERT_TRUE(await("node list shows behavior/r1 ready again", [&] {
    nlohmann::json now;
    return node_list(now, "list-resumed") && !row_of(now, behavior).is_null() &&
           row_of(now, behavior)["state"] == "ready";
  }));
  EXPECT_TRUE(process_running(behavior));
  EXPECT_EQ(pid_in("behavior-r1.pid"), behavior);
  EXPECT_FALSE(contains(read_file(launcher.log_file()), "ended")) << read_file(launcher.log_file());
}

// Two processes under one name (a mistake node list must show, not hide): two rows, and a
// warning that names them.
TEST_F(LaunchTest, NodeListShowsEveryProcessOfOneName) {
  join(186);
  Recorder<msg::Heartbeat> beats(participant(), dds::topics::heartbeat);
  const std::vector<std::string> args = {"--instance", "twin", "--domain", std::to_string(domain_), "--log-dir",
                                         dir().path()};
  auto& a = start("twin-a", AUTONOMY_FAKE_SERVICE_BIN, args);
  auto& b = start("twin-b", AUTONOMY_FAKE_SERVICE_BIN, args);
  ASSERT_TRUE(await_ready(beats, a));
  ASSERT_TRUE(await_ready(beats, b));

  nlohmann::json rows;
  ASSERT_TRUE(node_list(rows));
  ASSERT_FALSE(row_of(rows, a.pid()).is_null()) << rows.dump();
  ASSERT_FALSE(row_of(rows, b.pid()).is_null()) << rows.dump();
  for (const pid_t pid : {a.pid(), b.pid()}) {
    EXPECT_EQ(row_of(rows, pid)["service"], "fake");
    EXPECT_EQ(row_of(rows, pid)["instance"], "twin");
    EXPECT_EQ(row_of(rows, pid)["state"], "ready");
  }
  auto& text = start("list-text", AUTONOMY_AUTONOMY_BIN, {"node", "list", "--domain", std::to_string(domain_)}, false,
                     true);
  ASSERT_TRUE(text.wait_for_exit(kDeadline));
  EXPECT_TRUE(contains(read_file(text.stderr_file()), "2 processes are named fake/twin"))
      << read_file(text.stderr_file());
}

}  // namespace
}  // namespace autonomy::test
