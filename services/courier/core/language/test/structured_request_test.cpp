// The structured request: the same checks and completion as text, field names instead of columns.
#include "services/courier/core/language/structured_request.hpp"

#include "services/courier/core/language/test/language_fixture.hpp"

#include <limits>

namespace autonomy::courier {
namespace {

using test::hm;

void expect_same(const Interpretation& a, const Interpretation& b, const std::string& what) {
  EXPECT_EQ(a.object.kind, b.object.kind) << what;
  EXPECT_EQ(a.object.colour, b.object.colour) << what;
  EXPECT_EQ(a.object.id, b.object.id) << what;
  EXPECT_EQ(a.pickup_place, b.pickup_place) << what;
  EXPECT_EQ(a.delivery_place, b.delivery_place) << what;
  EXPECT_EQ(a.pickup_person, b.pickup_person) << what;
  EXPECT_EQ(a.delivery_person, b.delivery_person) << what;
  EXPECT_EQ(a.deadline_s, b.deadline_s) << what;
  EXPECT_EQ(a.assumptions, b.assumptions) << what;
}

class Structured : public ::testing::Test {
 protected:
  Structured() { k.learned.record("Wolfram", "letter", "michael-desk"); }
  CommandAnswer ask(const StructuredRequest& r) { return interpret_request(r, k, test::kNowSim); }
  OfficeKnowledge k = test::paper_office();
};

TEST_F(Structured, GivesTheSameInterpretationsAsText) {
  struct Pair {
    const char* text;
    StructuredRequest request;
  };
  StructuredRequest deadline_s{"", "book", "green", "", "Michael", "", hm(10, 30)};
  for (const Pair& p : {
           Pair{"deliver the green book from the librarian to room A-114 by 10:30",
                {"", "book", "green", "librarian", "A-114", "10:30", std::nullopt}},
           Pair{"deliver the green book to Michael by 10:30", deadline_s},
           Pair{"pick up the letter from Wolfram and deliver it",
                {"", "letter", "", "Wolfram", "", "", std::nullopt}},
           Pair{"deliver letter-3 to the mail room",
                {"letter-3", "", "", "", "mail room", "", std::nullopt}},
           Pair{"put the red letter on the meeting table on michael-desk",
                {"", "Letter", "RED", "meeting-table", "michael-desk", "", std::nullopt}},
       }) {
    const CommandAnswer text = interpret_command(p.text, k, test::kNowSim);
    const CommandAnswer structured = ask(p.request);
    ASSERT_EQ(text.kind, CommandAnswer::Kind::delivery) << p.text << ": " << text.summary();
    ASSERT_EQ(structured.kind, CommandAnswer::Kind::delivery)
        << p.text << ": " << structured.summary();
    expect_same(text.delivery, structured.delivery, p.text);
  }
}

TEST_F(Structured, RejectionsNameTheField) {
  struct Case {
    StructuredRequest request;
    RejectReason reason;
    const char* field;
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const Case& c : {
           Case{{}, RejectReason::missing_object, "kind"},
           Case{{"", "", "red", "Jan", "Anna", "", std::nullopt},
                RejectReason::missing_object,
                "kind"},
           Case{{"", "bok", "", "Jan", "Anna", "", std::nullopt},
                RejectReason::unknown_object,
                "kind"},
           Case{{"letter-99", "", "", "", "Anna", "", std::nullopt},
                RejectReason::unknown_object,
                "object_id"},
           Case{{"letter-3", "book", "", "", "Anna", "", std::nullopt},
                RejectReason::unknown_object,
                "object_id"},
           Case{{"", "letter", "grene", "Jan", "Anna", "", std::nullopt},
                RejectReason::unknown_colour,
                "colour"},
           Case{{"", "letter", "", "A-122", "Anna", "", std::nullopt},
                RejectReason::unknown_place,
                "from"},
           Case{{"", "letter", "", "Jan", "Micheal", "", std::nullopt},
                RejectReason::unknown_place,
                "to"},
           Case{{"", "letter", "", "Jan", "Jan", "", std::nullopt}, RejectReason::same_place, "to"},
           Case{{"", "letter", "", "Jan", "", "", std::nullopt},
                RejectReason::missing_destination,
                "to"},
           Case{{"", "letter", "", "Jan", "Anna", "10:61", std::nullopt},
                RejectReason::bad_time,
                "deadline"},
           Case{{"", "letter", "", "Jan", "Anna", "09:00", std::nullopt},
                RejectReason::deadline_in_past,
                "deadline"},
           Case{{"", "letter", "", "Jan", "Anna", "", nan}, RejectReason::bad_time, "deadline_s"},
           Case{{"", "letter", "", "Jan", "Anna", "", 90000.0},
                RejectReason::deadline_after_midnight,
                "deadline_s"},
           Case{{"", "letter", "", "Jan", "Anna", "11:00", hm(11, 0)},
                RejectReason::repeated_phrase,
                "deadline"},
           Case{{"", "letter", "", std::string(200, 'x'), "Anna", "", std::nullopt},
                RejectReason::too_long,
                "from"},
           Case{{"", "letter", "", "Jan\n", "Anna", "", std::nullopt},
                RejectReason::bad_character,
                "from"},
           Case{{"", "box", "purple", "", "Anna", "", std::nullopt},
                RejectReason::missing_pickup,
                "from"},
           Case{{"", "envelope", "", "mail-tray", "Anna", "", std::nullopt},
                RejectReason::ambiguous_object,
                "kind"},
       }) {
    const CommandAnswer a = ask(c.request);
    ASSERT_FALSE(a.accepted()) << a.summary();
    EXPECT_EQ(to_string(a.rejection.reason), std::string(to_string(c.reason)))
        << a.rejection.message;
    EXPECT_EQ(a.rejection.field, c.field) << a.rejection.message;
    EXPECT_EQ(a.rejection.column, 0);
    EXPECT_FALSE(a.rejection.message.empty());
  }
}

TEST_F(Structured, SuggestionsForUnknownNames) {
  const CommandAnswer a = ask({"", "book", "green", "", "A-122", "", std::nullopt});
  EXPECT_EQ(a.rejection.suggestions, (std::vector<std::string>{"A-112", "A-120", "A-121"}));
  EXPECT_EQ(a.rejection.word, "A-122");
  EXPECT_EQ(a.summary(),
            "rejected (unknown_place) in field to: no place or person 'A-122'; did you mean A-112, "
            "A-120 or A-121?");
}

}  // namespace
}  // namespace autonomy::courier
