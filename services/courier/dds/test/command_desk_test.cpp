// The command desk over the office scenario's knowledge, a real journal and an executive with a
// scripted scheduler: acceptances are journalled before they are answered, repeats get the same
// reply, every rejection says why.
#include "services/courier/dds/command_desk.hpp"
#include "services/courier/dds/office_file.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <unistd.h>

namespace autonomy::courier {
namespace {

class NoScheduler : public ScheduleSource {
 public:
  Plan plan(const PlanRequest&) override { return {}; }
};

class CommandDeskTest : public ::testing::Test {
 protected:
  CommandDeskTest()
      : office_(load_courier_office(std::string(AUTONOMY_SOURCE_DIR) + "/deploy/scenarios/office.pbtxt").office.value()),
        path_("/tmp/command_desk_test_" + std::to_string(getpid()) + ".db"),
        executive_(office_.floor, scheduler_) {
    for (const char* suffix : {"", "-wal", "-shm"}) std::remove((path_ + suffix).c_str());
    journal_ = std::make_unique<Journal>(path_);
    desk_ = std::make_unique<CommandDesk>(office_.knowledge, executive_, *journal_, 0);
    executive_.add_robot("rhino", 3);
  }
  msg::CourierReply text(const std::string& id, const std::string& words) {
    msg::CourierCommand c;
    c.command_id = id;
    c.requester = "test";
    c.text = words;
    return desk_->handle(c, kNine, 1);
  }
  static constexpr double kNine = 1800.0;  // 09:00 (the day starts at 08:30)

  CourierOffice office_;
  std::string path_;
  NoScheduler scheduler_;
  CourierExecutive executive_;
  std::unique_ptr<Journal> journal_;
  std::unique_ptr<CommandDesk> desk_;
};

TEST_F(CommandDeskTest, ThePapersCommandIsAcceptedJournalledAndAnsweredAgainOnRepeat) {
  const msg::CourierReply r =
      text("c1", "put the red letter on the meeting table in room A-111 on the desk in room A-120 by 10:30");
  ASSERT_TRUE(r.accepted) << r.reason << ": " << r.detail;
  EXPECT_EQ(r.job_id, "job-1");
  EXPECT_EQ(r.action, "deliver");
  EXPECT_EQ(r.from, "meeting-table");
  EXPECT_EQ(r.to, "michael-desk");
  EXPECT_EQ(r.deadline, "10:30");
  ASSERT_NE(executive_.job("job-1"), nullptr);
  EXPECT_EQ(executive_.job("job-1")->object.id, "letter-red");
  EXPECT_DOUBLE_EQ(*executive_.job("job-1")->deadline_s, 10.5 * 3600);
  // In the journal before the reply went out, and the repeat is the same answer, no second job.
  const Journal::Contents c = journal_->load();
  ASSERT_EQ(c.jobs.size(), 1u);
  EXPECT_EQ(c.jobs[0].destination, "michael-desk");
  const msg::CourierReply again = text("c1", "deliver the green book from the librarian to Anna");
  EXPECT_EQ(again.job_id, "job-1");
  EXPECT_EQ(again.to, "michael-desk");
  EXPECT_EQ(journal_->load().jobs.size(), 1u);
  // A desk restarted on the same journal numbers on.
  CommandDesk restarted(office_.knowledge, executive_, *journal_, journal_->load().jobs_created);
  msg::CourierCommand c2;
  c2.command_id = "c2";
  c2.text = "deliver the green book from the librarian's desk in room A-110 to the desk in room A-114";
  EXPECT_EQ(restarted.handle(c2, kNine, 2).job_id, "job-2");
}

// One object in one open job: a second command for the green book names the job that holds it;
// once that job has delivered it, the book is known to lie at Anna's desk and commands follow.
TEST_F(CommandDeskTest, AnObjectInAnOpenJobIsRefusedNamingThatJobAndItsPlaceFollowsItsDelivery) {
  const msg::CourierReply first = text("c1", "deliver the green book from the librarian to Anna");
  ASSERT_TRUE(first.accepted) << first.reason << ": " << first.detail;
  const msg::CourierReply second = text("c2", "deliver the green book from the librarian to Michael");
  EXPECT_FALSE(second.accepted);
  EXPECT_EQ(second.reason, "object_in_open_job");
  EXPECT_EQ(second.job_id, "job-1");
  EXPECT_EQ(second.word, "book-green");
  EXPECT_NE(second.detail.find("book-green is in open job job-1 (to a114-desk, queued)"), std::string::npos)
      << second.detail;
  // Structured, by id: the same answer.
  msg::CourierCommand by_id;
  by_id.command_id = "c3";
  by_id.kind = msg::CourierCommandKind::Deliver;
  by_id.object_id = "book-green";
  by_id.to = "michael-desk";
  EXPECT_EQ(desk_->handle(by_id, kNine, 1).reason, "object_in_open_job");
  EXPECT_EQ(executive_.jobs().size(), 1u);

  // The job delivers the book (its object belief moves with the handovers; here restored so).
  Job delivered = *executive_.job("job-1");
  delivered.state = JobState::completed;
  delivered.object_place = "a114-desk";
  executive_.restore_job(delivered);
  const msg::CourierReply from_old_place = text("c4", "deliver the green book from the librarian to Michael");
  EXPECT_FALSE(from_old_place.accepted);
  EXPECT_EQ(from_old_place.detail, "no green book is known to be at librarian-desk; name a known object or its place");
  const msg::CourierReply onwards = text("c5", "deliver the green book to Michael");
  ASSERT_TRUE(onwards.accepted) << onwards.reason << ": " << onwards.detail;
  EXPECT_EQ(onwards.from, "a114-desk");
  EXPECT_EQ(onwards.to, "michael-desk");
}

TEST_F(CommandDeskTest, RejectionsSayWhyAndWhere) {
  const msg::CourierReply unknown = text("c1", "deliver the green book from the librarian to room A-122");
  EXPECT_FALSE(unknown.accepted);
  EXPECT_EQ(unknown.reason, "unknown_room");
  EXPECT_EQ(unknown.word, "A-122");
  EXPECT_GT(unknown.column, 0);
  EXPECT_FALSE(unknown.suggestions.empty());
  const msg::CourierReply past = text("c2", "deliver the green book from the librarian to Anna by 08:00");
  EXPECT_EQ(past.reason, "deadline_in_past");
  const msg::CourierReply too_long = text("c3", std::string(2000, 'a'));
  EXPECT_EQ(too_long.reason, "too_long");
  EXPECT_EQ(too_long.detail, "text has 2000 bytes, more than 1024");
  msg::CourierCommand no_id;
  no_id.text = "deliver the green book from the librarian to Anna";
  EXPECT_EQ(desk_->handle(no_id, kNine, 1).reason, "invalid_command");
  msg::CourierCommand bad_kind;
  bad_kind.command_id = "c4";
  bad_kind.kind = static_cast<msg::CourierCommandKind>(9);
  EXPECT_EQ(desk_->handle(bad_kind, kNine, 1).reason, "invalid_command");
  EXPECT_TRUE(executive_.jobs().empty());
}

TEST_F(CommandDeskTest, StructuredDeliverCancelAndRevise) {
  msg::CourierCommand d;
  d.command_id = "s1";
  d.kind = msg::CourierCommandKind::Deliver;
  d.object_id = "book-green";
  d.from = "librarian";
  d.to = "Anna";
  d.deadline = "11:00";
  const msg::CourierReply r = desk_->handle(d, kNine, 1);
  ASSERT_TRUE(r.accepted) << r.reason << ": " << r.detail;
  EXPECT_EQ(r.to, "a114-desk");

  msg::CourierCommand revise;
  revise.command_id = "s2";
  revise.kind = msg::CourierCommandKind::Revise;
  revise.job_id = r.job_id;
  revise.to = "Michael";
  revise.deadline = "11:30";
  const msg::CourierReply rr = desk_->handle(revise, kNine, 2);
  ASSERT_TRUE(rr.accepted) << rr.reason << ": " << rr.detail;
  EXPECT_EQ(executive_.job(r.job_id)->destination, "michael-desk");
  EXPECT_DOUBLE_EQ(*executive_.job(r.job_id)->deadline_s, 11.5 * 3600);

  revise.command_id = "s3";
  revise.to = "Miachel";
  revise.deadline.clear();
  const msg::CourierReply typo = desk_->handle(revise, kNine, 3);
  EXPECT_FALSE(typo.accepted);
  EXPECT_EQ(typo.reason, "unknown_place");
  EXPECT_NE(std::find(typo.suggestions.begin(), typo.suggestions.end(), "Michael"), typo.suggestions.end());

  msg::CourierCommand cancel;
  cancel.command_id = "s4";
  cancel.kind = msg::CourierCommandKind::Cancel;
  cancel.job_id = r.job_id;
  EXPECT_TRUE(desk_->handle(cancel, kNine, 4).accepted);
  EXPECT_EQ(executive_.job(r.job_id)->state, JobState::cancelled);
  // Journalled with the reply: a restart keeps the cancel and the revision before it.
  const Journal::Contents journalled = journal_->load();
  ASSERT_EQ(journalled.jobs.size(), 1u);
  EXPECT_EQ(journalled.jobs[0].state, JobState::cancelled);
  EXPECT_EQ(journalled.jobs[0].destination, "michael-desk");
  EXPECT_EQ(journalled.jobs_created, 1);
  cancel.command_id = "s5";
  const msg::CourierReply twice = desk_->handle(cancel, kNine, 5);
  EXPECT_FALSE(twice.accepted);
  EXPECT_EQ(twice.reason, "job_not_changeable");
  cancel.command_id = "s6";
  cancel.job_id = "job-99";
  EXPECT_EQ(desk_->handle(cancel, kNine, 6).reason, "unknown_job");
}

TEST_F(CommandDeskTest, TextRevisionsReachTheExecutive) {
  ASSERT_TRUE(text("c1", "deliver the green book from the librarian to Anna").accepted);
  const msg::CourierReply r = text("c2", "cancel job job-1");
  EXPECT_TRUE(r.accepted) << r.reason << ": " << r.detail;
  EXPECT_EQ(r.action, "cancel");
  EXPECT_EQ(executive_.job("job-1")->state, JobState::cancelled);
}

}  // namespace
}  // namespace autonomy::courier
