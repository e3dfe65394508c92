// WaitSet (common/dds/waitset.hpp): which conditions it reports, with a timeout and without.
// Domain 105 (participants without topics cannot disturb each other; shared with the event loop's
// stop tests).
#include "common/dds/waitset.hpp"
#include "common/test/test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <optional>
#include <vector>

namespace autonomy::dds {
namespace {

using namespace std::chrono_literals;

class WaitSetTest : public ::testing::Test {
 protected:
  void SetUp() override { test::use_loopback_profile(); }
};

std::vector<dds_attach_t> sorted(std::vector<dds_attach_t> v) {
  std::sort(v.begin(), v.end());
  return v;
}

// A zero timeout answers from the conditions' trigger state (no timed wait): the same conditions
// as a waiting call, in the order they were attached.
TEST_F(WaitSetTest, ZeroTimeoutReportsTheTriggeredConditionsInAttachOrder) {
  Participant p(105);
  WaitSet ws(p);
  GuardCondition a(p), b(p), c(p);
  ws.attach(a.handle(), 7);
  ws.attach(b.handle(), 3);
  ws.attach(c.handle(), 5);
  EXPECT_TRUE(ws.wait(0ns).empty());

  c.trigger();
  b.trigger();
  EXPECT_EQ(ws.wait(0ns), (std::vector<dds_attach_t>{3, 5}));
  EXPECT_EQ(sorted(ws.wait(100ms)), (std::vector<dds_attach_t>{3, 5}));
  EXPECT_EQ(ws.wait(-1ns), (std::vector<dds_attach_t>{3, 5}));  // negative: as zero

  b.reset();
  EXPECT_EQ(ws.wait(0ns), (std::vector<dds_attach_t>{5}));
  ws.detach(c.handle());
  EXPECT_TRUE(ws.wait(0ns).empty()) << "a detached condition is not reported, triggered or not";
  a.trigger();
  EXPECT_EQ(ws.wait(0ns), (std::vector<dds_attach_t>{7}));
}

// Cyclone detaches a deleted condition from its waitsets; a zero timeout then leaves it out too
// (its handle is no longer valid), without an error.
TEST_F(WaitSetTest, AConditionDeletedWhileAttachedIsLeftOut) {
  Participant p(105);
  WaitSet ws(p);
  GuardCondition kept(p);
  std::optional<GuardCondition> deleted(std::in_place, p);
  ws.attach(deleted->handle(), 1);
  ws.attach(kept.handle(), 2);
  deleted->trigger();
  kept.trigger();
  EXPECT_EQ(ws.wait(0ns), (std::vector<dds_attach_t>{1, 2}));
  deleted.reset();
  EXPECT_EQ(ws.wait(0ns), (std::vector<dds_attach_t>{2}));
  EXPECT_EQ(ws.wait(100ms), (std::vector<dds_attach_t>{2}));
}

}  // namespace
}  // namespace autonomy::dds
