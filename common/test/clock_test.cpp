// Wall and simulated clocks (common/clock/clock.hpp).
#include "common/clock/clock.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <thread>
#include <vector>

namespace autonomy::clock {
namespace {

TEST(SimulatedClockTest, NotRunningBeforeFirstAdvance) {
  SimulatedClock c;
  EXPECT_FALSE(c.running());
  EXPECT_EQ(c.tick(), -1);
  EXPECT_EQ(c.now_ns(), 0);
}

TEST(SimulatedClockTest, RunsFromTickZero) {
  SimulatedClock c;
  c.advance(0, 0);
  EXPECT_TRUE(c.running());
  EXPECT_EQ(c.tick(), 0);
  EXPECT_EQ(c.now_ns(), 0);
}

TEST(SimulatedClockTest, AdvanceSetsTickAndTime) {
  SimulatedClock c;
  c.advance(3, 60'000'000);
  EXPECT_TRUE(c.running());
  EXPECT_EQ(c.tick(), 3);
  EXPECT_EQ(c.now_ns(), 60'000'000);
  c.advance(4, 80'000'000);
  EXPECT_EQ(c.tick(), 4);
  EXPECT_EQ(c.now_ns(), 80'000'000);
}

TEST(SimulatedClockTest, StaleAndDuplicateTicksAreIgnored) {
  SimulatedClock c;
  c.advance(10, 200'000'000);
  c.advance(9, 180'000'000);  // stale
  EXPECT_EQ(c.tick(), 10);
  EXPECT_EQ(c.now_ns(), 200'000'000);
  c.advance(10, 999'000'000);  // duplicate tick with other time
  EXPECT_EQ(c.tick(), 10);
  EXPECT_EQ(c.now_ns(), 200'000'000);
  c.advance(12, 240'000'000);  // a gap is fine
  EXPECT_EQ(c.tick(), 12);
  EXPECT_EQ(c.now_ns(), 240'000'000);
}

TEST(SimulatedClockTest, NowSecondsIsNanosecondsScaled) {
  SimulatedClock c;
  c.advance(1, 1'500'000'000);
  EXPECT_DOUBLE_EQ(c.now_s(), 1.5);
  c.advance(2, 2'250'000'000);
  EXPECT_DOUBLE_EQ(c.now_s(), 2.25);
}

TEST(SimulatedClockTest, ReadersOnOtherThreadsNeverSeeTimeGoBack) {
  SimulatedClock c;
  std::thread writer([&] {
    for (int64_t t = 0; t < 20000; ++t) c.advance(t, t * 1000);
  });
  int64_t last_tick = -1;
  bool monotonic = true;
  while (last_tick < 19999) {
    const int64_t t = c.tick();
    if (t < last_tick) monotonic = false;
    last_tick = t;
  }
  writer.join();
  EXPECT_TRUE(monotonic);
  EXPECT_EQ(c.now_ns(), 19999 * 1000);
}

TEST(WallClockTest, IsAlwaysRunning) {
  WallClock c;
  EXPECT_TRUE(c.running());
}

TEST(WallClockTest, FollowsSystemClock) {
  WallClock c;
  const auto to_ns = [](std::chrono::system_clock::time_point t) {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(t.time_since_epoch()).count();
  };
  const int64_t before = to_ns(std::chrono::system_clock::now());
  const int64_t now = c.now_ns();
  const int64_t after = to_ns(std::chrono::system_clock::now());
  EXPECT_GE(now, before);
  EXPECT_LE(now, after);
  EXPECT_LT(after - before, 1'000'000'000);  // sanity: the sandwich is tight
  EXPECT_NEAR(c.now_s(), static_cast<double>(after) * 1e-9, 1.0);
  EXPECT_GT(c.now_s(), 1.6e9);  // Unix epoch, not process start (2020-09 or later)
}

TEST(WallClockTest, UsableThroughTheInterface) {
  WallClock wall;
  SimulatedClock sim;
  std::vector<const Clock*> clocks{&wall, &sim};
  EXPECT_TRUE(clocks[0]->running());
  EXPECT_FALSE(clocks[1]->running());
  sim.advance(0, 42);
  EXPECT_TRUE(clocks[1]->running());
  EXPECT_EQ(clocks[1]->now_ns(), 42);
}

}  // namespace
}  // namespace autonomy::clock
