#include "common/msg/text_limits.hpp"

#include <gtest/gtest.h>

namespace autonomy::msg {
namespace {

TEST(TextLimits, LengthProblemNamesTheFieldAndBothLengths) {
  EXPECT_FALSE(length_problem("goal_id", std::string(128, 'g'), kMaxIdLength));
  EXPECT_EQ(*length_problem("goal_id", std::string(129, 'g'), kMaxIdLength), "goal_id has 129 bytes, more than 128");
}

TEST(TextLimits, FirstLengthProblemReportsTheFirstFieldOverItsLimitInOrder) {
  const std::string ok = "r1";
  const std::string long_name(65, 'n');
  const std::string long_text(2000, 't');
  EXPECT_FALSE(first_length_problem({{"robot_id", ok, kMaxNameLength}, {"reason", ok, kMaxTextLength}}));
  EXPECT_EQ(*first_length_problem({{"robot_id", ok, kMaxNameLength},
                                   {"source", long_name, kMaxNameLength},
                                   {"reason", long_text, kMaxTextLength}}),
            "source has 65 bytes, more than 64");
}

TEST(TextLimits, LogsAndEchoesAreCut) {
  EXPECT_EQ(clipped_for_log("short"), "short");
  EXPECT_EQ(clipped_for_log(std::string(100000, 'x'), 4), "xxxx...(100000 bytes)");
  EXPECT_EQ(clipped_id(std::string(300, 'x')).size(), kMaxIdLength);
  EXPECT_EQ(clipped_id("g1"), "g1");
}

}  // namespace
}  // namespace autonomy::msg
