#include "services/behavior/core/mission/contact_judge.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace autonomy::behavior {
namespace {

TEST(ContactJudge, FirstSightTakesTheRawFlag) {
  ContactJudge judge;
  EXPECT_TRUE(judge.update("r2", 0.0, true));
  EXPECT_FALSE(judge.update("r3", 0.0, false));
}

TEST(ContactJudge, AFlickeringLinkKeepsContact) {
  ContactJudge judge({2.0, 0.5});
  EXPECT_TRUE(judge.update("r2", 0.0, true));
  // Down for 0.3 s, up for 0.1 s, again and again: never down for 2 s in one stretch.
  for (int k = 0; k < 50; ++k) {
    const double t = 0.1 + 0.4 * k;
    EXPECT_TRUE(judge.update("r2", t, false)) << t;
    EXPECT_TRUE(judge.update("r2", t + 0.3, false)) << t;
    EXPECT_TRUE(judge.update("r2", t + 0.35, true)) << t;
  }
}

TEST(ContactJudge, LostAfterTheLinkIsDownLongEnoughAndRestoredAfterItIsUpLongEnough) {
  ContactJudge judge({2.0, 0.5});
  judge.update("r2", 0.0, true);
  EXPECT_TRUE(judge.update("r2", 1.0, false));
  EXPECT_TRUE(judge.update("r2", 2.9, false));
  EXPECT_FALSE(judge.update("r2", 3.0, false));  // down since 1.0: 2 s
  EXPECT_FALSE(judge.update("r2", 4.0, true));
  EXPECT_FALSE(judge.update("r2", 4.4, true));
  EXPECT_FALSE(judge.update("r2", 4.45, false));  // a blip down restarts the wait
  EXPECT_FALSE(judge.update("r2", 4.5, true));
  EXPECT_FALSE(judge.update("r2", 4.9, true));
  EXPECT_TRUE(judge.update("r2", 5.0, true));  // up since 4.5: 0.5 s
  EXPECT_TRUE(judge.update("r3", 5.0, true));  // teammates are judged separately
}

TEST(ContactJudge, ZeroDelaysJudgeEveryTickOnItsOwn) {
  ContactJudge judge({0.0, 0.0});
  judge.update("r2", 0.0, true);
  EXPECT_FALSE(judge.update("r2", 0.1, false));
  EXPECT_TRUE(judge.update("r2", 0.2, true));
  EXPECT_THROW(ContactJudge({-1.0, 0.0}), std::invalid_argument);
}

}  // namespace
}  // namespace autonomy::behavior
