#include "services/courier/core/execution/door_belief.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace autonomy::courier {
namespace {

TEST(DoorBelief, UnseenDoorsAreOpenAndFlipsNeedTheHysteresisBand) {
  DoorBelief doors;
  EXPECT_TRUE(doors.believed_open("A-120"));
  EXPECT_EQ(doors.observe("A-120", 1.2, 10.0, "rhino"), DoorChange::none);
  EXPECT_EQ(doors.observe("A-120", 0.5, 11.0, "rhino"), DoorChange::none);  // inside the band: still open
  EXPECT_EQ(doors.observe("A-120", 0.1, 12.0, "rhino"), DoorChange::closed);
  EXPECT_FALSE(doors.believed_open("A-120"));
  EXPECT_EQ(doors.observe("A-120", 0.5, 13.0, "rhino"), DoorChange::none);  // not wide enough to reopen
  EXPECT_EQ(doors.observe("A-120", -0.9, 14.0, "rhino"), DoorChange::opened);  // either swing
  EXPECT_DOUBLE_EQ(doors.view("A-120")->seen_at_s, 14.0);
  EXPECT_EQ(doors.observe("A-120", std::numeric_limits<double>::quiet_NaN(), 15.0, "rhino"), DoorChange::none);
  EXPECT_DOUBLE_EQ(doors.view("A-120")->seen_at_s, 14.0);
}

TEST(DoorBelief, AFirstSightingClosedIsAChange) {
  DoorBelief doors;
  EXPECT_EQ(doors.observe("A-116", 0.0, 1.0, "r"), DoorChange::closed);
  EXPECT_THROW(DoorBelief(DoorBeliefSettings{0.6, 0.35}), std::invalid_argument);
}

TEST(DoorBelief, AnExpiredClosedSightingIsAssumedOpenUntilSeenAgain) {
  DoorBelief doors;
  doors.observe("A-116", 0.0, 100.0, "r");
  doors.observe("A-120", 0.0, 350.0, "r");
  EXPECT_EQ(doors.expire_closed(400.0 - 100.0 + 1.0), std::vector<std::string>{"A-116"});
  EXPECT_TRUE(doors.believed_open("A-116"));
  EXPECT_TRUE(doors.view("A-116")->open_assumed);
  EXPECT_FALSE(doors.believed_open("A-120"));
  EXPECT_TRUE(doors.expire_closed(301.0).empty());  // expired once, not again
  doors.observe("A-116", 1.0, 500.0, "r");
  EXPECT_FALSE(doors.view("A-116")->open_assumed);  // a sighting replaces the assumption
}

}  // namespace
}  // namespace autonomy::courier
