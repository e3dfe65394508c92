// Replay of a courier run (issue 26): the paper's example with A-120 closing and reopening
// (Fig. 5), recorded with `autonomy record -a` from before the world started, then fed by
// `autonomy replay` into a fresh simulator alone: the recorded commands, handover requests and
// acknowledgements stand in for rhino's behavior and the courier, and the fresh world must give
// back every recorded robot state, scan, door, object and handover answer, tick by tick.
//
//   domain  test
//   ------  -----------------------------------------------
//     53    CourierTest.ARecordedRunReplaysIntoAFreshWorldExactly
#include "tests/integration/courier_fixture.hpp"
#include "tests/support/recorder_log.hpp"

#include <gtest/gtest.h>

#include <csignal>
#include <regex>

namespace autonomy::test {
namespace {

using namespace std::chrono_literals;

TEST_F(CourierTest, ARecordedRunReplaysIntoAFreshWorldExactly) {
  setup_observers(53);
  const std::string file = dir().file("courier.mcap");
  auto& recorder = start("recorder", AUTONOMY_AUTONOMY_BIN,
                         {"record", "-a", "-o", file, "--domain", std::to_string(domain_), "--chunk", "0.2", "--verbose"},
                         false);
  ASSERT_TRUE(await("the recorder's readers", [&] {
    return read_file(dir().file("recorder.out")).find("Ctrl-C stops") != std::string::npos;
  }));
  start_world(office_scenario(kFig5Script));
  // The world is held until the test releases it (send_paper_commands): by then the recorder's
  // readers must have matched every writer a replay needs, or the replay refuses the file. Acks
  // come from the test, rhino's behavior and the courier.
  for (const auto& [topic, writers] : std::vector<std::pair<std::string, unsigned>>{
           {"autonomy/clock", 1}, {"autonomy/robot/state", 1}, {"autonomy/lockstep/ack", 3},
           {"autonomy/robot/cmd_vel", 1}, {"autonomy/office/handover_request", 1}})
    ASSERT_TRUE(await("the recorder matched the writers of " + topic,
                      [&] { return recorder_matched(read_file(dir().file("recorder.out")), topic, writers); }))
        << read_file(dir().file("recorder.out"));
  send_paper_commands();
  ASSERT_TRUE(both_jobs_finished("both jobs finished"));
  EXPECT_TRUE(job_in("job-1", msg::JobState::Completed)) << job_story("job-1");
  // The world stops first; the recorder, slower than the world on a loaded machine, is stopped
  // once it took everything that was sent (a file cut at another point for each topic would
  // hold outputs whose inputs it lost).
  for (ChildProcess* c : {simulator_, behavior_, courier_}) stop_watching(*c);
  simulator_->kill_and_wait();
  std::map<std::string, std::size_t> counts;
  ASSERT_TRUE(await("the recorder caught up with the stopped world", [&] { return recording_stopped_growing(file, counts); },
                    60s));
  recorder.signal(SIGINT);
  const auto recorded = recorder.wait_for_exit(10s);
  ASSERT_TRUE(recorded && recorded->exited && recorded->code == 0) << read_file(dir().file("recorder.out"));
  for (ChildProcess* c : {behavior_, courier_}) c->kill_and_wait();

  auto& fresh = start_simulator({"--config", scenario_, "--mode", "lockstep", "--wait-for", "replay"}, false,
                                "simulator-replay");
  auto& replay = start("replay", AUTONOMY_AUTONOMY_BIN, {"replay", file, "--domain", std::to_string(domain_)}, false);
  const auto ended = replay.wait_for_exit(kRun);
  fresh.kill_and_wait();
  const std::string out = read_file(dir().file("replay.out"));
  ASSERT_TRUE(ended.has_value()) << out;
  EXPECT_TRUE(ended->exited && ended->code == 0) << ended->describe() << "\n" << out;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(out, m, std::regex(R"(replay matches the recording: (\d+) of (\d+) recorded outputs)")))
      << out;
  EXPECT_EQ(m[1], m[2]);
  EXPECT_GT(std::stoul(m[1]), 1000u) << out;
  // What the courier example is about came back too: the door's closing and reopening, the
  // letters and the book changing hands, the handover answers.
  for (const char* topic : {"autonomy/truth/door", "autonomy/truth/object", "autonomy/office/handover_status",
                            "autonomy/robot/state", "autonomy/robot/range_scan"})
    EXPECT_TRUE(std::regex_search(out, std::regex(std::string(topic) + ": [1-9][0-9]* matched"))) << topic << "\n" << out;
  // The courier's handover requests were inputs, replayed at the ticks they were made.
  EXPECT_NE(out.find("autonomy/office/handover_request ("), std::string::npos) << out;
}

}  // namespace
}  // namespace autonomy::test
