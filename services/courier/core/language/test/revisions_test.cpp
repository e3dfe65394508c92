// Revisions as text: cancel a job, change its destination or deadline.
#include "services/courier/core/language/test/language_fixture.hpp"

namespace autonomy::courier {
namespace {

using test::hm;

Revision accepted_revision(const std::string& text, const OfficeKnowledge& k) {
  const CommandAnswer a = interpret_command(text, k, test::kNowSim);
  EXPECT_EQ(a.kind, CommandAnswer::Kind::revision) << text << ": " << a.summary();
  return a.revision;
}

class Revisions : public ::testing::Test {
 protected:
  OfficeKnowledge k = test::paper_office();
};

TEST_F(Revisions, Cancel) {
  for (const char* text :
       {"cancel job J7", "Cancel J7.", "please cancel the job J7", "cancel job J7 please"}) {
    const Revision r = accepted_revision(text, k);
    EXPECT_EQ(r.kind, Revision::Kind::cancel) << text;
    EXPECT_EQ(r.job, "J7") << text;  // as written
    EXPECT_EQ(std::string(text).substr(r.job_column - 1, 2), "J7") << text;
  }
}

TEST_F(Revisions, ChangeTheDestination) {
  const Revision r = accepted_revision("change the destination of job j-3 to Michael", k);
  EXPECT_EQ(r.kind, Revision::Kind::change);
  EXPECT_EQ(r.job, "j-3");
  EXPECT_EQ(r.job_column, 31);
  EXPECT_EQ(r.delivery_place, "michael-desk");
  EXPECT_EQ(r.delivery_person, "Michael");
  EXPECT_FALSE(r.deadline_s.has_value());
  EXPECT_EQ(r.assumptions, std::vector<std::string>{"destination: Michael's desk (michael-desk)"});
  EXPECT_EQ(
      accepted_revision("change the destination of j1 to the desk in room A-119", k).delivery_place,
      "a119-desk");
  EXPECT_EQ(accepted_revision("deliver job j1 to room A-114", k).delivery_place, "a114-desk");
}

TEST_F(Revisions, ChangeTheDeadline) {
  Revision r = accepted_revision("change the deadline of job j1 to 11:30", k);
  EXPECT_EQ(r.kind, Revision::Kind::change);
  EXPECT_EQ(r.deadline_s, hm(11, 30));
  EXPECT_TRUE(r.delivery_place.empty());
  EXPECT_EQ(accepted_revision("change the deadline of job j1 to within 20 minutes", k).deadline_s,
            hm(9, 50));
  r = accepted_revision("deliver job j1 by 11:30", k);
  EXPECT_EQ(r.deadline_s, hm(11, 30));
  EXPECT_TRUE(r.delivery_place.empty());
  r = accepted_revision("bring job j1 to Anna before 11", k);
  EXPECT_EQ(r.deadline_s, hm(11, 0));
  EXPECT_EQ(r.delivery_place, "a114-desk");
}

TEST_F(Revisions, CheckedLikeCommands) {
  struct Case {
    const char* text;
    RejectReason reason;
    int column;
  };
  for (const Case& c : {
           Case{"change the deadline of job j1 to 9:00", RejectReason::deadline_in_past, 34},
           Case{"change the deadline of job j1 to soon", RejectReason::bad_time, 34},
           Case{"change the destination of job j1 to A-122", RejectReason::unknown_place, 37},
           Case{"change the destination of job j1", RejectReason::unexpected_word, 33},
           Case{"change the destination of job j1 to Anna by 11", RejectReason::unexpected_word,
                42},
           Case{"change the owner of job j1 to Anna", RejectReason::unexpected_word, 12},
           Case{"deliver job j1", RejectReason::missing_destination, 15},
           Case{"deliver job j1 from Anna", RejectReason::unexpected_word, 16},
           Case{"deliver job j1 by 11 by 12", RejectReason::repeated_phrase, 22},
           Case{"cancel job j1 j2", RejectReason::unexpected_word, 15},
           Case{"cancel the", RejectReason::missing_job, 11},
       }) {
    const Rejection r = test::rejected(c.text, k);
    EXPECT_EQ(to_string(r.reason), std::string(to_string(c.reason))) << c.text << ": " << r.message;
    EXPECT_EQ(r.column, c.column) << c.text << ": " << r.message;
  }
}

TEST_F(Revisions, Summaries) {
  EXPECT_EQ(interpret_command("cancel job j1", k, test::kNowSim).summary(), "cancel job j1");
  EXPECT_EQ(interpret_command("deliver job j1 to Anna by 11", k, test::kNowSim).summary(),
            "change job j1: destination a114-desk deadline 11:00");
}

}  // namespace
}  // namespace autonomy::courier
