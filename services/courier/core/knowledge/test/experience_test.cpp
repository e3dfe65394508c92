// What the courier learns: running handover statistics, once-per-day votes by half hour with a
// prior that keeps doors open until several days say otherwise, travel times after a few drives.
#include "services/courier/core/knowledge/experience.hpp"

#include <gtest/gtest.h>

namespace autonomy::courier {
namespace {

constexpr double k10_15 = 10 * 3600 + 15 * 60;

TEST(Experience, HandoverTimesAreRunningStatisticsUsedAfterThreeSamples) {
  Experience e;
  e.handover("Michael", 20);
  e.handover("Michael", 30);
  EXPECT_DOUBLE_EQ(e.expected_handover("Michael", 10), 10);  // two samples: still nominal
  e.handover("Michael", 40);
  EXPECT_DOUBLE_EQ(e.expected_handover("Michael", 10), 30);
  EXPECT_DOUBLE_EQ(e.handovers().at("Michael").stddev(), 10);
  EXPECT_DOUBLE_EQ(e.expected_handover("Jean", 12), 12);  // never seen
  e.handover("Michael", -1);                              // nonsense is ignored
  EXPECT_EQ(e.handovers().at("Michael").n, 3);
}

TEST(Experience, ADoorVotesOncePerHalfHourAndDay) {
  Experience e;
  for (int minute = 0; minute < 14; ++minute) e.door("A-120", k10_15 + minute * 60, false, 1);
  EXPECT_EQ(e.doors().at("A-120").no[HalfHourCounts::slot_of(k10_15)], 1);
  e.door("A-120", k10_15 + 20 * 60, false, 1);  // 10:35: the next half hour
  EXPECT_EQ(e.doors().at("A-120").no[HalfHourCounts::slot_of(k10_15 + 20 * 60)], 1);
  // Never seen: open by the prior; one closed day is not yet a habit.
  EXPECT_NEAR(e.p_open("A-111", k10_15), 2.0 / 3.0, 1e-12);
  EXPECT_NEAR(e.p_open("A-120", k10_15), 0.5, 1e-12);
  EXPECT_FALSE(e.usually_closed("A-120", k10_15));
}

TEST(Experience, AHabitNeedsSeveralDaysAndCanBeUnlearned) {
  Experience e;
  for (std::int64_t day = 1; day <= 3; ++day) e.door("A-120", k10_15, false, day);
  EXPECT_NEAR(e.p_open("A-120", k10_15), 2.0 / 6.0, 1e-12);
  EXPECT_TRUE(e.usually_closed("A-120", k10_15));
  EXPECT_FALSE(e.usually_closed("A-120", k10_15 + 3600));  // other hours know nothing
  for (std::int64_t day = 4; day <= 5; ++day) e.door("A-120", k10_15, true, day);
  EXPECT_NEAR(e.p_open("A-120", k10_15), 4.0 / 8.0, 1e-12);
  EXPECT_FALSE(e.usually_closed("A-120", k10_15));
  // Presence the same way.
  for (std::int64_t day = 1; day <= 3; ++day) e.presence("Michael", k10_15, false, day);
  EXPECT_TRUE(e.usually_absent("Michael", k10_15));
  EXPECT_FALSE(e.usually_absent("Jean", k10_15));
}

TEST(Experience, TravelTimesAfterThreeDrivesAndEveryObservationCountsAsUnsaved) {
  Experience e;
  e.travel("mailroom", "A-120 desk", 50);
  e.travel("mailroom", "A-120 desk", 60);
  EXPECT_FALSE(e.travel_time("mailroom", "A-120 desk"));
  e.travel("mailroom", "A-120 desk", 70);
  ASSERT_TRUE(e.travel_time("mailroom", "A-120 desk"));
  EXPECT_DOUBLE_EQ(*e.travel_time("mailroom", "A-120 desk"), 60);
  EXPECT_FALSE(e.travel_time("A-120 desk", "mailroom"));  // directed
  EXPECT_EQ(e.unsaved(), 3u);
  e.mark_saved();
  EXPECT_EQ(e.unsaved(), 0u);
  e.door("A-120", k10_15, true, 1);
  e.door("A-120", k10_15, true, 1);  // the same vote again: nothing new
  EXPECT_EQ(e.unsaved(), 1u);
}

TEST(Experience, HalfHoursWrapAroundTheDay) {
  EXPECT_EQ(HalfHourCounts::slot_of(0), 0);
  EXPECT_EQ(HalfHourCounts::slot_of(1799), 0);
  EXPECT_EQ(HalfHourCounts::slot_of(1800), 1);
  EXPECT_EQ(HalfHourCounts::slot_of(86399), 47);
  EXPECT_EQ(HalfHourCounts::slot_of(86400 + 1800), 1);
  EXPECT_EQ(HalfHourCounts::slot_of(-1), 47);
}

}  // namespace
}  // namespace autonomy::courier
