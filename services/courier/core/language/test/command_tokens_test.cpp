#include "services/courier/core/language/command_tokens.hpp"

#include "services/courier/core/language/delivery_completion.hpp"

#include <gtest/gtest.h>

namespace autonomy::courier {
namespace {

Rejection tokenize_rejection(const std::string& text) {
  try {
    tokenize_command(text);
  } catch (const RejectionError& e) {
    return e.rejection;
  }
  ADD_FAILURE() << "accepted: " << text;
  return {};
}

TEST(CommandTokens, WordsAreLowerCasedWithTheirColumns) {
  const auto t = tokenize_command("Put  the RED letter, on A-111.");
  ASSERT_EQ(t.size(), 6u);
  EXPECT_EQ(t[0].word, "put");
  EXPECT_EQ(t[0].column, 1);
  EXPECT_EQ(t[1].column, 6);
  EXPECT_EQ(t[2].word, "red");
  EXPECT_EQ(t[2].text, "RED");
  EXPECT_EQ(t[3].word, "letter");  // the comma separates
  EXPECT_EQ(t[5].word, "a-111");   // the full stop separates
  EXPECT_EQ(t[5].column, 25);
}

TEST(CommandTokens, PossessivesAndTypographicApostrophes) {
  const auto t = tokenize_command("the librarian's desk, James' desk, Anna\xE2\x80\x99s desk");
  ASSERT_EQ(t.size(), 7u);
  EXPECT_EQ(t[1].word, "librarian");
  EXPECT_TRUE(t[1].possessive);
  EXPECT_EQ(t[1].text, "librarian's");
  EXPECT_FALSE(t[2].possessive);
  EXPECT_EQ(t[3].word, "james");
  EXPECT_TRUE(t[3].possessive);
  EXPECT_EQ(t[5].word, "anna");
  EXPECT_TRUE(t[5].possessive);
  EXPECT_EQ(t[6].column, 45);  // columns count bytes: the apostrophe is three
}

TEST(CommandTokens, TimesKeepColonsAndDotsBetweenDigits) {
  const auto t = tokenize_command("by 10:30; by 10.30. (by 9)");
  ASSERT_EQ(t.size(), 6u);
  EXPECT_EQ(t[1].word, "10:30");
  EXPECT_EQ(t[3].word, "10.30");
  EXPECT_EQ(t[5].word, "9");
}

TEST(CommandTokens, TabsAndLineBreaksAreSpaces) {
  EXPECT_EQ(tokenize_command("cancel\tjob\r\nj1").size(), 3u);
  EXPECT_TRUE(tokenize_command(" ,.;!? ").empty());
}

TEST(CommandTokens, RejectsControlCharactersAndNonAsciiAtTheirColumn) {
  Rejection r = tokenize_rejection(std::string("cancel job\x01 j1"));
  EXPECT_EQ(r.reason, RejectReason::bad_character);
  EXPECT_EQ(r.column, 11);
  EXPECT_EQ(r.word, "0x01");
  r = tokenize_rejection("deliver the gr\xC3\xBCn book");
  EXPECT_EQ(r.reason, RejectReason::bad_character);
  EXPECT_EQ(r.column, 15);
  EXPECT_EQ(tokenize_rejection(std::string("a\x7f")).column, 2);
}

TEST(CommandTokens, RejectsMoreThanTheMaximumLength) {
  EXPECT_NO_THROW(tokenize_command(std::string(kMaxCommandBytes, 'a')));
  const Rejection r = tokenize_rejection(std::string(kMaxCommandBytes + 1, 'a'));
  EXPECT_EQ(r.reason, RejectReason::too_long);
  EXPECT_EQ(r.column, static_cast<int>(kMaxCommandBytes) + 1);
}

}  // namespace
}  // namespace autonomy::courier
