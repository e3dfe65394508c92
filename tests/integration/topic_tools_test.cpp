// `autonomy topic echo`, `topic type` and `interface show` on a topic whose type is not in the
// project's IDL: ddsperf (Cyclone's tool, a real foreign process) publishes DDSPerfRDataKS of its
// own type KeyedSeq; the tool gets the type from discovery's type information and prints the
// samples' fields; `topic pub` writes that type from JSON; `topic info` names the processes of
// the topic's endpoints and the pairs whose QoS cannot match, `topic bw` measures its bytes, and
// `node info` describes one of our processes (fake_service); `topic echo` reads a type with a
// string key (NavGoal on a topic outside the catalogue) by its discovered type; `topic pub` and
// `topic echo` on a catalogue topic go through the same walker, with the type idlc compiled in.
// Domains 137-139, 179, 199 and 208.
#include <gtest/gtest.h>
#include <unistd.h>

#include <nlohmann/json.hpp>
#include <algorithm>
#include <cmath>
#include <csignal>
#include <regex>
#include <sstream>

#include "common/dds/reader.hpp"
#include "common/dds/topics.hpp"
#include "common/dds/writer.hpp"
#include "tests/support/dds_observer.hpp"
#include "tests/support/process_test.hpp"

namespace autonomy::test {
namespace {

using namespace std::chrono_literals;

constexpr int kDomainForeignPub = 137;
constexpr int kDomainForeignEcho = 138;
constexpr int kDomainForeignType = 139;
constexpr int kDomainInfo = 179;
constexpr int kDomainStringKey = 199;
constexpr int kDomainCatalogue = 208;
constexpr const char* kDdsperf = "/usr/bin/ddsperf";

std::vector<std::string> lines_of(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) lines.push_back(line);
  return lines;
}

class TopicToolsTest : public ProcessTest {
 protected:
  // Runs the tool to its end; returns its stdout lines (stderr goes to <name>.err).
  std::vector<std::string> run_tool(const std::string& name, std::vector<std::string> args, int expected_code = 0) {
    args.insert(args.end(), {"--domain", std::to_string(domain_)});
    auto& tool = start(name, AUTONOMY_AUTONOMY_BIN, args, /*must_keep_running=*/false, /*separate_stderr=*/true);
    const auto ended = tool.wait_for_exit(60s);
    EXPECT_TRUE(ended.has_value()) << name << " did not end";
    if (ended) {
      EXPECT_TRUE(ended->exited && ended->code == expected_code)
          << name << ": " << ended->describe() << "\n" << read_file(dir().file(name + ".err"));
    }
    return lines_of(read_file(tool.log_file()));
  }
  void start_ddsperf(const std::string& rate = "20Hz") {
    // 20 samples/s of 24 bytes (seq, keyval, the baggage length and 12 octets of baggage), for
    // at most 60 s (the test ends it before).
    start("ddsperf", kDdsperf, {"-i", std::to_string(domain_), "-D", "60", "pub", rate, "size", "24"});
  }
};

TEST_F(TopicToolsTest, EchoPrintsTheFieldsOfAForeignType) {
  if (::access(kDdsperf, X_OK) != 0) GTEST_SKIP() << "ddsperf (cyclonedds-tools) is not installed";
  join(kDomainForeignEcho);
  start_ddsperf();
  const auto lines = run_tool("echo", {"topic", "echo", "DDSPerfRDataKS", "--count", "2", "--timeout", "30",
                                       "--discovery-wait", "10"});
  ASSERT_EQ(lines.size(), 2u);
  int64_t previous_seq = -1;
  for (const auto& line : lines) {
    const auto j = nlohmann::json::parse(line);
    ASSERT_TRUE(j.contains("seq") && j["seq"].is_number_unsigned()) << line;
    EXPECT_TRUE(j.contains("keyval") && j["keyval"].is_number()) << line;
    ASSERT_TRUE(j.contains("baggage")) << line;
    EXPECT_EQ(j["baggage"].value("length", 0), 12) << line;
    EXPECT_EQ(j["baggage"].value("base64", "").size(), 16u) << line;  // 12 bytes in base64
    EXPECT_GT(j["seq"].get<int64_t>(), previous_seq) << line;
    previous_seq = j["seq"].get<int64_t>();
  }
  const auto field = run_tool("echo-field", {"topic", "echo", "DDSPerfRDataKS", "--count", "1", "--timeout", "30",
                                             "--field", "baggage", "--bytes", "hex"});
  ASSERT_EQ(field.size(), 1u);
  EXPECT_EQ(nlohmann::json::parse(field[0]).value("hex", "").size(), 24u) << field[0];
  // A member the type does not have: usage error naming it and the nearest member.
  run_tool("echo-bad-field", {"topic", "echo", "DDSPerfRDataKS", "--timeout", "30", "--field", "baggag"}, 2);
  EXPECT_NE(read_file(dir().file("echo-bad-field.err")).find("did you mean baggage"), std::string::npos)
      << read_file(dir().file("echo-bad-field.err"));
}

TEST_F(TopicToolsTest, PubWritesAForeignTypeFromJson) {
  if (::access(kDdsperf, X_OK) != 0) GTEST_SKIP() << "ddsperf (cyclonedds-tools) is not installed";
  join(kDomainForeignPub);
  start_ddsperf("1Hz");  // announces the type; its own samples have keyval 0
  auto& echo = start("echo", AUTONOMY_AUTONOMY_BIN,
                     {"topic", "echo", "DDSPerfRDataKS", "--field", "keyval", "--count", "4", "--timeout", "40",
                      "--discovery-wait", "10", "--domain", std::to_string(domain_)},
                     /*must_keep_running=*/false, /*separate_stderr=*/true);
  run_tool("pub", {"topic", "pub", "DDSPerfRDataKS", R"({"seq":1,"keyval":77,"baggage":{"hex":"0a0b"}})", "--count", "3",
                   "--rate", "5", "--wait", "10"});
  const auto ended = echo.wait_for_exit(60s);
  ASSERT_TRUE(ended.has_value() && ended->exited && ended->code == 0) << read_file(dir().file("echo.err"));
  const auto lines = lines_of(read_file(echo.log_file()));
  EXPECT_NE(std::find(lines.begin(), lines.end(), "77"), lines.end()) << read_file(echo.log_file());
  // JSON that does not fit the type: usage error naming the member.
  run_tool("pub-bad", {"topic", "pub", "DDSPerfRDataKS", R"({"seq":1,"keyval":-1})", "--wait", "10"}, 2);
  EXPECT_NE(read_file(dir().file("pub-bad.err")).find("keyval: -1 is out of range"), std::string::npos)
      << read_file(dir().file("pub-bad.err"));
}

TEST_F(TopicToolsTest, TopicTypeAndInterfaceShowPrintIdl) {
  if (::access(kDdsperf, X_OK) != 0) GTEST_SKIP() << "ddsperf (cyclonedds-tools) is not installed";
  join(kDomainForeignType);
  start_ddsperf();
  const auto idl = run_tool("type", {"topic", "type", "DDSPerfRDataKS", "--discovery-wait", "10"});
  std::string text;
  for (const auto& l : idl) text += l + "\n";
  EXPECT_NE(text.find("struct KeyedSeq {"), std::string::npos) << text;
  EXPECT_NE(text.find("@key uint32 keyval;"), std::string::npos) << text;
  EXPECT_NE(text.find("sequence<octet> baggage;"), std::string::npos) << text;
  const auto ours = run_tool("show", {"interface", "show", "NavGoal", "--discovery-wait", "0"});
  std::string ours_text;
  for (const auto& l : ours) ours_text += l + "\n";
  EXPECT_NE(ours_text.find("@key string robot_id;"), std::string::npos) << ours_text;
  run_tool("unknown", {"topic", "type", "DDSPerfRDataKZ", "--discovery-wait", "1"}, 2);
  EXPECT_NE(read_file(dir().file("unknown.err")).find("did you mean DDSPerfRDataKS"), std::string::npos)
      << read_file(dir().file("unknown.err"));
}

// A string key through the discovered-type path: Cyclone 0.10.2's dds_create_topic_descriptor
// marks such a key fixed-size, and the tool aborted (realloc(): invalid pointer in
// dds_stream_extract_key_from_data) on the first sample. Two instances of NavGoal, written
// transient-local before the tool starts, on a topic name the catalogue does not know.
TEST_F(TopicToolsTest, EchoReadsADiscoveredTypeWithAStringKey) {
  join(kDomainStringKey);
  const dds::TopicSpec<msg::NavGoal> spec{"tools_test/string_key", dds::QosClass::State};
  const dds::Topic<msg::NavGoal> topic(participant(), spec);
  const dds::Writer<msg::NavGoal> writer(participant(), topic);
  // Keys longer than 16 bytes serialized (the fixed-key buffer) and a short one.
  writer.write(msg::NavGoal{"robot-with-a-rather-long-identifier", "g1", 1.5, -2.0, 0.0, ""});
  writer.write(msg::NavGoal{"r2", "g2", 3.0, 4.0, 0.0, ""});
  const auto lines = run_tool("echo-string-key", {"topic", "echo", "tools_test/string_key", "--count", "2",
                                                  "--timeout", "10", "--discovery-wait", "5"});
  ASSERT_EQ(lines.size(), 2u) << read_file(dir().file("echo-string-key.err"));
  std::vector<std::string> robots;
  for (const auto& line : lines) {
    const auto j = nlohmann::json::parse(line);
    robots.push_back(j.value("robot_id", ""));
    const bool short_key = robots.back() == "r2";
    EXPECT_EQ(j.value(short_key ? "y" : "x", 0.0), short_key ? 4.0 : 1.5) << line;
  }
  std::sort(robots.begin(), robots.end());
  EXPECT_EQ(robots, (std::vector<std::string>{"r2", "robot-with-a-rather-long-identifier"}));
}

// ddsperf publishes 50 samples/s of 1000 bytes; this test's process holds a best-effort writer
// and a reliable reader of one topic (a pair that cannot match); fake_service is one of ours.
TEST_F(TopicToolsTest, InfoBwAndNodeInfoNameProcessesAndMeasure) {
  if (::access(kDdsperf, X_OK) != 0) GTEST_SKIP() << "ddsperf (cyclonedds-tools) is not installed";
  join(kDomainInfo);
  auto& fake = start("fake", AUTONOMY_FAKE_SERVICE_BIN,
                     {"--instance", "ti", "--domain", std::to_string(domain_), "--log-dir", dir().path()});
  auto& pub = start("ddsperf", kDdsperf, {"-i", std::to_string(domain_), "-D", "60", "pub", "50Hz", "size", "1000"});
  const dds::TopicSpec<msg::NavGoal> spec{"tools_test/mismatch", dds::QosClass::Stream};
  const dds::Topic<msg::NavGoal> topic(participant(), spec);
  const dds::Writer<msg::NavGoal> best_effort(participant(), topic, dds::QosClass::Stream);
  const dds::Reader<msg::NavGoal> reliable(participant(), topic, dds::QosClass::Event);

  // topic info on ddsperf's topic: its writer is the ddsperf process.
  const auto info = run_tool("info", {"topic", "info", "DDSPerfRDataKS", "--discovery-wait", "1"});
  std::string text;
  for (const auto& l : info) text += l + "\n";
  EXPECT_NE(text.find("Type: KeyedSeq\n"), std::string::npos) << text;
  const auto writers = std::find(info.begin(), info.end(), "Writers: 1");
  ASSERT_TRUE(writers != info.end() && writers + 1 != info.end()) << text;
  EXPECT_EQ(writers[1].find("  ddsperf (pid " + std::to_string(pub.pid()) + " on "), 0u) << text;
  EXPECT_NE(writers[1].find("reliable volatile"), std::string::npos) << text;

  // topic info on the test's own pair: both endpoints named with this process's pid, the pair
  // called out for its reliability.
  const std::string ours = "(pid " + std::to_string(::getpid()) + " on ";
  const auto pair = run_tool("info-mismatch", {"topic", "info", "tools_test/mismatch", "--discovery-wait", "1"});
  std::string pair_text;
  for (const auto& l : pair) pair_text += l + "\n";
  const auto pw = std::find(pair.begin(), pair.end(), "Writers: 1");
  const auto pr = std::find(pair.begin(), pair.end(), "Readers: 1");
  ASSERT_TRUE(pw != pair.end() && pr == pw + 2 && pr + 1 != pair.end()) << pair_text;
  EXPECT_NE(pw[1].find(ours), std::string::npos) << pair_text;
  EXPECT_NE(pw[1].find("best-effort"), std::string::npos) << pair_text;
  EXPECT_NE(pr[1].find(ours), std::string::npos) << pair_text;
  EXPECT_NE(pair_text.find("QoS mismatches (these pairs do not communicate):\n"), std::string::npos) << pair_text;
  EXPECT_NE(pair_text.find(": reliability: the reader requests reliable, the writer offers best-effort\n"),
            std::string::npos)
      << pair_text;

  // topic bw: every sample is 1000 bytes of KeyedSeq plus the 4-byte encapsulation header; the
  // rate is within a factor 1.5 of 50 of them per second.
  const auto bw = run_tool("bw", {"topic", "bw", "DDSPerfRDataKS", "--duration", "3.5", "--discovery-wait", "2"});
  const std::regex report(R"(average: (\d+) B/s \(.*\)  mean: (\d+) B  min: (\d+) B  max: (\d+) B  window: (\d+))");
  int reports = 0;
  for (const auto& l : bw) {
    std::smatch m;
    if (!std::regex_match(l, m, report)) continue;
    ++reports;
    EXPECT_EQ(m[2].str(), "1004") << l;
    EXPECT_EQ(m[3].str(), "1004") << l;
    EXPECT_EQ(m[4].str(), "1004") << l;
    if (std::stoi(m[5].str()) >= 20) {  // a rate over at least 19 intervals
      const double rate = std::stod(m[1].str());
      EXPECT_GT(rate, 50 * 1004 / 1.5) << l;
      EXPECT_LT(rate, 50 * 1004 * 1.5) << l;
    }
  }
  EXPECT_GE(reports, 2) << ::testing::PrintToString(bw);

  // node info: fake_service's pid and host, and the topics it writes and reads.
  const auto node = run_tool("node-info", {"node", "info", "fake/ti", "--wait", "5"});
  std::string node_text;
  for (const auto& l : node) node_text += l + "\n";
  EXPECT_NE(node_text.find("node: fake/ti\n"), std::string::npos) << node_text;
  EXPECT_NE(node_text.find("\n  pid: " + std::to_string(fake.pid()) + "\n"), std::string::npos) << node_text;
  EXPECT_NE(node_text.find("\n  program: fake_service\n"), std::string::npos) << node_text;
  const auto writes = node_text.find("  writes (");
  const auto reads = node_text.find("  reads (");
  ASSERT_TRUE(writes != std::string::npos && reads != std::string::npos && writes < reads) << node_text;
  const std::string written = node_text.substr(writes, reads - writes);
  EXPECT_NE(written.find("\n    autonomy/heartbeat  autonomy::Heartbeat  reliable transient-local"), std::string::npos)
      << node_text;
  EXPECT_NE(written.find("\n    autonomy/nav/goal_status  autonomy::GoalStatus  reliable transient-local"),
            std::string::npos)
      << node_text;
  EXPECT_EQ(node_text.find("DDSPerf"), std::string::npos) << node_text;  // ddsperf's are not fake's
  // An unknown name: usage error naming the nearest process.
  run_tool("node-unknown", {"node", "info", "fake/tj", "--wait", "1"}, 2);
  EXPECT_NE(read_file(dir().file("node-unknown.err")).find("did you mean fake/ti?"), std::string::npos)
      << read_file(dir().file("node-unknown.err"));
}

// A catalogue topic: pub checks and serializes the JSON by the type idlc compiled in (the walker's
// inverse), a typed reader of the project gets the values, echo prints them back by the walker.
TEST_F(TopicToolsTest, PubAndEchoOnACatalogueTopicGoThroughTheWalker) {
  join(kDomainCatalogue);
  Recorder<msg::GoalStatus> statuses(participant(), dds::topics::goal_status);
  auto& echo = start("echo", AUTONOMY_AUTONOMY_BIN,
                     {"topic", "echo", "autonomy/nav/goal_status", "--count", "1", "--timeout", "40", "--domain",
                      std::to_string(domain_)},
                     /*must_keep_running=*/false, /*separate_stderr=*/true);
  // A writer that writes nothing, to see echo's reader matched (beside the recorder) before pub
  // publishes.
  const dds::Topic<msg::GoalStatus> topic(participant(), dds::topics::goal_status);
  const dds::Writer<msg::GoalStatus> probe(participant(), topic);
  ASSERT_TRUE(await("echo's reader", [&] { return probe.matched_readers() >= 2; }));
  // pub stays up (--count 0, once a second) until echo has its sample: echo's reader matched the
  // probe, but it may match pub's own writer only after a pub that exited at once was gone with
  // its transient-local sample (seen under ASan, where every start is slower).
  auto& pub = start("pub", AUTONOMY_AUTONOMY_BIN,
                    {"topic", "pub", "autonomy/nav/goal_status",
                     R"({"robot_id":"r1","goal_id":"g1","state":"preempted","tick":12.0,"distance_to_goal":"inf"})",
                     "--wait", "10", "--count", "0", "--rate", "1", "--domain", std::to_string(domain_)},
                    /*must_keep_running=*/false, /*separate_stderr=*/true);
  ASSERT_TRUE(await("the status in the typed reader", [&] { return !statuses.poll().empty() || !statuses.all().empty(); }));
  const msg::GoalStatus& got = statuses.all().front();
  EXPECT_EQ(got.robot_id, "r1");
  EXPECT_EQ(got.goal_id, "g1");
  EXPECT_EQ(got.state, msg::GoalState::Preempted);
  EXPECT_EQ(got.tick, 12);
  EXPECT_TRUE(std::isinf(got.distance_to_goal) && got.distance_to_goal > 0);
  EXPECT_EQ(got.reason, "");  // left out: empty

  const auto ended = echo.wait_for_exit(60s);
  pub.signal(SIGINT);
  const auto pub_ended = pub.wait_for_exit(20s);
  EXPECT_TRUE(pub_ended.has_value() && pub_ended->exited && pub_ended->code == 0) << read_file(dir().file("pub.err"));
  ASSERT_TRUE(ended.has_value() && ended->exited && ended->code == 0) << read_file(dir().file("echo.err"));
  const auto lines = lines_of(read_file(echo.log_file()));
  ASSERT_EQ(lines.size(), 1u) << read_file(echo.log_file());
  EXPECT_EQ(lines[0], R"({"robot_id":"r1","goal_id":"g1","state":"preempted","reason":"","tick":12,"distance_to_goal":"inf"})");

  // JSON that does not fit: exit 2, the member path, what was expected and found, the type's members.
  run_tool("pub-enum", {"topic", "pub", "autonomy/nav/goal_status", R"({"robot_id":"r1","state":"lost"})", "--wait", "0"}, 2);
  const std::string enum_error = read_file(dir().file("pub-enum.err"));
  EXPECT_NE(enum_error.find("state: expected one of accepted, active, reached, blocked, preempted, rejected, cancelled, "
                            "got string \"lost\""),
            std::string::npos)
      << enum_error;
  EXPECT_NE(enum_error.find("autonomy/nav/goal_status carries autonomy::GoalStatus {@key robot_id, goal_id, state, "
                            "reason, tick, distance_to_goal}"),
            std::string::npos)
      << enum_error;
  run_tool("pub-key", {"topic", "pub", "autonomy/nav/goal_status", R"({"goal_id":"g1"})", "--wait", "0"}, 2);
  EXPECT_NE(read_file(dir().file("pub-key.err")).find("robot_id: missing key member"), std::string::npos)
      << read_file(dir().file("pub-key.err"));
}

}  // namespace
}  // namespace autonomy::test
