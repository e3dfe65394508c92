// Recording support: each catalogue type's schema is one self-contained IDL text; QoS survives the
// trip through channel metadata; a sample taken as CDR (header as on the wire) decodes to the
// value that was written, and a RawWriter republishes it to typed readers unchanged (DDS on
// loopback, domain 196).
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <thread>

#include "common/dds/reader.hpp"
#include "common/dds/topics.hpp"
#include "common/dds/writer.hpp"
#include "tools/autonomy/suggest.hpp"
#include "tools/recording/idl_text.hpp"
#include "tools/recording/raw_topic.hpp"

namespace autonomy::recording {
namespace {

constexpr int kDomain = 196;

template <typename Pred>
bool eventually(Pred pred) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  while (std::chrono::steady_clock::now() < deadline) {
    if (pred()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return pred();
}

TEST(IdlSchema, ATypeGetsTheTextOfItsFileWithoutPreprocessorLines) {
  const auto s = omgidl_schema("autonomy::NavGoal");
  EXPECT_NE(s.find("struct NavGoal"), std::string::npos);
  EXPECT_NE(s.find("module autonomy"), std::string::npos);
  EXPECT_EQ(s.find("\n#"), std::string::npos);
  EXPECT_THROW(omgidl_schema("autonomy::NoSuchType"), std::runtime_error);
  // A name that only appears inside another identifier is not a declaration.
  EXPECT_THROW(omgidl_schema("autonomy::Goal"), std::runtime_error);
}

TEST(IdlSchema, EveryCatalogueTypeHasASchema) {
  ASSERT_GT(recordable_topics().size(), 40u);
  for (const auto& t : recordable_topics()) {
    std::string schema;
    EXPECT_NO_THROW(schema = omgidl_schema(t.type_name)) << t.name;
    const auto simple = t.type_name.substr(t.type_name.rfind("::") + 2);
    EXPECT_NE(schema.find(simple), std::string::npos) << t.name;
  }
  EXPECT_EQ(find_recordable("autonomy/nav/goal")->type_name, "autonomy::NavGoal");
  EXPECT_EQ(find_recordable("no/such/topic"), nullptr);
}

TEST(QosMetadata, EveryClassSurvivesTheRoundTrip) {
  for (auto cls : {dds::QosClass::State, dds::QosClass::Stream, dds::QosClass::Command, dds::QosClass::Event,
                   dds::QosClass::Queue}) {
    const auto q = dds::make_qos(cls);
    const auto m = qos_metadata(q.get(), cls);
    EXPECT_EQ(m.at("qos_class"), dds::to_string(cls));
    const auto back = qos_from_metadata(m);
    EXPECT_EQ(qos_metadata(back.get(), cls), m);
  }
  const auto state = qos_metadata(dds::make_qos(dds::QosClass::State).get(), dds::QosClass::State);
  EXPECT_EQ(state.at("durability"), "transient-local");
  EXPECT_EQ(state.at("reliability"), "reliable");
  EXPECT_EQ(state.at("depth"), "1");
  auto bad = state;
  bad["reliability"] = "sometimes";
  try {
    qos_from_metadata(bad);
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("reliability=\"sometimes\""), std::string::npos) << e.what();
  }
  bad.erase("reliability");
  EXPECT_THROW(qos_from_metadata(bad), std::runtime_error);
}

TEST(RawTopic, TakenCdrDecodesAndRepublishesUnchanged) {
  ::setenv("CYCLONEDDS_URI", AUTONOMY_LOOPBACK_URI, 1);
  dds::Participant p(kDomain);
  const auto& goal = *find_recordable("autonomy/nav/goal");
  RawReader raw_reader(p, goal);
  dds::Topic<msg::NavGoal> topic(p, dds::topics::nav_goal);
  dds::Writer<msg::NavGoal> typed_writer(p, topic);
  const msg::NavGoal sent{"r1", "g-42", 18.5, -2.25, 0.3, "obstacles"};
  std::vector<RawSample> got;
  ASSERT_TRUE(eventually([&] {
    if (got.empty()) typed_writer.write(sent);
    raw_reader.take(got);
    return !got.empty();
  }));
  const auto& cdr = got.front().cdr;
  ASSERT_GE(cdr.size(), 8u);
  EXPECT_EQ(cdr[0], 0);  // CDR_LE, XCDR1: final types on the wire
  EXPECT_EQ(cdr[1], 1);
  EXPECT_GT(got.front().source_timestamp, 0);
  EXPECT_GE(got.front().reception_time, got.front().source_timestamp);

  DecodedSample decoded(goal.descriptor, cdr);
  const auto value = dds::DdsType<msg::NavGoal>::from_c(*static_cast<const autonomy_NavGoal*>(decoded.get()));
  EXPECT_EQ(value.goal_id, "g-42");
  EXPECT_EQ(value.y, -2.25);
  EXPECT_EQ(value.constraint_set, "obstacles");

  EXPECT_THROW(DecodedSample(goal.descriptor, cdr.substr(0, cdr.size() - 6)), std::runtime_error);
  EXPECT_THROW(DecodedSample(goal.descriptor, "\x00\x01"), std::runtime_error);

  // Republished from the bytes: a typed reader gets the same value.
  dds::Participant p2(kDomain);
  dds::Topic<msg::NavGoal> topic2(p2, dds::topics::nav_goal);
  dds::Reader<msg::NavGoal> typed_reader(p2, topic2);
  const auto q = qos_from_metadata(qos_metadata(dds::make_qos(goal.qos).get(), goal.qos));
  RawWriter raw_writer(p2, goal, q.get());
  std::vector<msg::NavGoal> received;
  ASSERT_TRUE(eventually([&] {
    if (received.empty() && raw_writer.matched_readers() > 0) raw_writer.write(cdr);
    for (auto& s : typed_reader.take())
      if (s.valid && s.value.goal_id == "g-42") received.push_back(s.value);
    return !received.empty();
  }));
  EXPECT_EQ(received.front().robot_id, "r1");
  EXPECT_EQ(received.front().x, 18.5);
  EXPECT_EQ(received.front().tolerance, 0.3);
}

// The CLI's "did you mean" for recorded and catalogue topics and command words.
TEST(Suggest, NamesTheNearestTopicsAndCommands) {
  using tools::nearest;
  std::vector<std::string> topics;
  for (const auto& t : recordable_topics()) topics.push_back(t.name);
  EXPECT_EQ(nearest("autonomy/robot/stat", topics, 1), std::vector<std::string>{"autonomy/robot/state"});
  const auto goal = nearest("goal", topics, 2);
  ASSERT_EQ(goal.size(), 2u);
  EXPECT_EQ(goal[0], "autonomy/nav/goal");
  EXPECT_EQ(nearest("lst", {"list", "echo", "hz", "pub"}), std::vector<std::string>{"list"});
  EXPECT_TRUE(nearest("xyzzy", topics).empty());
  const auto text = tools::unknown_topic_message("autonomy topic echo", "autonomy/nav/gaol", topics);
  EXPECT_NE(text.find("did you mean autonomy/nav/goal"), std::string::npos) << text;
  EXPECT_EQ(text.find("autonomy/heartbeat"), std::string::npos) << "lists far names: " << text;
}

}  // namespace
}  // namespace autonomy::recording
