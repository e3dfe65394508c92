#include "simulator/office/office_spec.hpp"
#include "simulator/office/office_state.hpp"
#include "simulator/office/test/office_fixture.hpp"

#include <gtest/gtest.h>

#include <random>
#include <stdexcept>

namespace autonomy::sim::office {
namespace {

using test::small_office;

TEST(DayClock, SimulatedTimeIsClockTimeFromTheDayStart) {
  DayClock c;  // 08:30
  EXPECT_DOUBLE_EQ(c.time_of_day(0.0), 8.5 * 3600.0);
  EXPECT_DOUBLE_EQ(c.time_of_day(1800.0), 9.0 * 3600.0);
  EXPECT_DOUBLE_EQ(c.time_of_day(15.5 * 3600.0), 0.0);          // midnight
  EXPECT_DOUBLE_EQ(c.time_of_day(16.5 * 3600.0), 3600.0);       // 01:00 the next day
  EXPECT_DOUBLE_EQ(c.time_of_day(2 * 86400.0 + 60.0), 8.5 * 3600.0 + 60.0);
}

TEST(DayClock, ParsesAndFormatsClockTimes) {
  EXPECT_EQ(parse_clock("09:00"), 32400.0);
  EXPECT_EQ(parse_clock("17:30"), 63000.0);
  EXPECT_EQ(parse_clock("13:05:07"), 13 * 3600.0 + 5 * 60.0 + 7);
  EXPECT_EQ(parse_clock("24:00"), 86400.0);
  EXPECT_FALSE(parse_clock("24:01"));
  EXPECT_FALSE(parse_clock("9:00"));
  EXPECT_FALSE(parse_clock("09:60"));
  EXPECT_FALSE(parse_clock("09-00"));
  EXPECT_FALSE(parse_clock(""));
  EXPECT_EQ(format_clock(32400.0), "09:00");
  EXPECT_EQ(format_clock(13 * 3600.0 + 5 * 60.0 + 7.9), "13:05:07");
}

TEST(HandoverTimeModel, FixedUniformAndClippedNormal) {
  std::mt19937_64 rng(7);
  EXPECT_DOUBLE_EQ(HandoverTimeModel::fixed(12.5).sample(rng), 12.5);

  const auto uniform = HandoverTimeModel::uniform(5.0, 15.0);
  const auto normal = HandoverTimeModel::normal(30.0, 10.0, 20.0, 35.0);
  double sum_u = 0.0, sum_n = 0.0;
  bool clipped_low = false, clipped_high = false;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    const double u = uniform.sample(rng);
    ASSERT_GE(u, 5.0);
    ASSERT_LT(u, 15.0);
    sum_u += u;
    const double v = normal.sample(rng);
    ASSERT_GE(v, 20.0);
    ASSERT_LE(v, 35.0);
    clipped_low |= v == 20.0;
    clipped_high |= v == 35.0;
    sum_n += v;
  }
  EXPECT_NEAR(sum_u / n, 10.0, 0.1);
  EXPECT_TRUE(clipped_low);
  EXPECT_TRUE(clipped_high);
  // Mean of N(30, 10) clamped to [20, 35], with a = -1, b = 0.5 in standard units:
  // 30 + 10 * (a Phi(a) + phi(a) - phi(b) + b (1 - Phi(b))) = 30 + 10 * -0.11448 = 28.855.
  EXPECT_NEAR(sum_n / n, 28.855, 0.15);
}

TEST(HandoverTimeModel, EveryKindUsesTwoDrawsSoLaterDrawsDoNotShift) {
  for (const auto& m : {HandoverTimeModel::fixed(1.0), HandoverTimeModel::uniform(0.0, 1.0),
                        HandoverTimeModel::normal(1.0, 1.0, 0.0, 2.0)}) {
    std::mt19937_64 a(3), b(3);
    (void)m.sample(a);
    b.discard(2);
    EXPECT_EQ(a(), b());
  }
}

TEST(HandoverTimeModel, SameSeedSameDurations) {
  const auto m = HandoverTimeModel::normal(20.0, 5.0, 0.0, 60.0);
  std::mt19937_64 a(42), b(42);
  for (int i = 0; i < 10; ++i) EXPECT_EQ(m.sample(a), m.sample(b));
}

TEST(OfficeSpecProblems, TheSmallOfficeIsUsable) { EXPECT_TRUE(office_spec_problems(small_office()).empty()); }

TEST(OfficeSpecProblems, ReportsEveryProblemInOrder) {
  OfficeSpec s = small_office();
  s.clock.day_start_s = 90000.0;
  s.places.push_back({"anna-desk", PlaceKind::desk, "A-110", {1, 1}, 0.5});   // duplicate
  s.places.push_back({"lamp", PlaceKind::desk, "nowhere", {1, 1}, 0.0});      // unknown room, radius
  s.places.push_back({"nook", PlaceKind::table, "anna-desk", {1, 1}, 0.5});   // room is a desk
  s.people.push_back({"Carl", "attic", {{10 * 3600.0, 9 * 3600.0}}, HandoverTimeModel::uniform(5, 1)});
  s.people.push_back({"Dora", "bob-desk", {{9 * 3600.0, 12 * 3600.0}, {11 * 3600.0, 13 * 3600.0}},
                      HandoverTimeModel::normal(10, -1, 0, 20)});
  s.stations.push_back({"cellar", HandoverTimeModel::fixed(-2)});
  s.objects.push_back({"letter-1", "letter", "blue", ObjectLocation::at_place("anna-desk")});
  s.objects.push_back({"book-9", "book", "blue", ObjectLocation::at_place("library")});
  s.objects.push_back({"book-10", "book", "blue", ObjectLocation::carried_by("r7")});  // fine
  const std::vector<std::string> expected = {
      "day start 90000.0 s is not within [0, 86400)",
      "place anna-desk is declared twice",
      "place lamp has radius 0.0 m, not > 0",
      "place lamp is in unknown room nowhere",
      "place nook is in anna-desk, which is a desk, not a room",
      "person Carl sits at unknown place attic",
      "person Carl has presence 10:00-09:00 that is not within one day, start before end",
      "person Carl has a handover time range [5.0, 1.0] s that is not 0 <= min <= max",
      "person Dora has presence 11:00-13:00 overlapping or before the previous interval",
      "person Dora has a negative handover time standard deviation -1.0 s",
      "loading station at unknown place cellar",
      "loading station at cellar has a negative handover time -2.0 s",
      "object letter-1 is declared twice",
      "object book-9 is at unknown place library",
  };
  EXPECT_EQ(office_spec_problems(s), expected);
}

TEST(OfficeState, RefusesAnUnusableSpec) {
  OfficeSpec s = small_office();
  s.people[0].desk = "attic";
  try {
    OfficeState office(s);
    FAIL() << "accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("person Anna sits at unknown place attic"), std::string::npos);
  }
}

}  // namespace
}  // namespace autonomy::sim::office
