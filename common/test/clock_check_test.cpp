// The clock check every service applies to autonomy/clock (common/clock/clock_check.hpp).
#include "common/clock/clock_check.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace autonomy::clock {
namespace {

constexpr int64_t kStep = 100'000'000;  // 0.1 s
constexpr uint64_t kWorld = 0x1234'5678'9abc'def0ULL;

ClockReading at(int64_t tick, uint64_t world = kWorld) { return {world, tick, tick * kStep, kStep}; }

TEST(ClockCheckTest, FirstClockJoinsItsWorld) {
  ClockCheck c;
  EXPECT_FALSE(c.world());
  EXPECT_EQ(c.check(at(40), 0), ClockVerdict::Follow);
  ASSERT_TRUE(c.world());
  EXPECT_EQ(*c.world(), kWorld);
  EXPECT_EQ(c.tick(), 40);
  EXPECT_EQ(c.counts().ignored(), 0u);
}

TEST(ClockCheckTest, AnotherWorldsClockIsIgnoredAndCounted) {
  ClockCheck c;
  ASSERT_EQ(c.check(at(5), 0), ClockVerdict::Follow);
  EXPECT_EQ(c.check(at(6, kWorld + 1), 0), ClockVerdict::OtherWorld);
  EXPECT_EQ(c.check(at(700, 0), 0), ClockVerdict::OtherWorld);
  EXPECT_EQ(c.tick(), 5);
  EXPECT_EQ(c.counts().other_world, 2u);
  // Its own world goes on as if nothing happened.
  EXPECT_EQ(c.check(at(6), 0), ClockVerdict::Follow);
  EXPECT_EQ(c.tick(), 6);
  EXPECT_EQ(*c.world(), kWorld);
}

TEST(ClockCheckTest, RepeatedTickIsNotCounted) {
  ClockCheck c;
  ASSERT_EQ(c.check(at(5), 0), ClockVerdict::Follow);
  EXPECT_EQ(c.check(at(5), 0), ClockVerdict::Repeated);
  EXPECT_EQ(c.counts().ignored(), 0u);
}

TEST(ClockCheckTest, BackwardsTickIsIgnoredAndCounted) {
  ClockCheck c;
  ASSERT_EQ(c.check(at(50), 0), ClockVerdict::Follow);
  EXPECT_EQ(c.check(at(49), 0), ClockVerdict::Backwards);
  EXPECT_EQ(c.check(at(0), 0), ClockVerdict::Backwards);
  EXPECT_EQ(c.counts().backwards, 2u);
  EXPECT_EQ(c.tick(), 50);
}

TEST(ClockCheckTest, ForgedMaximalTickIsALeapAndLaterTicksStillCount) {
  ClockCheck c;
  ASSERT_EQ(c.check(at(10), 0), ClockVerdict::Follow);
  const int64_t max = std::numeric_limits<int64_t>::max();
  // The forged sample of issue 22: tick 2^63-1, whatever time it claims.
  EXPECT_EQ(c.check({kWorld, max, 11 * kStep, kStep}, 0), ClockVerdict::Malformed);
  EXPECT_EQ(c.check({kWorld, max, max, 1}, 0), ClockVerdict::Leap);
  EXPECT_EQ(c.tick(), 10);
  EXPECT_EQ(c.check(at(11), 0), ClockVerdict::Follow);
  EXPECT_EQ(c.tick(), 11);
  EXPECT_EQ(c.counts().malformed, 1u);
  EXPECT_EQ(c.counts().leap, 1u);
}

TEST(ClockCheckTest, ForgedFirstClockDoesNotJoinAWorld) {
  ClockCheck c;
  EXPECT_EQ(c.check({kWorld + 7, std::numeric_limits<int64_t>::max(), 0, kStep}, 0), ClockVerdict::Malformed);
  EXPECT_FALSE(c.world());
  EXPECT_EQ(c.check(at(0), 0), ClockVerdict::Follow);
  EXPECT_EQ(*c.world(), kWorld);
}

TEST(ClockCheckTest, LeapLimitGrowsWithTheWallTimeSinceTheTickFollowed) {
  ClockCheck c({1000, 10'000});  // 1000 ticks at once, 10000 more per wall second
  constexpr int64_t kSecond = 1'000'000'000;
  ASSERT_EQ(c.check(at(0), 0), ClockVerdict::Follow);
  EXPECT_EQ(c.check(at(1000), 0), ClockVerdict::Follow);
  EXPECT_EQ(c.check(at(2001), 0), ClockVerdict::Leap);
  // An idle lockstep world races through quiet ticks: after 2 s, 20000 ticks more are real.
  EXPECT_EQ(c.check(at(1000 + 21'000), 2 * kSecond), ClockVerdict::Follow);
  EXPECT_EQ(c.check(at(22'000 + 1001), 2 * kSecond), ClockVerdict::Leap);
  EXPECT_EQ(c.counts().leap, 2u);
}

TEST(ClockCheckTest, ConsistentForgedFarFutureIsALeapWithTheDefaultLimit) {
  ClockCheck c;
  ASSERT_EQ(c.check(at(10), 0), ClockVerdict::Follow);
  // 290 years of 0.1 s ticks, tick and time consistent: no world got there in a second.
  const int64_t far = int64_t{91'000'000'000};
  EXPECT_EQ(c.check(at(far), 1'000'000'000), ClockVerdict::Leap);
  EXPECT_EQ(c.check(at(11), 1'000'000'000), ClockVerdict::Follow);
}

TEST(ClockCheckTest, TimeThatIsNotTickTimesStepIsMalformed) {
  ClockCheck c;
  EXPECT_EQ(c.check({kWorld, 10, 10 * kStep + 5'000'000, kStep}, 0), ClockVerdict::Malformed);
  EXPECT_EQ(c.check({kWorld, 10, -1, kStep}, 0), ClockVerdict::Malformed);
  EXPECT_EQ(c.check({kWorld, -3, 0, kStep}, 0), ClockVerdict::Malformed);
  EXPECT_EQ(c.check({kWorld, 10, 0, 0}, 0), ClockVerdict::Malformed);
  EXPECT_EQ(c.counts().malformed, 4u);
  // Rounding per tick (the simulator stamps llround(tick * step_s * 1e9)) is not malformed.
  EXPECT_EQ(c.check({kWorld, 3, 3 * kStep + 1, kStep}, 0), ClockVerdict::Follow);
}

TEST(ClockCheckTest, ExplanationNamesBothWorlds) {
  ClockCheck c;
  ASSERT_EQ(c.check(at(5), 0), ClockVerdict::Follow);
  const ClockReading other = at(6, 99);
  const std::string text = c.explain(other, c.check(other, 0));
  EXPECT_NE(text.find("world 99"), std::string::npos) << text;
  EXPECT_NE(text.find("world " + std::to_string(kWorld)), std::string::npos) << text;
}

}  // namespace
}  // namespace autonomy::clock
