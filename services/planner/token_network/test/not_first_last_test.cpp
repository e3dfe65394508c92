// Not-first/not-last on windows: hand-computed cases where each rule narrows a window, and on
// small random sets of windows no schedule that fits them is ever cut off (all integer start
// times enumerated).
#include "not_first_last.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <random>

namespace autonomy::planner {
namespace {

// A and B fill [2, 10] exactly; i (2 long, window [0, 10]) starts before 2 so it lies outside
// their task interval. Not last: 2 + 8 > 10 - 2, so i ends by the latest start of A or B, 6.
TEST(NotFirstNotLast, NotLastLowersTheLatestEnd) {
  const auto out = not_first_not_last({{2, 10, 4}, {2, 10, 4}, {0, 10, 2}});
  ASSERT_EQ(out.size(), 3u);
  EXPECT_EQ(out[2].lct, 6);
  EXPECT_EQ(out[2].est, 0);
  for (int k : {0, 1}) {  // A and B: nothing to narrow
    EXPECT_EQ(out[k].est, 2);
    EXPECT_EQ(out[k].lct, 10);
  }
}

// A and B fill [0, 8]; i (window [0, 10]) ends after 8 so it lies outside their task
// interval. Not first: 0 + 2 > 8 - 8, so i starts after the earliest end of A or B, 4.
TEST(NotFirstNotLast, NotFirstRaisesTheEarliestStart) {
  const auto out = not_first_not_last({{0, 8, 4}, {0, 8, 4}, {0, 10, 2}});
  EXPECT_EQ(out[2].est, 4);
  EXPECT_EQ(out[2].lct, 10);
}

// Slack everywhere: nothing changes.
TEST(NotFirstNotLast, LooseWindowsStayAsTheyAre) {
  const std::vector<UnaryWindow> in{{0, 100, 5}, {3, 90, 7}, {10, 80, 2}};
  const auto out = not_first_not_last(in);
  for (std::size_t k = 0; k < in.size(); ++k) {
    EXPECT_EQ(out[k].est, in[k].est);
    EXPECT_EQ(out[k].lct, in[k].lct);
  }
}

TEST(NotFirstNotLast, NeverCutsOffAScheduleThatFits) {
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> count(2, 4), release(0, 6), length(1, 4), slack(0, 6);
  int narrowed = 0, schedules = 0;
  for (int round = 0; round < 3000; ++round) {
    std::vector<UnaryWindow> w(std::size_t(count(rng)));
    for (UnaryWindow& x : w) {
      x.est = release(rng);
      x.duration = length(rng);
      x.lct = x.est + x.duration + slack(rng);
    }
    const auto out = not_first_not_last(w);
    for (std::size_t k = 0; k < w.size(); ++k) {
      ASSERT_GE(out[k].est, w[k].est);  // never widens
      ASSERT_LE(out[k].lct, w[k].lct);
      narrowed += out[k].est > w[k].est || out[k].lct < w[k].lct;
    }
    // Every assignment of integer starts within the windows, pairwise apart.
    std::vector<Time> start(w.size());
    std::function<void(std::size_t)> place = [&](std::size_t k) {
      if (k == w.size()) {
        ++schedules;
        for (std::size_t i = 0; i < w.size(); ++i) {
          ASSERT_GE(start[i], out[i].est) << "round " << round << " token " << i;
          ASSERT_LE(start[i] + w[i].duration, out[i].lct) << "round " << round << " token " << i;
        }
        return;
      }
      for (Time s = w[k].est; s + w[k].duration <= w[k].lct; ++s) {
        bool apart = true;
        for (std::size_t i = 0; i < k; ++i)
          apart &= s + w[k].duration <= start[i] || start[i] + w[i].duration <= s;
        if (!apart) continue;
        start[k] = s;
        place(k + 1);
      }
    };
    place(0);
  }
  // The rules do something on these windows, and the check saw schedules to compare with.
  EXPECT_GT(narrowed, 100);
  EXPECT_GT(schedules, 1000);
}

}  // namespace
}  // namespace autonomy::planner
