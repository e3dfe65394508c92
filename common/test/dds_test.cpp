// The RAII layer over Cyclone with real participants on the loopback profile: typed write/take,
// transient-local state for late joiners, dispose, errors. Each test uses its own domain
// (100-109) so that ctest -j can run them side by side.
#include "common/dds/error.hpp"
#include "common/dds/participant.hpp"
#include "common/dds/reader.hpp"
#include "common/dds/topics.hpp"
#include "common/dds/writer.hpp"
#include "common/test/test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <string>

namespace autonomy::dds {
namespace {

using test::eventually;
using test::fields;
using test::Variant;

class DdsTest : public ::testing::Test {
 protected:
  void SetUp() override { test::use_loopback_profile(); }
};

// Takes from reader until at least n samples arrived or 2 s passed.
template <typename T>
std::vector<Sample<T>> take_at_least(const Reader<T>& reader, size_t n) {
  std::vector<Sample<T>> all;
  eventually([&] {
    for (auto& s : reader.take()) all.push_back(std::move(s));
    return all.size() >= n;
  });
  return all;
}

TEST_F(DdsTest, RobotStateWriteTakeRoundTrip) {
  Participant p(100);
  EXPECT_EQ(p.domain(), 100u);
  EXPECT_GT(p.handle(), 0);
  Topic<msg::RobotState> topic(p, topics::robot_state);
  Reader<msg::RobotState> reader(p, topic);
  Writer<msg::RobotState> writer(p, topic);
  ASSERT_TRUE(writer.wait_for_readers(1, std::chrono::seconds(2)));
  EXPECT_EQ(reader.matched_writers(), 1u);

  const auto sent = test::make_robot_state(Variant::Full);
  writer.write(sent);
  const auto got = take_at_least(reader, 1);
  ASSERT_EQ(got.size(), 1u);
  EXPECT_TRUE(got[0].valid);
  EXPECT_EQ(got[0].instance_state, InstanceState::Alive);
  EXPECT_EQ(fields(got[0].value), fields(sent));
  EXPECT_GT(got[0].source_timestamp, 0);
  EXPECT_NE(got[0].publication_handle, 0u);

  // take() removed it: nothing left.
  EXPECT_TRUE(reader.take().empty());

  // read() leaves the sample in the reader, take() removes it.
  auto second = sent;
  second.robot_id = "read-me";
  writer.write(second);
  ASSERT_TRUE(eventually([&] { return reader.read().size() == 1; }));
  const auto again = reader.read();
  ASSERT_EQ(again.size(), 1u);
  EXPECT_EQ(again[0].value.robot_id, "read-me");
  EXPECT_EQ(reader.take().size(), 1u);
  EXPECT_TRUE(reader.read().empty());
}

TEST_F(DdsTest, LateJoinerGetsTheLastStateOfEveryKey) {
  Participant writer_side(101);
  Topic<msg::RobotState> wtopic(writer_side, topics::robot_state);
  Writer<msg::RobotState> writer(writer_side, wtopic);
  auto state = test::make_robot_state(Variant::Full);
  for (int tick = 1; tick <= 3; ++tick) {
    state.robot_id = "r1";
    state.tick = tick;
    writer.write(state);
    state.robot_id = "r2";
    state.tick = 100 + tick;
    writer.write(state);
  }

  // The reader joins after every sample was written, from another participant.
  Participant reader_side(101);
  Topic<msg::RobotState> rtopic(reader_side, topics::robot_state);
  Reader<msg::RobotState> reader(reader_side, rtopic);
  const auto got = take_at_least(reader, 2);
  std::this_thread::sleep_for(std::chrono::milliseconds(50));  // anything more would be a bug
  auto rest = reader.take();
  ASSERT_TRUE(rest.empty()) << rest.size() << " extra samples";

  std::map<std::string, int64_t> last;
  for (const auto& s : got) {
    EXPECT_TRUE(s.valid);
    EXPECT_TRUE(last.emplace(s.value.robot_id, s.value.tick).second) << "two samples for " << s.value.robot_id;
    EXPECT_EQ(fields(s.value), fields([&] {
                auto v = state;
                v.robot_id = s.value.robot_id;
                v.tick = s.value.tick;
                return v;
              }()));
  }
  EXPECT_EQ(last, (std::map<std::string, int64_t>{{"r1", 3}, {"r2", 103}}));
}

TEST_F(DdsTest, DisposeIsSeenWithTheKey) {
  Participant p(102);
  Topic<msg::RobotState> topic(p, topics::robot_state);
  Reader<msg::RobotState> reader(p, topic);
  Writer<msg::RobotState> writer(p, topic);
  ASSERT_TRUE(writer.wait_for_readers(1, std::chrono::seconds(2)));

  auto a = test::make_robot_state(Variant::Full);
  a.robot_id = "gone-\xC3\xA9";
  auto b = a;
  b.robot_id = "stays";
  writer.write(a);
  writer.write(b);
  ASSERT_EQ(take_at_least(reader, 2).size(), 2u);

  msg::RobotState key;
  key.robot_id = a.robot_id;
  writer.dispose(key);
  const auto got = take_at_least(reader, 1);
  ASSERT_EQ(got.size(), 1u);
  EXPECT_FALSE(got[0].valid);
  EXPECT_EQ(got[0].instance_state, InstanceState::Disposed);
  EXPECT_EQ(got[0].value.robot_id, a.robot_id);

  // The other instance is untouched: a new sample for it is alive.
  writer.write(b);
  const auto alive = take_at_least(reader, 1);
  ASSERT_EQ(alive.size(), 1u);
  EXPECT_EQ(alive[0].value.robot_id, "stays");
  EXPECT_EQ(alive[0].instance_state, InstanceState::Alive);

  // A type with two key fields: the disposed sample carries both.
  Topic<msg::Heartbeat> hb_topic(p, topics::heartbeat);
  Reader<msg::Heartbeat> hb_reader(p, hb_topic);
  Writer<msg::Heartbeat> hb_writer(p, hb_topic);
  ASSERT_TRUE(hb_writer.wait_for_readers(1, std::chrono::seconds(2)));
  const auto hb = test::make_heartbeat(Variant::Full);
  hb_writer.write(hb);
  ASSERT_EQ(take_at_least(hb_reader, 1).size(), 1u);
  hb_writer.dispose(hb);
  const auto hb_got = take_at_least(hb_reader, 1);
  ASSERT_EQ(hb_got.size(), 1u);
  EXPECT_FALSE(hb_got[0].valid);
  EXPECT_EQ(hb_got[0].instance_state, InstanceState::Disposed);
  EXPECT_EQ(hb_got[0].value.service, hb.service);
  EXPECT_EQ(hb_got[0].value.instance, hb.instance);
}

TEST_F(DdsTest, BadDomainThrowsDdsErrorWithCycloneText) {
  try {
    Participant p(300);
    FAIL() << "a participant on domain 300 was created";
  } catch (const DdsError& e) {
    EXPECT_LT(e.code(), 0);
    const std::string what = e.what();
    EXPECT_NE(what.find("dds_create_participant"), std::string::npos) << what;
    EXPECT_NE(what.find(dds_strretcode(e.code())), std::string::npos) << what;
  }
}

TEST(DdsErrorTest, CheckPassesNonNegativeAndThrowsNegative) {
  EXPECT_EQ(check(0, "x"), 0);
  EXPECT_EQ(check(17, "x"), 17);
  try {
    check(DDS_RETCODE_BAD_PARAMETER, "dds_frobnicate");
    FAIL() << "no throw";
  } catch (const DdsError& e) {
    EXPECT_EQ(e.code(), DDS_RETCODE_BAD_PARAMETER);
    EXPECT_EQ(std::string(e.what()), std::string("dds_frobnicate: ") + dds_strretcode(DDS_RETCODE_BAD_PARAMETER));
  }
}

TEST(EntityTest, MoveTransfersOwnership) {
  Entity a;
  EXPECT_FALSE(a);
  Entity b(12345);  // not a real handle: reset() tolerates that
  EXPECT_TRUE(b);
  a = std::move(b);
  EXPECT_EQ(a.handle(), 12345);
  EXPECT_FALSE(b);  // NOLINT(bugprone-use-after-move): the moved-from state is specified
  Entity c(std::move(a));
  EXPECT_EQ(c.handle(), 12345);
  EXPECT_EQ(a.handle(), 0);  // NOLINT(bugprone-use-after-move)
  c.reset();
  EXPECT_FALSE(c);
}

// Every message type through Cyclone's serializer and back, both variants.
template <typename T>
void expect_wire_round_trip(const Participant& p, const TopicSpec<T>& spec, const T& full, const T& empty) {
  SCOPED_TRACE(spec.name);
  Topic<T> topic(p, spec);
  Reader<T> reader(p, topic);
  Writer<T> writer(p, topic);
  ASSERT_TRUE(writer.wait_for_readers(1, std::chrono::seconds(2)));
  for (const T* v : {&full, &empty}) {
    writer.write(*v);
    const auto got = take_at_least(reader, 1);
    ASSERT_EQ(got.size(), 1u);
    EXPECT_TRUE(got[0].valid);
    EXPECT_EQ(fields(got[0].value), fields(*v));
  }
}

TEST_F(DdsTest, EveryMessageSurvivesTheWire) {
  Participant p(108);
  expect_wire_round_trip(p, topics::heartbeat, test::make_heartbeat(Variant::Full), test::make_heartbeat(Variant::Empty));
  expect_wire_round_trip(p, topics::clock, test::make_sim_clock(Variant::Full), test::make_sim_clock(Variant::Empty));
  expect_wire_round_trip(p, topics::lockstep_registration, test::make_registration(Variant::Full),
                         test::make_registration(Variant::Empty));
  expect_wire_round_trip(p, topics::tick_ack, test::make_tick_ack(Variant::Full), test::make_tick_ack(Variant::Empty));
  expect_wire_round_trip(p, topics::robot_state, test::make_robot_state(Variant::Full),
                         test::make_robot_state(Variant::Empty));
  expect_wire_round_trip(p, topics::cmd_vel, test::make_velocity_command(Variant::Full),
                         test::make_velocity_command(Variant::Empty));
  expect_wire_round_trip(p, topics::command_rejected, test::make_command_rejection(Variant::Full),
                         test::make_command_rejection(Variant::Empty));
  expect_wire_round_trip(p, topics::spawn_request, test::make_spawn_request(Variant::Full),
                         test::make_spawn_request(Variant::Empty));
  expect_wire_round_trip(p, topics::spawn_reply, test::make_spawn_reply(Variant::Full),
                         test::make_spawn_reply(Variant::Empty));
  expect_wire_round_trip(p, topics::world_map, test::make_world_map(Variant::Full), test::make_world_map(Variant::Empty));
  expect_wire_round_trip(p, topics::sim_status, test::make_sim_status(Variant::Full),
                         test::make_sim_status(Variant::Empty));
  expect_wire_round_trip(p, topics::nav_goal, test::make_nav_goal(Variant::Full), test::make_nav_goal(Variant::Empty));
  expect_wire_round_trip(p, topics::goal_status, test::make_goal_status(Variant::Full),
                         test::make_goal_status(Variant::Empty));
  expect_wire_round_trip(p, topics::nav_cancel, test::make_nav_cancel(Variant::Full),
                         test::make_nav_cancel(Variant::Empty));
  expect_wire_round_trip(p, topics::mission_status, test::make_mission_status(Variant::Full),
                         test::make_mission_status(Variant::Empty));
  expect_wire_round_trip(p, topics::range_scan, test::make_range_scan(Variant::Full),
                         test::make_range_scan(Variant::Empty));
  expect_wire_round_trip(p, topics::pose_estimate, test::make_pose_estimate(Variant::Full),
                         test::make_pose_estimate(Variant::Empty));
  expect_wire_round_trip(p, topics::door_observation, test::make_door_observation(Variant::Full),
                         test::make_door_observation(Variant::Empty));
  expect_wire_round_trip(p, topics::truth_door, test::make_door_state(Variant::Full),
                         test::make_door_state(Variant::Empty));
  expect_wire_round_trip(p, topics::radio_link, test::make_radio_link(Variant::Full),
                         test::make_radio_link(Variant::Empty));
  expect_wire_round_trip(p, topics::radio_team, test::make_team_connectivity(Variant::Full),
                         test::make_team_connectivity(Variant::Empty));
  expect_wire_round_trip(p, topics::team_outbox, test::make_team_message(Variant::Full),
                         test::make_team_message(Variant::Empty));
  expect_wire_round_trip(p, topics::team_inbox, test::make_team_delivery(Variant::Full),
                         test::make_team_delivery(Variant::Empty));
  expect_wire_round_trip(p, topics::door_command, test::make_door_command(Variant::Full),
                         test::make_door_command(Variant::Empty));
}

// A reader of another QoS class: a volatile reader on a state topic still gets live samples,
// so tools can watch any topic.
TEST_F(DdsTest, ReaderOfAnotherClassMatches) {
  Participant p(109);
  Topic<msg::SimulatorStatus> topic(p, topics::sim_status);
  Writer<msg::SimulatorStatus> writer(p, topic);
  Reader<msg::SimulatorStatus> reader(p, topic, QosClass::Event);
  ASSERT_TRUE(writer.wait_for_readers(1, std::chrono::seconds(2)));
  writer.write(test::make_sim_status(Variant::Full));
  const auto got = take_at_least(reader, 1);
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0].value.commands_applied, 10'000'000'000ull);
}

}  // namespace
}  // namespace autonomy::dds
