// The watchdog: a tick that does not end raises the alarm once (its callback on the watchdog's
// thread), and ticks that end again clear it.
#include "watchdog.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <thread>

namespace autonomy::executive {
namespace {

// Polls `condition` for up to 20 s (the machine may be loaded; nothing here is timed).
bool eventually(const std::function<bool()>& condition) {
  for (int i = 0; i < 2000; ++i) {
    if (condition()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return condition();
}

TEST(Watchdog, AStalledTickRaisesTheAlarmOnceAndAnEndedOneClearsIt) {
  std::atomic<int> stalls{0}, recoveries{0};
  std::atomic<std::int64_t> stalled_for_ms{0};
  Watchdog dog(
      std::chrono::milliseconds(50),
      [&](Watchdog::Clock::duration busy) {
        stalled_for_ms = std::chrono::duration_cast<std::chrono::milliseconds>(busy).count();
        ++stalls;
      },
      [&] { ++recoveries; });
  EXPECT_FALSE(dog.alarmed());
  dog.tick_started();
  ASSERT_TRUE(eventually([&] { return stalls.load() == 1; }));
  EXPECT_TRUE(dog.alarmed());
  EXPECT_GE(stalled_for_ms.load(), 50);
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  EXPECT_EQ(stalls.load(), 1);  // once per stall, not once per check
  dog.tick_ended();
  ASSERT_TRUE(eventually([&] { return recoveries.load() == 1; }));
  EXPECT_FALSE(dog.alarmed());
  dog.tick_started();  // a second stall is a second alarm
  ASSERT_TRUE(eventually([&] { return stalls.load() == 2; }));
  dog.tick_ended();
}

}  // namespace
}  // namespace autonomy::executive
