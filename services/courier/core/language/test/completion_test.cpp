// Incomplete commands completed from knowledge, and what is said about it.
#include "services/courier/core/language/test/language_fixture.hpp"

namespace autonomy::courier {
namespace {

using test::accepted_delivery;
using test::rejected;
using Strings = std::vector<std::string>;

class Completion : public ::testing::Test {
 protected:
  OfficeKnowledge k = test::paper_office();
};

TEST_F(Completion, TheObjectKnownAtThePickupPlace) {
  const Interpretation i = accepted_delivery("deliver the letter from Jan to Anna", k);
  EXPECT_EQ(i.object.id, "letter-2");
  EXPECT_EQ(i.object.colour, "yellow");  // filled in from the known object
  EXPECT_EQ(i.assumptions[1], "object: the yellow letter known to be on Jan's desk (letter-2)");
}

TEST_F(Completion, AnObjectNotKnownAtThePickupIsAnnounced) {
  const Interpretation i = accepted_delivery("deliver the green letter from Jan to Anna", k);
  EXPECT_EQ(i.object.id, "");
  EXPECT_EQ(i.object.kind, "letter");
  EXPECT_EQ(i.object.colour, "green");
  EXPECT_EQ(i.pickup_place, "a112-desk");
  EXPECT_EQ(
      i.assumptions[1],
      "object: a green letter not yet known to be at a112-desk; it is to be handed over there");
  // A kind the knowledge has never seen, but a common word, with a pickup place.
  EXPECT_EQ(accepted_delivery("deliver the parcel from the mail tray to Anna", k).object.kind,
            "parcel");
}

TEST_F(Completion, ThePickupWhereTheOnlyMatchingObjectLies) {
  const Interpretation i = accepted_delivery("deliver the yellow letter to Anna", k);
  EXPECT_EQ(i.pickup_place, "a112-desk");
  EXPECT_EQ(i.pickup_person, "Jan");
  EXPECT_EQ(i.assumptions[0],
            "pickup: Jan's desk (a112-desk), where the yellow letter is known to be (letter-2)");
}

TEST_F(Completion, ObjectsAboardARobotAreNotLyingAnywhere) {
  k.objects[1].place.clear();  // the red book, aboard
  k.objects[1].carrier = "rhino";
  EXPECT_EQ(accepted_delivery("deliver the book from the librarian to Anna", k).object.id,
            "book-green");
  EXPECT_EQ(rejected("deliver the red book to Anna", k).reason, RejectReason::missing_pickup);
}

TEST_F(Completion, TheAddresseeBeforeLearnedDestinations) {
  k.objects[8].addressee = "Sebastian";  // letter-4 on Wolfram's desk
  k.learned.record("Wolfram", "letter", "michael-desk");
  const Interpretation i = accepted_delivery("pick up the letter from Wolfram and deliver it", k);
  EXPECT_EQ(i.delivery_place, "a121-desk");
  EXPECT_EQ(i.delivery_person, "Sebastian");
  EXPECT_EQ(i.assumptions.back(), "destination: Sebastian, the addressee of letter-4 (a121-desk)");
}

TEST_F(Completion, LearnedDestinationsByPersonThenAnyKind) {
  k.learned.record("Wolfram", "book", "a114-desk");
  k.learned.record("Wolfram", "letter", "a112-desk");
  k.learned.record("Wolfram", "letter", "michael-desk");
  k.learned.record("Wolfram", "letter", "michael-desk");
  EXPECT_EQ(accepted_delivery("pick up the letter from Wolfram and deliver it", k).delivery_place,
            "michael-desk");
  // Learned from the place when nobody sits there.
  k.learned.record("meeting-table", "letter", "a121-desk");
  const Interpretation t = accepted_delivery("pick up the blue letter from the meeting table", k);
  EXPECT_EQ(t.delivery_place, "a121-desk");
  EXPECT_EQ(t.assumptions.back(),
            "destination: Sebastian, the most frequent destination of letters from meeting-table "
            "(a121-desk, 1 of 1)");
}

TEST_F(Completion, NothingToCompleteFromIsRejectedSayingWhatIsMissing) {
  const Rejection r = rejected("pick up the letter from Wolfram", k);
  EXPECT_EQ(r.reason, RejectReason::missing_destination);
  EXPECT_EQ(r.message,
            "where to deliver the white letter is not said, and no destination of letters from "
            "Wolfram has been learned; say 'to' a place or person");
  const Rejection p = rejected("deliver the purple box to Anna", k);
  EXPECT_EQ(p.message, "no purple box is known to be anywhere; say where to pick it up");
}

TEST_F(Completion, AmbiguousWithoutAPickupListsEveryCandidate) {
  const Rejection r = rejected("deliver the white letter to Anna", k);
  EXPECT_EQ(r.reason, RejectReason::ambiguous_object);
  EXPECT_EQ(r.suggestions, (Strings{"letter-1", "letter-4"}));
  // Saying where resolves it.
  EXPECT_EQ(accepted_delivery("deliver the white letter from Michael to Anna", k).object.id,
            "letter-1");
}

TEST_F(Completion, KnowledgeChangesChangeTheAnswer) {
  // The courier learns that the red letter moved to Jan's desk.
  for (KnownObject& o : k.objects)
    if (o.id == "letter-red") o.place = "a112-desk";
  const Interpretation i = accepted_delivery("deliver the red letter to Michael", k);
  EXPECT_EQ(i.pickup_place, "a112-desk");
  const Interpretation paper = accepted_delivery(
      "put the red letter on the meeting table in room A-111 on the desk in room A-120", k);
  EXPECT_EQ(paper.object.id, "");  // no longer known to be there
  EXPECT_EQ(rejected("deliver letter-red from the meeting table to Michael", k).reason,
            RejectReason::object_elsewhere);
}

}  // namespace
}  // namespace autonomy::courier
