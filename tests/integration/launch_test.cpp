// Integration tests of deploy/launch.sh: the real script starting the real simulator and behavior
// (--bin: the build's bin folder) over Cyclone DDS on loopback, a second launch.sh as "another
// terminal", kill -9 as a crash; every outcome is polled for with a deadline.
//
// One DDS domain per test (ctest runs them in parallel); this file uses 150-159 only:
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
#include "tests/support/process_test.hpp"

#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <string>
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
       ":2: expected NAME [on-exit=POLICY] PROGRAM"},
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

}  // namespace
}  // namespace autonomy::test
