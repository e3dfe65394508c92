// The delivery-sequence table (delivery_sequence_bound.hpp) on three places along a line, every
// value computed by hand: the cheapest order of the deliveries priced as completions, the places'
// detours, unreachable deliveries and the input checks.
#include "services/courier/core/scheduler/delivery_sequence_bound.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>
#include <vector>

namespace autonomy::courier::scheduling::detail {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Places 0 - 1 - 2 on a line, 10 s and 20 s apart; job 0 delivers at place 1 (5 s handover), job 1
// at place 2 (7 s).
const std::vector<double> kLine = {0, 10, 30,  //
                                   10, 0, 20,  //
                                   30, 20, 0};

TEST(DeliverySequenceBoundTest, PricesTheCheapestOrderOfTheDeliveriesAsCompletions) {
  const DeliverySequenceBound bound({1, 2}, {5.0, 7.0}, kLine, 3);
  EXPECT_DOUBLE_EQ(bound.cost(0b00, 0), 0.0);
  EXPECT_DOUBLE_EQ(bound.cost(0b01, 0), 15.0);  // 10 + 5
  EXPECT_DOUBLE_EQ(bound.cost(0b10, 0), 37.0);  // 30 + 7
  // From 0: job 0 first, 2 x (10 + 5) + (20 + 7) = 57; job 1 first would be 2 x 37 + 25 = 99.
  EXPECT_DOUBLE_EQ(bound.cost(0b11, 0), 57.0);
  // From 2: job 1 first (no leg), 2 x 7 + (20 + 5) = 39; job 0 first would be 2 x 25 + 27 = 77.
  EXPECT_DOUBLE_EQ(bound.cost(0b11, 2), 39.0);
  // From 1: job 0 at once, 2 x 5 + (20 + 7) = 37.
  EXPECT_DOUBLE_EQ(bound.cost(0b11, 1), 37.0);
}

TEST(DeliverySequenceBoundTest, DetourIsTheLeastExtraTravelOfAVisitBetweenTwoOtherPlaces) {
  const DeliverySequenceBound bound({1, 2}, {5.0, 7.0}, kLine, 3);
  EXPECT_DOUBLE_EQ(bound.detour(1), 0.0);   // on the way from 0 to 2
  EXPECT_DOUBLE_EQ(bound.detour(0), 20.0);  // 1 -> 0 -> 1 or 1 -> 0 -> 2: 20 more
  EXPECT_DOUBLE_EQ(bound.detour(2), 40.0);  // 1 -> 2 -> 1 or 0 -> 2 -> 1: 40 more
}

TEST(DeliverySequenceBoundTest, ADeliveryThatCannotBeReachedCostsInfinity) {
  std::vector<double> cut = kLine;
  cut[0 * 3 + 2] = kInf;  // no way from 0 to 2 (shortest travel: not through 1 either)
  cut[1 * 3 + 2] = kInf;
  const DeliverySequenceBound bound({1, 2}, {5.0, 7.0}, cut, 3);
  EXPECT_DOUBLE_EQ(bound.cost(0b01, 0), 15.0);
  EXPECT_EQ(bound.cost(0b10, 0), kInf);
  EXPECT_EQ(bound.cost(0b11, 0), kInf);
  EXPECT_DOUBLE_EQ(bound.cost(0b10, 2), 7.0);
}

TEST(DeliverySequenceBoundTest, RejectsInputsThatDoNotFit) {
  EXPECT_THROW(DeliverySequenceBound({1, 2}, {5.0}, kLine, 3), std::invalid_argument);
  EXPECT_THROW(DeliverySequenceBound({1, 3}, {5.0, 7.0}, kLine, 3), std::invalid_argument);
  EXPECT_THROW(DeliverySequenceBound({1, 2}, {5.0, 7.0}, kLine, 2), std::invalid_argument);
  const std::vector<int> many(DeliverySequenceBound::kMaxJobs + 1, 1);
  const std::vector<double> durations(many.size(), 5.0);
  EXPECT_THROW(DeliverySequenceBound(many, durations, kLine, 3), std::invalid_argument);
}

}  // namespace
}  // namespace autonomy::courier::scheduling::detail
