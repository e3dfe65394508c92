// The command forms of the paper and of issue 9, with their complete interpretations.
#include "services/courier/core/language/test/language_fixture.hpp"

namespace autonomy::courier {
namespace {

using test::accepted_delivery;
using test::hm;
using Strings = std::vector<std::string>;

class PaperCommands : public ::testing::Test {
 protected:
  OfficeKnowledge k = test::paper_office();
};

TEST_F(PaperCommands, PutTheRedLetterOnTheMeetingTableOnTheDeskInA120) {
  const Interpretation i = accepted_delivery(
      "put the red letter on the meeting table in room A-111 on the desk in room A-120", k);
  EXPECT_EQ(i.object.kind, "letter");
  EXPECT_EQ(i.object.colour, "red");
  EXPECT_EQ(i.object.id, "letter-red");
  EXPECT_EQ(i.pickup_place, "meeting-table");
  EXPECT_EQ(i.pickup_person, "");
  EXPECT_EQ(i.delivery_place, "michael-desk");
  EXPECT_EQ(i.delivery_person, "Michael");
  EXPECT_FALSE(i.deadline_s.has_value());
  EXPECT_EQ(i.assumptions,
            Strings{"object: the red letter known to be on meeting-table (letter-red)"});
}

TEST_F(PaperCommands, DeliverTheGreenBookFromTheLibrariansDeskToTheDeskInA114) {
  const Interpretation i = accepted_delivery(
      "deliver the green book from the librarian's desk in room A-110 to the desk in room A-114.",
      k);
  EXPECT_EQ(i.object.id, "book-green");
  EXPECT_EQ(i.pickup_place, "librarian-desk");
  EXPECT_EQ(i.pickup_person, "librarian");
  EXPECT_EQ(i.delivery_place, "a114-desk");
  EXPECT_EQ(i.delivery_person, "Anna");
  EXPECT_EQ(i.assumptions,
            (Strings{"pickup: the librarian's desk (librarian-desk)",
                     "object: the green book known to be on the librarian's desk (book-green)"}));
}

TEST_F(PaperCommands, PickUpTheLetterFromWolframAndDeliverIt) {
  k.learned.record("Wolfram", "letter", "michael-desk");
  k.learned.record("Wolfram", "letter", "michael-desk");
  k.learned.record("Wolfram", "letter", "a114-desk");
  const Interpretation i = accepted_delivery("pick up the letter from Wolfram and deliver it", k);
  EXPECT_EQ(i.object.id, "letter-4");
  EXPECT_EQ(i.pickup_place, "a118-desk");
  EXPECT_EQ(i.pickup_person, "Wolfram");
  EXPECT_EQ(i.delivery_place, "michael-desk");
  EXPECT_EQ(i.delivery_person, "Michael");
  EXPECT_EQ(i.assumptions,
            (Strings{"pickup: Wolfram's desk (a118-desk)",
                     "object: the white letter known to be on Wolfram's desk (letter-4)",
                     "destination: Michael, the most frequent destination of letters from Wolfram "
                     "(michael-desk, 2 of 3)"}));
}

TEST_F(PaperCommands, CaseArticlesAndPunctuationDoNotMatter) {
  const Interpretation a =
      accepted_delivery("PUT RED LETTER ON MEETING TABLE IN ROOM A-111 ON DESK IN ROOM A-120!!", k);
  const Interpretation b = accepted_delivery(
      "  please, put the red letter on the meeting-table in A-111; on the desk in a-120.  ", k);
  EXPECT_EQ(a.object.id, "letter-red");
  EXPECT_EQ(a.pickup_place, b.pickup_place);
  EXPECT_EQ(a.delivery_place, b.delivery_place);
  EXPECT_EQ(b.delivery_place, "michael-desk");
}

TEST_F(PaperCommands, Deadlines) {
  struct Case {
    const char* deadline;
    double seconds_of_day;
  };
  for (const Case& c :
       {Case{"by 10:30", hm(10, 30)}, Case{"before 11", hm(11, 0)}, Case{"until 2 pm", hm(14, 0)},
        Case{"by 2pm", hm(14, 0)}, Case{"by 12 am", -1.0}, Case{"by noon", hm(12, 0)},
        Case{"by 10.45", hm(10, 45)}, Case{"within 20 minutes", hm(9, 50)},
        Case{"within 2 hours", hm(11, 30)}, Case{"in 90 min", hm(11, 0)},
        Case{"in half an hour", hm(10, 0)}, Case{"within an hour", hm(10, 30)},
        Case{"within 20min", hm(9, 50)}, Case{"by 24:00", hm(24, 0)}}) {
    const std::string text = std::string("deliver the green book to Anna ") + c.deadline;
    const CommandAnswer a = interpret_command(text, k, test::kNowSim);
    if (c.seconds_of_day < 0) {  // 12 am is midnight, long past at 09:30
      EXPECT_EQ(a.rejection.reason, RejectReason::deadline_in_past) << text;
      continue;
    }
    ASSERT_EQ(a.kind, CommandAnswer::Kind::delivery) << text << ": " << a.summary();
    ASSERT_TRUE(a.delivery.deadline_s.has_value()) << text;
    EXPECT_DOUBLE_EQ(*a.delivery.deadline_s, c.seconds_of_day) << text;
  }
}

TEST_F(PaperCommands, TheDeadlineMayComeAnywhereAfterTheObject) {
  const Interpretation i = accepted_delivery("deliver the green book by 10:30 to Michael", k);
  EXPECT_EQ(i.delivery_place, "michael-desk");
  EXPECT_EQ(i.deadline_s, hm(10, 30));
  const Interpretation j =
      accepted_delivery("pick up the letter from Wolfram by 11 and deliver it to Michael", k);
  EXPECT_EQ(j.deadline_s, hm(11, 0));
  EXPECT_EQ(j.delivery_place, "michael-desk");
}

TEST_F(PaperCommands, PeopleAsPlaces) {
  const Interpretation i =
      accepted_delivery("deliver the red book from the librarian to Michael", k);
  EXPECT_EQ(i.pickup_place, "librarian-desk");
  EXPECT_EQ(i.pickup_person, "librarian");
  EXPECT_EQ(i.delivery_place, "michael-desk");
  EXPECT_EQ(i.delivery_person, "Michael");
  EXPECT_EQ(i.assumptions,
            (Strings{"pickup: the librarian's desk (librarian-desk)",
                     "object: the red book known to be on the librarian's desk (book-red)",
                     "destination: Michael's desk (michael-desk)"}));
  // Possessives name the person's desk; "Wolfram's letter" is the letter from Wolfram.
  EXPECT_EQ(accepted_delivery("bring Wolfram's letter to Michael's desk", k).object.id, "letter-4");
  EXPECT_EQ(accepted_delivery("take the blue letter to Anna's", k).delivery_place, "a114-desk");
  EXPECT_EQ(accepted_delivery("take the blue letter to Anna's office", k).delivery_place,
            "a114-desk");
  // Roles name people too.
  k.people[3].roles = {"professor"};
  EXPECT_EQ(accepted_delivery("take the blue letter to the professor", k).delivery_place,
            "a118-desk");
}

TEST_F(PaperCommands, RoomsAsPlaces) {
  const Interpretation i = accepted_delivery("bring the red book to room A-114", k);
  EXPECT_EQ(i.delivery_place, "a114-desk");
  EXPECT_EQ(i.delivery_person, "Anna");
  EXPECT_EQ(i.assumptions.back(), "destination: room A-114 means Anna's desk (a114-desk)");
  // A room without a person: its loading station, else its only place.
  EXPECT_EQ(accepted_delivery("take the blue letter to A-116", k).delivery_place, "mail-tray");
  EXPECT_EQ(accepted_delivery("take the blue letter to the mail room", k).delivery_place,
            "mail-tray");
  EXPECT_EQ(accepted_delivery("take the red book to A-113", k).delivery_place, "a113-desk");
  const Interpretation m = accepted_delivery("put the red letter in room A-111 in room A-120", k);
  EXPECT_EQ(m.pickup_place, "meeting-table");
  EXPECT_EQ(m.delivery_place, "michael-desk");
}

TEST_F(PaperCommands, ObjectsByIdAndPlacesByName) {
  const Interpretation i = accepted_delivery("deliver letter-3 to a114-desk", k);
  EXPECT_EQ(i.object.id, "letter-3");
  EXPECT_EQ(i.object.kind, "letter");
  EXPECT_EQ(i.object.colour, "blue");
  EXPECT_EQ(i.pickup_place, "meeting-table");
  EXPECT_EQ(i.assumptions, Strings{"pickup: meeting-table, where letter-3 is known to be"});
  EXPECT_EQ(accepted_delivery("carry the white envelope from mail-tray to jan", k).delivery_place,
            "a112-desk");
}

TEST_F(PaperCommands, OtherVerbsAndOrders) {
  EXPECT_EQ(accepted_delivery("bring the green book to Anna from the librarian", k).pickup_place,
            "librarian-desk");
  EXPECT_EQ(
      accepted_delivery("take the red letter from the meeting table to Jan", k).delivery_place,
      "a112-desk");
  EXPECT_EQ(accepted_delivery("move the blue letter onto the desk in room A-119", k).delivery_place,
            "a119-desk");
  const Interpretation p =
      accepted_delivery("pick up the yellow letter at Jan's desk and bring it to Sebastian", k);
  EXPECT_EQ(p.pickup_place, "a112-desk");
  EXPECT_EQ(p.delivery_place, "a121-desk");
  // One "on" place with a "to" place is where the object lies.
  const Interpretation on =
      accepted_delivery("deliver the red letter on the meeting table to Anna", k);
  EXPECT_EQ(on.pickup_place, "meeting-table");
  EXPECT_EQ(on.delivery_place, "a114-desk");
}

}  // namespace
}  // namespace autonomy::courier
