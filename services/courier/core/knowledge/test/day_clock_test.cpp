#include "services/courier/core/knowledge/day_clock.hpp"

#include <gtest/gtest.h>

namespace autonomy::courier {
namespace {

TEST(DayClock, SimulatedTimeZeroIsTheDayStartAndWrapsAtMidnight) {
  const DayClock clock{8.5 * 3600.0};
  EXPECT_DOUBLE_EQ(clock.time_of_day(0.0), 30600.0);
  EXPECT_DOUBLE_EQ(clock.time_of_day(3600.0), 34200.0);
  EXPECT_DOUBLE_EQ(clock.time_of_day(15.5 * 3600.0 + 60.0), 60.0);  // 00:01 the next day
  EXPECT_EQ(clock.day_of(0.0), 0);
  EXPECT_EQ(clock.day_of(15.5 * 3600.0 - 1.0), 0);
  EXPECT_EQ(clock.day_of(15.5 * 3600.0 + 60.0), 1);
  EXPECT_EQ(clock.day_of(15.5 * 3600.0 + 86400.0), 2);
}

TEST(DayClock, SimTimeOfAClockTimeOnTheSameDay) {
  const DayClock clock{8.5 * 3600.0};
  EXPECT_DOUBLE_EQ(clock.sim_time_of(10.5 * 3600.0, 100.0), 7200.0);  // 10:30 is 2 h after 08:30
  EXPECT_DOUBLE_EQ(clock.sim_time_of(8.0 * 3600.0, 100.0), -1800.0);  // 08:00 was before the start
  // On the second day (sim 86400 is 08:30 again) 10:30 is 86400 + 7200.
  EXPECT_DOUBLE_EQ(clock.sim_time_of(10.5 * 3600.0, 86400.0 + 60.0), 93600.0);
}

TEST(ParseClock, AcceptsHoursAndMinutesWithOptionalSeconds) {
  EXPECT_EQ(parse_clock("10:30"), 37800.0);
  EXPECT_EQ(parse_clock("9:05"), 32700.0);
  EXPECT_EQ(parse_clock("09:05:07"), 32707.0);
  EXPECT_EQ(parse_clock("24:00"), 86400.0);
  EXPECT_EQ(parse_clock("00:00"), 0.0);
}

TEST(ParseClock, RejectsMalformedTimes) {
  for (const char* bad : {"", "10", "10:", ":30", "10:3", "10:300", "25:00", "24:01", "10:60",
                          "10:30:60", "1a:30", "10:30:00:00", "100:00", "-1:00", "10::30"})
    EXPECT_FALSE(parse_clock(bad).has_value()) << bad;
}

TEST(FormatClock, MinutesOrSeconds) {
  EXPECT_EQ(format_clock(37800.0), "10:30");
  EXPECT_EQ(format_clock(37815.9), "10:30:15");
  EXPECT_EQ(format_clock(0.0), "00:00");
}

}  // namespace
}  // namespace autonomy::courier
