// Recordings of real runs (issue 26): `autonomy record` beside the simulator and a behavior in
// lockstep, read back by the project's reader and by independent readers (npm's @mcap/core and
// @foxglove/omgidl-serialization, tests/node/validate_recording.js), and a recorder killed with -9.
//
//   domain  test
//   ------  -----------------------------------------------
//    197    RecordingTest.ALockstepRunIsReadByIndependentReaders
//    198    RecordingTest.ARecorderKilledLeavesItsChunksReadable
//     52    RecordingTest.ALockstepRunReplaysExactlyAndAnotherWorldDiffers
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

#include "common/mcap/reader.hpp"
#include "tests/support/goal_statuses.hpp"
#include "tests/support/process_test.hpp"
#include "tests/support/recorder_log.hpp"
#include "tools/recording/raw_topic.hpp"

namespace autonomy::test {
namespace {

using namespace std::chrono_literals;

constexpr int kDomainIndependentReaders = 197;
constexpr int kDomainKilled = 198;
constexpr int kDomainReplay = 52;

// What a recording holds, read with the project's reader.
struct Contents {
  mcap::ReadReport report;
  std::map<std::string, std::vector<mcap::Message>> by_topic;
  std::map<std::string, mcap::Channel> channels;
  std::map<std::string, std::string> schema_of;
};

Contents read_recording(const std::string& path) {
  Contents c;
  mcap::Reader reader(path);
  c.report = reader.read([&](const mcap::Channel& ch, const mcap::Schema* s, const mcap::Message& m) {
    c.by_topic[ch.topic].push_back(m);
    c.channels[ch.topic] = ch;
    c.schema_of[ch.topic] = s ? s->name : "";
  });
  return c;
}

template <typename T>
std::vector<T> decode_all(const std::vector<mcap::Message>& messages, const std::string& topic) {
  const auto* t = recording::find_recordable(topic);
  std::vector<T> out;
  for (const auto& m : messages) {
    recording::DecodedSample d(t->descriptor, m.data);
    out.push_back(dds::DdsType<T>::from_c(*static_cast<const typename dds::DdsType<T>::C*>(d.get())));
  }
  return out;
}

bool log_says(const ChildProcess& child, const std::string& text) {
  std::ifstream in(child.log_file());
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str().find(text) != std::string::npos;
}

std::string find_node() {
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "/usr/bin:/usr/local/bin");
  std::string dir;
  while (std::getline(dirs, dir, ':'))
    if (!dir.empty() && ::access((dir + "/node").c_str(), X_OK) == 0) return dir + "/node";
  return "";
}

class RecordingTest : public ProcessTest {
 protected:
  ChildProcess& start_recorder(const std::string& file, std::vector<std::string> extra = {}) {
    std::vector<std::string> args = {"record", "-a", "-o", file, "--domain", std::to_string(domain_), "--chunk", "0.2"};
    args.insert(args.end(), extra.begin(), extra.end());
    return start("recorder", AUTONOMY_AUTONOMY_BIN, args, false);
  }
};

TEST_F(RecordingTest, ALockstepRunIsReadByIndependentReaders) {
  join(kDomainIndependentReaders);
  Recorder<msg::Heartbeat> beats(participant(), dds::topics::heartbeat);
  Recorder<msg::GoalStatus> goals(participant(), dds::topics::goal_status);
  dds::Topic<msg::NavGoal> goal_topic(participant(), dds::topics::nav_goal);
  dds::Writer<msg::NavGoal> goal_writer(participant(), goal_topic);

  start_simulator({"--wait-for", "behavior/r1"});
  auto& behavior = start_behavior("r1");
  ASSERT_TRUE(await_ready(beats, behavior));
  // Started once the world runs: its map (transient-local, published once) must still be captured.
  const std::string file = dir().file("run.mcap");
  auto& recorder = start_recorder(file);
  ASSERT_TRUE(await("the recorder's readers", [&] { return log_says(recorder, "Ctrl-C stops"); }));
  ASSERT_TRUE(goal_writer.wait_for_readers(2, kDeadline)) << "behavior and recorder did not both match the goal";
  const msg::NavGoal goal{"r1", "rec-goal-1", 18.0, 2.0, 0.0, ""};
  goal_writer.write(goal);
  ASSERT_TRUE(await("goal rec-goal-1 reached", [&] {
    goals.poll();
    for (const auto& s : goals.all())
      if (s.goal_id == goal.goal_id && s.state == msg::GoalState::Reached) return true;
    return false;
  }, 60s)) << states_text(goals.all());
  std::map<std::string, std::size_t> counts;  // the recorder takes the last statuses
  ASSERT_TRUE(await("the recorder caught up with the quiet world", [&] { return recording_stopped_growing(file, counts); },
                    60s));
  recorder.signal(SIGINT);
  const auto ended = recorder.wait_for_exit(10s);
  ASSERT_TRUE(ended && ended->exited && ended->code == 0) << (ended ? ended->describe() : "still running");

  // The project's reader: complete, every CRC checked, the map captured, the goal and its statuses.
  const auto c = read_recording(file);
  EXPECT_TRUE(c.report.complete) << c.report.note;
  EXPECT_TRUE(c.report.data_crc_checked);
  EXPECT_TRUE(c.report.summary_crc_checked);
  EXPECT_EQ(c.report.compressions, std::set<std::string>{"zstd"});
  ASSERT_EQ(c.by_topic.count("autonomy/map"), 1u) << "transient-local state present at start not captured";
  EXPECT_EQ(c.schema_of.at("autonomy/map"), "autonomy::WorldMap");
  EXPECT_EQ(c.channels.at("autonomy/map").metadata.at("durability"), "transient-local");
  EXPECT_EQ(c.channels.at("autonomy/nav/goal").metadata.at("durability"), "volatile");
  const auto goals_recorded = decode_all<msg::NavGoal>(c.by_topic.at("autonomy/nav/goal"), "autonomy/nav/goal");
  ASSERT_EQ(goals_recorded.size(), 1u);
  EXPECT_EQ(goals_recorded[0].goal_id, goal.goal_id);
  EXPECT_EQ(goals_recorded[0].x, goal.x);
  std::vector<msg::GoalState> observed, recorded;
  for (const auto& s : goals.all())
    if (s.goal_id == goal.goal_id) observed.push_back(s.state);
  for (const auto& s : decode_all<msg::GoalStatus>(c.by_topic.at("autonomy/nav/goal_status"), "autonomy/nav/goal_status"))
    if (s.goal_id == goal.goal_id) recorded.push_back(s.state);
  // The statuses the recorder got are the last ones the test saw, in order, down to Reached. All
  // of them but the first few: goal_status is transient-local keep-last 1, so when the recorder's
  // reader matches the behavior's writer after the goal went out (the test sees its own matches,
  // not the recorder's), it gets the latest status at that moment, not the ones before it.
  ASSERT_FALSE(recorded.empty());
  ASSERT_LE(recorded.size(), observed.size());
  EXPECT_TRUE(std::equal(recorded.begin(), recorded.end(), observed.end() - static_cast<std::ptrdiff_t>(recorded.size())))
      << "recorded " << ::testing::PrintToString(recorded) << ", observed " << ::testing::PrintToString(observed);
  EXPECT_EQ(recorded.back(), msg::GoalState::Reached);
  for (const auto& [topic, messages] : c.by_topic)
    for (const auto& m : messages) {
      EXPECT_GT(m.publish_time, 0u) << topic;
      EXPECT_LE(m.publish_time, m.log_time + 1'000'000'000ull) << topic << ": published after it was received";
    }
  const auto robot_states = c.by_topic.at("autonomy/robot/state").size();
  EXPECT_GT(robot_states, 10u);

  // The independent readers: the same counts and values from the embedded schemas.
  const std::string node = find_node();
  if (node.empty())
    GTEST_SKIP() << "node is not installed: the MCAP validation by independent readers (tests/node) was skipped; "
                    "install nodejs and run deploy/test.sh";
  const std::string modules = std::string(AUTONOMY_SOURCE_DIR) + "/tests/node/node_modules/@mcap/core";
  struct stat st{};
  ASSERT_EQ(::stat(modules.c_str(), &st), 0) << "the npm packages are missing: npm ci --prefix "
                                             << AUTONOMY_SOURCE_DIR << "/tests/node (deploy/test.sh does this)";
  std::ostringstream expect;
  expect << R"({"counts":{"autonomy/nav/goal":1,"autonomy/map":1,"autonomy/robot/state":)" << robot_states << "},"
         << R"("values":[{"topic":"autonomy/nav/goal","match":{"goal_id":"rec-goal-1"},"expect":{"robot_id":"r1","x":18,"y":2}}],)"
         << R"("sequences":[{"topic":"autonomy/nav/goal_status","match":{"goal_id":"rec-goal-1"},"field":"state","values":[)";
  for (size_t i = 0; i < recorded.size(); ++i) expect << (i ? "," : "") << static_cast<int>(recorded[i]);
  expect << "]}]}";
  const std::string expect_file = dir().file("expect.json");
  write_file(expect_file, expect.str());
  auto& validator = start("validate_recording", node,
                          {std::string(AUTONOMY_SOURCE_DIR) + "/tests/node/validate_recording.js", file, expect_file}, false);
  const auto v = validator.wait_for_exit(120s);
  ASSERT_TRUE(v.has_value()) << "validate_recording.js did not finish";
  EXPECT_TRUE(v->exited && v->code == 0) << v->describe() << "\n" << validator.log_tail();
  std::fprintf(stderr, "%s\n", validator.log_tail(600).c_str());
}

TEST_F(RecordingTest, ARecorderKilledLeavesItsChunksReadable) {
  join(kDomainKilled);
  Recorder<msg::Heartbeat> beats(participant(), dds::topics::heartbeat);
  start_simulator({"--wait-for", "behavior/r1"});
  auto& behavior = start_behavior("r1");
  ASSERT_TRUE(await_ready(beats, behavior));
  const std::string file = dir().file("killed.mcap");
  auto& recorder = start_recorder(file);
  // At least three chunks on disk (robot states, clocks and heartbeats keep coming), then kill -9.
  ASSERT_TRUE(await("three chunks in the file", [&] {
    try {
      return read_recording(file).report.chunks >= 3;
    } catch (const mcap::McapError&) {
      return false;  // not even the header yet
    }
  }));
  recorder.kill_and_wait();

  const auto c = read_recording(file);
  EXPECT_FALSE(c.report.complete);
  EXPECT_TRUE(c.report.truncated);
  EXPECT_GE(c.report.chunks, 3u);
  EXPECT_FALSE(c.report.note.empty());
  ASSERT_GT(c.by_topic.count("autonomy/heartbeat"), 0u);
  // Every message of the complete chunks decodes with its type.
  EXPECT_GT(decode_all<msg::Heartbeat>(c.by_topic.at("autonomy/heartbeat"), "autonomy/heartbeat").size(), 0u);
  if (c.by_topic.count("autonomy/robot/state")) {
    for (const auto& s : decode_all<msg::RobotState>(c.by_topic.at("autonomy/robot/state"), "autonomy/robot/state"))
      EXPECT_EQ(s.robot_id, "r1");
  }
}

// Replay (issue 26): a lockstep run recorded from before the world started, fed back by
// `autonomy replay` into a fresh simulator (the behavior and the test's goal left out: the
// recorded commands stand in for them) reproduces every recorded robot state, clock and event
// tick by tick. Fed into a world with an obstacle in the robot's way, it names the first state
// that differs.
TEST_F(RecordingTest, ALockstepRunReplaysExactlyAndAnotherWorldDiffers) {
  join(kDomainReplay);
  Recorder<msg::Heartbeat> beats(participant(), dds::topics::heartbeat);
  Recorder<msg::GoalStatus> goals(participant(), dds::topics::goal_status);
  dds::Topic<msg::NavGoal> goal_topic(participant(), dds::topics::nav_goal);
  dds::Writer<msg::NavGoal> goal_writer(participant(), goal_topic);
  dds::Topic<msg::LockstepRegistration> registration_topic(participant(), dds::topics::lockstep_registration);
  dds::Writer<msg::LockstepRegistration> hand(participant(), registration_topic);
  const std::string file = dir().file("run.mcap");
  auto& recorder = start_recorder(file, {"--verbose"});
  ASSERT_TRUE(await("the recorder's readers", [&] { return log_says(recorder, "Ctrl-C stops"); }));
  // A lockstep world runs the whole trip in well under a second; a loaded machine discovers
  // slower than that. The world is held (for the test's hand too) until the recorder's readers
  // have matched the writers whose samples the replay needs: the world's clock and states, the
  // behavior's commands and acks (without an ack the fresh world would apply its commands a tick
  // late: the replay refuses such a file).
  auto& simulator = start_simulator({"--wait-for", "behavior/r1,test/hand"}, true, "simulator-recorded");
  auto& behavior = start_behavior("r1");
  for (const char* topic : {"autonomy/clock", "autonomy/robot/state", "autonomy/lockstep/ack", "autonomy/robot/cmd_vel"})
    ASSERT_TRUE(await(std::string("the recorder matched the writer of ") + topic,
                      [&] { return recorder_matched(read_file(dir().file("recorder.out")), topic, 1); }));
  hand.write({"test/hand", false});  // registered once and left: the world starts with behavior/r1 alone
  ASSERT_TRUE(await_ready(beats, behavior));
  ASSERT_TRUE(goal_writer.wait_for_readers(2, kDeadline));
  goal_writer.write({"r1", "replay-goal", 18.0, 2.0, 0.0, ""});
  ASSERT_TRUE(await("goal replay-goal reached", [&] {
    goals.poll();
    for (const auto& g : goals.all())
      if (g.goal_id == "replay-goal" && g.state == msg::GoalState::Reached) return true;
    return false;
  }, 60s)) << states_text(goals.all());
  // The world is quiet once r1 stands at its goal: the recorder, slower than the world on a
  // loaded machine, has taken everything once the file stops growing.
  std::map<std::string, std::size_t> counts;
  ASSERT_TRUE(await("the recorder caught up with the quiet world", [&] { return recording_stopped_growing(file, counts); },
                    60s));
  recorder.signal(SIGINT);
  const auto recorded = recorder.wait_for_exit(10s);
  ASSERT_TRUE(recorded && recorded->exited && recorded->code == 0);
  stop_watching(simulator);
  stop_watching(behavior);
  behavior.kill_and_wait();
  simulator.kill_and_wait();
  const auto c = read_recording(file);
  const auto states = decode_all<msg::RobotState>(c.by_topic.at("autonomy/robot/state"), "autonomy/robot/state");
  ASSERT_GT(states.size(), 20u);

  // No world yet: the tool says how to start one, from the recorded simulator's heartbeat.
  auto& early = start("replay-early", AUTONOMY_AUTONOMY_BIN,
                      {"replay", file, "--domain", std::to_string(domain_), "--world-wait", "1"}, false);
  const auto early_end = early.wait_for_exit(30s);
  ASSERT_TRUE(early_end && early_end->exited && early_end->code == 1);
  EXPECT_NE(read_file(dir().file("replay-early.out"))
                .find("start one with the recorded scenario, in lockstep, waiting for the replay:\n  simulator "
                      "--mode lockstep --wait-for replay --domain " + std::to_string(domain_)),
            std::string::npos)
      << read_file(dir().file("replay-early.out"));

  auto replay = [&](const std::string& name, std::vector<std::string> simulator_args) {
    simulator_args.insert(simulator_args.end(), {"--wait-for", "replay"});
    auto& fresh = start_simulator(simulator_args, false, "simulator-" + name);
    auto& tool = start(name, AUTONOMY_AUTONOMY_BIN, {"replay", file, "--domain", std::to_string(domain_)}, false);
    const auto ended = tool.wait_for_exit(120s);
    fresh.kill_and_wait();
    return std::make_pair(ended, read_file(dir().file(name + ".out")));
  };
  // The same world: every recorded output back, exit 0.
  const auto [same, same_out] = replay("replay-same", {});
  ASSERT_TRUE(same.has_value()) << same_out;
  EXPECT_TRUE(same->exited && same->code == 0) << same->describe() << "\n" << same_out;
  EXPECT_NE(same_out.find("replay matches the recording"), std::string::npos) << same_out;
  EXPECT_NE(same_out.find("autonomy/robot/state: " + std::to_string(states.size()) + " matched"), std::string::npos)
      << "every recorded state (" << states.size() << ") compared and matched:\n" << same_out;
  EXPECT_NE(same_out.find("autonomy/robot/cmd_vel ("), std::string::npos) << "the commands are inputs:\n" << same_out;

  // A world with a crate where r1 was half-way: the first state that differs is at or before the
  // tick r1 stood there, and the tool names it.
  const msg::RobotState& half_way = states[states.size() / 2];
  std::string crated = read_file(std::string(AUTONOMY_SOURCE_DIR) + "/deploy/scenarios/demo.pbtxt");
  const auto world_end = crated.find("\n}\n", crated.find("world {"));
  ASSERT_NE(world_end, std::string::npos);
  std::ostringstream crate;
  crate << "\n  obstacles { min_x: " << half_way.x - 0.2 << " min_y: " << half_way.y - 0.2 << " max_x: " << half_way.x + 0.2
        << " max_y: " << half_way.y + 0.2 << " }";
  crated.insert(world_end, crate.str());
  write_file(dir().file("crated.pbtxt"), crated);
  const auto [other, other_out] = replay("replay-crated", {"--config", dir().file("crated.pbtxt")});
  ASSERT_TRUE(other.has_value()) << other_out;
  EXPECT_TRUE(other->exited && other->code == 1) << other->describe() << "\n" << other_out;
  const std::string said = "replay differs from the recording: autonomy/robot/state at tick ";
  const auto at = other_out.find(said);
  ASSERT_NE(at, std::string::npos) << other_out;
  const int64_t tick = std::stoll(other_out.substr(at + said.size()));
  EXPECT_GT(tick, states.front().tick) << other_out;
  EXPECT_LE(tick, half_way.tick) << other_out;
}

}  // namespace
}  // namespace autonomy::test
