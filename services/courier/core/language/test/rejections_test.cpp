// Every rejection reason, with the word and column at fault (docs/courier-language.md lists them).
#include "services/courier/core/language/test/language_fixture.hpp"

#include <set>

namespace autonomy::courier {
namespace {

using Strings = std::vector<std::string>;

struct Case {
  std::string text;
  RejectReason reason;
  int column;
  std::string word;
  Strings suggestions;  // checked when not empty
};

OfficeKnowledge office_for_rejections() {
  OfficeKnowledge k = test::paper_office();
  k.people[1].roles = {"secretary"};  // Jan
  k.people[2].roles = {"secretary"};  // Anna
  k.objects.push_back({"letter-9", "letter", "green", "", "rhino", ""});
  return k;
}

const std::vector<Case>& cases() {
  static const std::vector<Case> all = {
      {"  ,. ", RejectReason::empty_command, 1, "", {}},
      {"please", RejectReason::empty_command, 1, "", {}},
      {std::string(600, 'a'), RejectReason::too_long, 513, std::string(16, 'a'), {}},
      {"deliver the b\x80ook to Anna", RejectReason::bad_character, 14, "0x80", {}},
      {"deliver the book\x07 to Anna", RejectReason::bad_character, 17, "0x07", {}},
      {"dleiver the green book to Anna", RejectReason::unknown_verb, 1, "dleiver", {"deliver"}},
      {"deliver the green book to Anna and then", RejectReason::unexpected_word, 36, "then", {}},
      {"pick the letter", RejectReason::unexpected_word, 6, "the", {}},
      {"cancel job j1 now", RejectReason::unexpected_word, 15, "now", {}},
      {"deliver to Anna", RejectReason::missing_object, 9, "to", {}},
      {"deliver it to Anna", RejectReason::missing_object, 9, "it", {}},
      {"deliver the green bok to Anna", RejectReason::unknown_object, 19, "bok", {"book", "box"}},
      {"deliver letter-99 to Anna", RejectReason::unknown_object, 9, "letter-99", {}},
      {"deliver the white letter-4 to Anna", RejectReason::unexpected_word, 13, "white", {}},
      {"deliver the grene book to Anna", RejectReason::unknown_colour, 13, "grene", {"green"}},
      {"deliver the red letter to", RejectReason::missing_place, 26, "", {}},
      {"deliver the red letter from to Anna", RejectReason::missing_place, 29, "to", {}},
      {"deliver the green book to A-122",
       RejectReason::unknown_place,
       27,
       "A-122",
       {"A-112", "A-120", "A-121"}},
      {"deliver the green book from Miachel's desk to Anna",
       RejectReason::unknown_person,
       29,
       "Miachel's",
       {"Michael"}},
      {"deliver the green book to the desk in room A-999",
       RejectReason::unknown_room,
       44,
       "A-999",
       {}},
      {"put the red letter on the meeting table in room A-110 on the desk in room A-120",
       RejectReason::place_not_in_room,
       27,
       "meeting",
       {"librarian-desk"}},
      {"deliver the green book to the table in room A-114",
       RejectReason::place_not_in_room,
       31,
       "table",
       {"a114-desk"}},
      {"put the red letter on the desk", RejectReason::ambiguous_place, 27, "desk", {}},
      {"deliver the green book to the secretary",
       RejectReason::ambiguous_person,
       31,
       "secretary",
       {"Jan", "Anna"}},
      {"deliver the envelope from the mail tray to Sebastian",
       RejectReason::ambiguous_object,
       13,
       "envelope",
       {"envelope-1", "envelope-2"}},
      {"deliver letter-4 from Michael to Anna", RejectReason::object_elsewhere, 23, "Michael", {}},
      {"deliver letter-9 to Anna", RejectReason::object_aboard, 9, "letter-9", {}},
      {"deliver the purple box to Anna", RejectReason::missing_pickup, 31, "", {}},
      {"pick up the letter from Wolfram and deliver it",
       RejectReason::missing_destination,
       47,
       "",
       {}},
      {"deliver the green book from the librarian to the librarian",
       RejectReason::same_place,
       50,
       "librarian",
       {}},
      {"deliver the green book to Anna by 25:00", RejectReason::bad_time, 35, "25:00", {}},
      {"deliver the green book to Anna within 20", RejectReason::bad_time, 41, "", {}},
      {"deliver the green book to Anna within 20 days", RejectReason::bad_time, 42, "days", {}},
      {"deliver the green book to Anna by 9", RejectReason::deadline_in_past, 35, "9", {}},
      {"deliver the green book to Anna within 0 minutes",
       RejectReason::deadline_in_past,
       39,
       "0",
       {}},
      {"deliver the green book to Anna within 900 hours",
       RejectReason::deadline_after_midnight,
       39,
       "900",
       {}},
      {"deliver the green book from the librarian to Anna to Jan",
       RejectReason::repeated_phrase,
       51,
       "to",
       {}},
      {"deliver the green book to Anna by 10 by 11", RejectReason::repeated_phrase, 38, "by", {}},
      {"cancel job", RejectReason::missing_job, 11, "", {}},
      {"change the deadline of job to 11:00", RejectReason::missing_job, 28, "to", {}},
  };
  return all;
}

TEST(Rejections, EachWithItsReasonWordAndColumn) {
  const OfficeKnowledge k = office_for_rejections();
  for (const Case& c : cases()) {
    const Rejection r = test::rejected(c.text, k);
    SCOPED_TRACE(c.text.substr(0, 80) + "  ->  " + r.message);
    EXPECT_EQ(to_string(r.reason), std::string(to_string(c.reason)));
    EXPECT_EQ(r.column, c.column);
    EXPECT_EQ(r.word, c.word);
    EXPECT_FALSE(r.message.empty());
    EXPECT_TRUE(r.field.empty());
    if (!c.suggestions.empty()) {
      EXPECT_EQ(r.suggestions, c.suggestions);
    }
  }
}

TEST(Rejections, EveryReasonIsExercised) {
  std::set<RejectReason> seen;
  for (const Case& c : cases()) seen.insert(c.reason);
  EXPECT_EQ(seen.size(), static_cast<std::size_t>(RejectReason::missing_job) + 1);
}

TEST(Rejections, UnknownNamesAreSuggestedInTheMessage) {
  const Rejection r = test::rejected("deliver the green book to A-122", test::paper_office());
  EXPECT_EQ(r.message, "no place or person 'A-122'; did you mean A-112, A-120 or A-121?");
  const Rejection far = test::rejected("deliver the green book to Zanzibar", test::paper_office());
  EXPECT_EQ(far.message, "no place or person 'Zanzibar'");
  EXPECT_TRUE(far.suggestions.empty());
}

TEST(Rejections, AmbiguousObjectsAreListed) {
  const Rejection r =
      test::rejected("deliver the book from the librarian to Anna", test::paper_office());
  EXPECT_EQ(r.reason, RejectReason::ambiguous_object);
  EXPECT_EQ(
      r.message,
      "there are 2 books at librarian-desk (book-green and book-red); say which by its colour "
      "or id");
  EXPECT_EQ(r.suggestions, (Strings{"book-green", "book-red"}));
}

TEST(Rejections, PastDeadlinesAreJudgedAgainstNow) {
  const OfficeKnowledge k = test::paper_office();
  const std::string text = "deliver the green book to Anna by 10:00";
  EXPECT_TRUE(interpret_command(text, k, 3600.0).accepted());         // 09:30
  const CommandAnswer late = interpret_command(text, k, 3 * 3600.0);  // 11:30
  ASSERT_FALSE(late.accepted());
  EXPECT_EQ(late.rejection.reason, RejectReason::deadline_in_past);
  EXPECT_EQ(late.rejection.message, "the deadline 10:00 is not after now (11:30)");
}

}  // namespace
}  // namespace autonomy::courier
