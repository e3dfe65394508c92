#pragma once
// The kill matrix (issue 23): every shipped service set (deploy/sets/) run by deploy/launch.sh
// as a user runs it, its mission started, and then one of its processes killed with SIGKILL
// mid-mission (respawned by the set's on-exit policy) or stopped with SIGSTOP for 10 s and
// continued. Each cell asserts the mission's outcome: the same as the set's cell without a blow,
// or the difference the cell names. Nothing accepted is lost in any cell.
//
// The worlds run in lockstep (the sets' paced worlds too: same processes, policies and
// arguments otherwise) with an ack timeout of 30 s, above a respawn's 1 s back-off plus start and
// readiness, so the world waits for a killed participant's successor and the outage costs no
// simulated time. The test is a lockstep participant (test/hand) until the blow: it holds tick 0
// while the mission is handed over, then steps the world to the cell's moment of the blow.
// SIGSTOP cells run the launcher with --hang-after 20: a 10 s stop is reported as silent and
// heard again, not as hung (the hung path is launch_test.cpp's).
//
// The simulator is the world: killed, its set stops (on-exit=stop, the default: a new simulator
// would start another world at tick 0) and the cell asserts that the launcher says so and that
// what the services accepted is in their journals for the next run.
//
//   domain  cell (set / process / blow)            domain  cell
//   ------  ---------------------------------      ------  ---------------------------------
//     1     demo / - / none                          26    ds1 / planner/main / stop
//     2     demo / simulator/main / kill             27    ds1 / executive/main / kill
//     3     demo / simulator/main / stop             28    ds1 / executive/main / stop
//     4     demo / behavior/r1 / kill                29    rover / - / none
//     5     demo / behavior/r1 / stop                30    rover / simulator/main / kill
//     6     courier / - / none                       31    rover / simulator/main / stop
//     7     courier / simulator/main / kill          32    rover / planner/main / kill
//     8     courier / simulator/main / stop          33    rover / planner/main / stop
//     9     courier / behavior/rhino / kill          34    rover / executive/main / kill
//    10     courier / behavior/rhino / stop          35    rover / executive/main / stop
//    11     courier / courier/main / kill            36    rover / behavior/rover / kill
//    12     courier / courier/main / stop            37    rover / behavior/rover / stop
//    13     courier-fleet / - / none                 38    recon-parallel / - / none
//    14     courier-fleet / simulator/main / stop    39    recon-parallel / simulator/main / kill
//    15     courier-fleet / behavior/rhino / kill    40    recon-parallel / simulator/main / stop
//    16     courier-fleet / behavior/rhino2 / kill   41    recon-parallel / behavior/r1 / kill
//    17     courier-fleet / behavior/rhino2 / stop   42    recon-parallel / behavior/r2 / stop
//    18     courier-fleet / courier/main / kill      43    recon-parallel / behavior/r3 / kill
//    19     courier-fleet / courier/main / stop      44    courier-fleet / behavior/rhino / stop
//    20     planner / - / none                       45    courier-fleet / simulator/main / kill
//    21     planner / planner/main / kill            46    recon-parallel / behavior/r1 / stop
//    22     planner / planner/main / stop            47    ds1 / simulator/main / kill
//    23     ds1 / - / none
//    24     ds1 / simulator/main / stop
//    25     ds1 / planner/main / kill
// (ctest names them integration.<Sets>/<Suite>.Cell/<set>_<process>_<blow>; the cells of each
// set family are in kill_matrix_{robots,courier,plans}_test.cpp, this is their fixture.)
#include "tests/support/executive_watch.hpp"
#include "tests/support/launched_set.hpp"
#include "tests/support/process_test.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdlib>
#include <csignal>
#include <filesystem>
#include <ostream>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace autonomy::test {

using namespace std::chrono_literals;

enum class Blow { none, kill, stop };

struct Cell {
  const char* set;
  const char* process;  // "" with Blow::none
  Blow blow;
  int domain;
};

inline const char* blow_name(Blow b) { return b == Blow::none ? "none" : b == Blow::kill ? "kill" : "stop"; }
// How gtest prints a cell in its messages.
inline void PrintTo(const Cell& c, std::ostream* out) {
  *out << c.set << " / " << (*c.process ? c.process : "-") << " / " << blow_name(c.blow) << " (domain " << c.domain
       << ")";
}

inline std::string cell_name(const ::testing::TestParamInfo<Cell>& info) {
  std::string name = std::string(info.param.set) + "_" + (*info.param.process ? info.param.process : "nothing") + "_" +
                     blow_name(info.param.blow);
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

inline constexpr char kHand[] = "test/hand";
inline constexpr auto kMission = std::chrono::seconds(150);
inline constexpr auto kStopped = std::chrono::seconds(10);

class KillMatrixTest : public ProcessTest, public ::testing::WithParamInterface<Cell> {
 protected:
  void SetUp() override {
    join(GetParam().domain);
    clock_.emplace(participant(), dds::topics::clock);
    ack_topic_.emplace(participant(), dds::topics::tick_ack);
    ack_writer_.emplace(participant(), *ack_topic_);
    registration_topic_.emplace(participant(), dds::topics::lockstep_registration);
    registration_writer_.emplace(participant(), *registration_topic_);
  }

  bool blows(const std::string& process) const { return GetParam().process == process; }
  bool killed() const { return GetParam().blow == Blow::kill; }
  bool world_killed() const { return killed() && blows("simulator/main"); }

  // The set's copy: worlds in lockstep, held for the test's hand, waiting 30 s for a silent
  // participant; every other line as shipped, or as `also` edits it (a cell that departs from
  // the shipped set says why).
  void prepare(const std::string& set, const LaunchedSet::LineEdit& also = nullptr) {
    // AUTONOMY_MATRIX_DEBUG=1: every process logs at debug level (to follow a cell's ticks).
    const std::string level = std::getenv("AUTONOMY_MATRIX_DEBUG") ? " --log-level debug" : "";
    set_.emplace(dir(), set, [&](const std::string& name, const std::string& line) {
      if (name != "simulator/main") return (also ? also(name, line) : line) + level;
      return replaced(line, " --mode paced", "") + " --mode lockstep --ack-timeout 30 --wait-for " + kHand + level;
    });
  }

  // Starts the launcher (foreground) and waits until it says the set is ready.
  void launch() {
    std::vector<std::string> extra;
    if (GetParam().blow == Blow::stop) extra = {"--hang-after", "20"};
    if (clock_used_) registration_writer_->write({kHand, true});
    launcher_ = &start("launcher", "/bin/bash", set_->launcher_args(domain_, extra), false);
    ASSERT_TRUE(await("the launcher says the set is ready", [&] {
      return contains(launcher_output(), "' ready on domain") || !launcher_->running();
    }, 90s));
    ASSERT_TRUE(launcher_->running()) << launcher_output();
  }
  std::string launcher_output() const { return read_file(dir().file("launcher.out")); }
  static bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

  // The world's newest tick seen so far.
  int64_t tick() {
    for (const auto& c : clock_->poll()) tick_ = std::max(tick_, c.tick);
    return tick_;
  }
  // Steps the world, as its lockstep participant, until `moment` holds after a tick; the world
  // then waits there for the hand. Polled every millisecond, not at await()'s 20 ms: the hand
  // steps thousands of ticks.
  ::testing::AssertionResult step_until(const std::string& what, const std::function<bool()>& moment) {
    int64_t acked = -1;
    const auto deadline = std::chrono::steady_clock::now() + kMission;
    while (std::chrono::steady_clock::now() < deadline) {
      const int64_t latest = tick();
      if (latest > acked) {
        if (moment()) return ::testing::AssertionSuccess();
        acked = latest;
        ack_writer_->write({kHand, acked, 0});
      }
      if (launcher_ && !launcher_->running())
        return ::testing::AssertionFailure() << "the launcher ended while waiting for: " << what << "\n"
                                             << launcher_output();
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    return ::testing::AssertionFailure() << "timed out waiting for: " << what << " (world at tick " << tick_ << ")";
  }
  void release_world() { registration_writer_->write({kHand, false}); }

  // The blow of the cell, at the moment the mission reached; then the hand lets go of the world.
  void blow() {
    const std::string process = GetParam().process;
    if (GetParam().blow == Blow::none) {
      release_world();
      return;
    }
    victim_ = set_->pid_of(process);
    ASSERT_GT(victim_, 0) << "no pid file for " << process;
    if (GetParam().blow == Blow::kill) {
      ASSERT_EQ(::kill(victim_, SIGKILL), 0);
      release_world();
      if (world_killed()) return;
      ASSERT_TRUE(await(process + " respawned and ready again", [&] {
        return contains(launcher_output(), "ready again (" + process + " respawned as pid");
      }, 60s)) << launcher_output();
      EXPECT_TRUE(contains(launcher_output(),
                           process + " (pid " + std::to_string(victim_) + ") ended: killed by SIGKILL"))
          << launcher_output();
      return;
    }
    ASSERT_EQ(::kill(victim_, SIGSTOP), 0);
    release_world();
    std::this_thread::sleep_for(kStopped);
    ASSERT_EQ(::kill(victim_, SIGCONT), 0);
    const std::string who = process + " (pid " + std::to_string(victim_) + ")";
    ASSERT_TRUE(await(who + " heard again",
                      [&] { return contains(launcher_output(), who + " is heard again"); }, 30s))
        << launcher_output();
    EXPECT_TRUE(contains(launcher_output(), who + " is silent")) << launcher_output();
    EXPECT_EQ(set_->pid_of(process), victim_) << "a stopped process is left running, not respawned";
  }

  // The world killed: the set stops, the launcher ends with 1 and names the simulator.
  void expect_the_set_stopped_with_the_world() {
    ASSERT_TRUE(launcher_->wait_for_exit(60s).has_value()) << launcher_output();
    const auto status = launcher_->status();
    EXPECT_TRUE(status->exited && status->code == 1) << status->describe();
    const std::string out = launcher_output();
    EXPECT_TRUE(contains(out, "simulator/main (pid " + std::to_string(victim_) + ") ended: killed by SIGKILL")) << out;
    EXPECT_TRUE(contains(out, "simulator/main: on-exit=stop, stopping the set")) << out;
  }

  // After a stop or a kill the set still runs, nothing stopped it and nothing was taken for hung
  // (the test's end kills the launcher, and with it the set).
  void expect_the_set_still_runs() {
    ASSERT_TRUE(launcher_->running()) << launcher_output();
    const auto out = launcher_output();
    EXPECT_FALSE(contains(out, "stopping the set")) << out;
    EXPECT_FALSE(contains(out, "(hung)")) << out;
  }

  std::optional<LaunchedSet> set_;
  ChildProcess* launcher_ = nullptr;
  pid_t victim_ = 0;
  bool clock_used_ = true;
  int64_t tick_ = -1;
  std::optional<Recorder<msg::SimClock>> clock_;
  std::optional<dds::Topic<msg::TickAck>> ack_topic_;
  std::optional<dds::Writer<msg::TickAck>> ack_writer_;
  std::optional<dds::Topic<msg::LockstepRegistration>> registration_topic_;
  std::optional<dds::Writer<msg::LockstepRegistration>> registration_writer_;
};

}  // namespace autonomy::test
