#include "services/courier/core/knowledge/destination_frequencies.hpp"

#include <gtest/gtest.h>

namespace autonomy::courier {
namespace {

TEST(DestinationFrequencies, NothingLearnedNothingAnswered) {
  const DestinationFrequencies f;
  EXPECT_FALSE(f.most_frequent_destination("Wolfram", "letter").has_value());
  EXPECT_EQ(f.total(), 0);
}

TEST(DestinationFrequencies, MostFrequentPerSourceAndKind) {
  DestinationFrequencies f;
  f.record("Wolfram", "letter", "michael-desk");
  f.record("Wolfram", "letter", "michael-desk");
  f.record("Wolfram", "letter", "a114-desk");
  f.record("Wolfram", "book", "a114-desk");
  f.record("Wolfram", "book", "a114-desk");
  f.record("Anna", "letter", "a112-desk");
  const auto letters = f.most_frequent_destination("wolfram", "LETTER");
  ASSERT_TRUE(letters.has_value());
  EXPECT_EQ(letters->destination, "michael-desk");
  EXPECT_EQ(letters->count, 2);
  EXPECT_EQ(letters->total, 3);
  // Any kind: a114-desk has 3 of Wolfram's 5.
  const auto any = f.most_frequent_destination("Wolfram", "");
  ASSERT_TRUE(any.has_value());
  EXPECT_EQ(any->destination, "a114-desk");
  EXPECT_EQ(any->count, 3);
  EXPECT_EQ(any->total, 5);
  EXPECT_FALSE(f.most_frequent_destination("Wolfram", "envelope").has_value());
  EXPECT_EQ(f.total(), 6);
}

TEST(DestinationFrequencies, TiesGoToTheFirstNameInOrder) {
  DestinationFrequencies f;
  f.record("Jan", "letter", "zeta");
  f.record("Jan", "letter", "alpha");
  EXPECT_EQ(f.most_frequent_destination("Jan", "letter")->destination, "alpha");
}

}  // namespace
}  // namespace autonomy::courier
