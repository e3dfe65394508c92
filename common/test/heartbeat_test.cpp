// The heartbeat publisher (common/service/heartbeat.hpp). Domains 106-107, one per test.
#include "common/dds/reader.hpp"
#include "common/service/heartbeat.hpp"
#include "common/test/test_support.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <unistd.h>

namespace autonomy::service {
namespace {

using namespace std::chrono_literals;

class HeartbeatTest : public ::testing::Test {
 protected:
  void SetUp() override { test::use_loopback_profile(); }
};

std::vector<dds::Sample<msg::Heartbeat>> take_at_least(const dds::Reader<msg::Heartbeat>& reader, size_t n) {
  std::vector<dds::Sample<msg::Heartbeat>> all;
  test::eventually([&] {
    for (auto& s : reader.take()) all.push_back(std::move(s));
    return all.size() >= n;
  });
  return all;
}

TEST_F(HeartbeatTest, PublishesWhoAndWhere) {
  dds::Participant p(106);
  dds::Topic<msg::Heartbeat> topic(p, dds::topics::heartbeat);
  dds::Reader<msg::Heartbeat> reader(p, topic);
  HeartbeatPublisher hb(p, "tester", "inst-\xC3\xA9", 250ms);
  EXPECT_EQ(hb.period(), 250ms);

  hb.publish();
  const auto got = take_at_least(reader, 1);
  ASSERT_EQ(got.size(), 1u);
  const auto& b = got[0].value;
  EXPECT_TRUE(got[0].valid);
  EXPECT_EQ(b.service, "tester");
  EXPECT_EQ(b.instance, "inst-\xC3\xA9");
  EXPECT_EQ(b.pid, static_cast<int32_t>(::getpid()));
  EXPECT_EQ(b.host, host_name());
  EXPECT_FALSE(b.host.empty());
  EXPECT_EQ(b.period_ms, 250u);
  EXPECT_EQ(b.state, msg::ServiceState::Starting);
  EXPECT_GE(b.uptime_s, 0.0);
  EXPECT_LT(b.uptime_s, 5.0);

  // Uptime grows from one beat to the next.
  std::this_thread::sleep_for(20ms);
  hb.publish();
  const auto next = take_at_least(reader, 1);
  ASSERT_EQ(next.size(), 1u);
  EXPECT_GE(next[0].value.uptime_s - b.uptime_s, 0.015);
}

TEST_F(HeartbeatTest, StateChangeIsPublishedAtOnceAndStopDisposes) {
  dds::Participant p(107);
  dds::Topic<msg::Heartbeat> topic(p, dds::topics::heartbeat);
  dds::Reader<msg::Heartbeat> reader(p, topic);
  auto publisher = std::make_unique<HeartbeatPublisher>(p, "svc", "main", 10s);  // a period no test waits for
  auto& hb = *publisher;
  EXPECT_TRUE(reader.take().empty());

  hb.set_state(msg::ServiceState::Ready);
  auto got = take_at_least(reader, 1);
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0].value.state, msg::ServiceState::Ready);
  EXPECT_EQ(got[0].value.service, "svc");
  EXPECT_EQ(got[0].value.instance, "main");

  // The same state again is not a change: nothing published.
  hb.set_state(msg::ServiceState::Ready);
  std::this_thread::sleep_for(30ms);
  EXPECT_TRUE(reader.take().empty());

  // Capabilities (a behavior that is a courier): published at once, and carried by later beats.
  hb.set_capabilities({"courier"});
  got = take_at_least(reader, 1);
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0].value.capabilities, std::vector<std::string>{"courier"});
  hb.set_capabilities({"courier"});
  std::this_thread::sleep_for(30ms);
  EXPECT_TRUE(reader.take().empty());

  hb.set_state(msg::ServiceState::Stopping);
  got = take_at_least(reader, 1);
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0].value.state, msg::ServiceState::Stopping);
  EXPECT_EQ(got[0].value.capabilities, std::vector<std::string>{"courier"});

  // A clean stop: destroying the publisher disposes the instance, so readers see it disposed
  // (not lost after the lease), with both key fields.
  publisher.reset();
  got = take_at_least(reader, 1);
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0].instance_state, dds::InstanceState::Disposed);
  EXPECT_EQ(got[0].value.service, "svc");
  EXPECT_EQ(got[0].value.instance, "main");
}

}  // namespace
}  // namespace autonomy::service
