// The runner's pure part: where the robots start.
#include "tools/experiments/runner/trial.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <stdexcept>

namespace autonomy::experiments {
namespace {

TEST(StartPositions, SortedInsideTheStartLineAndSpacedApart) {
  TrialSetup setup;
  for (std::uint64_t seed = 0; seed < 500; ++seed) {
    const std::vector<double> xs = start_positions(setup, seed);
    ASSERT_EQ(xs.size(), 3u);
    EXPECT_TRUE(std::is_sorted(xs.begin(), xs.end())) << "seed " << seed;
    EXPECT_GE(xs.front(), setup.start_min_x);
    EXPECT_LE(xs.back(), setup.start_max_x);
    for (size_t k = 1; k < xs.size(); ++k) EXPECT_GE(xs[k] - xs[k - 1], setup.min_start_spacing_m - 1e-9) << "seed " << seed;
  }
}

TEST(StartPositions, SameSeedSamePositionsOtherSeedOthers) {
  TrialSetup setup;
  EXPECT_EQ(start_positions(setup, 42), start_positions(setup, 42));
  EXPECT_NE(start_positions(setup, 42), start_positions(setup, 43));
}

TEST(StartPositions, TightSpacingStillFitsAndImpossibleSpacingThrows) {
  TrialSetup setup;
  setup.start_min_x = 0.0;
  setup.start_max_x = 10.0;
  setup.min_start_spacing_m = 4.9;  // 3 robots in 10 m: only arrangements near 0, 5, 10 qualify
  const std::vector<double> xs = start_positions(setup, 7);
  EXPECT_GE(xs[1] - xs[0], 4.9 - 1e-12);
  EXPECT_GE(xs[2] - xs[1], 4.9 - 1e-12);
  EXPECT_LE(xs[2], 10.0);
  setup.min_start_spacing_m = 5.0;  // exactly fits: 0, 5, 10
  EXPECT_EQ(start_positions(setup, 7), (std::vector<double>{0.0, 5.0, 10.0}));
  setup.min_start_spacing_m = 5.1;
  EXPECT_THROW(start_positions(setup, 7), std::invalid_argument);
}

}  // namespace
}  // namespace autonomy::experiments
