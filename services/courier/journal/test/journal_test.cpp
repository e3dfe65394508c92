#include "services/courier/journal/journal.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <unistd.h>

namespace autonomy::courier {
namespace {

std::string fresh_path(const std::string& name) {
  const std::string path = "/tmp/courier_journal_test_" + std::to_string(getpid()) + "_" + name + ".db";
  for (const char* suffix : {"", "-wal", "-shm"}) std::remove((path + suffix).c_str());
  return path;
}

Job red_letter() {
  Job j;
  j.id = "job-1";
  j.command_id = "c1";
  j.object = {"letter-red", "letter", "red"};
  j.pickup = "meeting-table";
  j.destination = "michael-desk";
  j.deadline_s = 37800.0;
  j.accepted_at_s = 30600.0;
  j.object_place = "meeting-table";
  return j;
}

TEST(Journal, CommandsJobsAndHandoversSurviveReopening) {
  const std::string path = fresh_path("reopen");
  {
    Journal journal(path);
    Job j = red_letter();
    journal.record_command("c1", R"({"accepted":true})", &j);
    journal.record_command("c2", R"({"accepted":false})", nullptr);
    j.state = JobState::underway;
    j.phase = JobPhase::to_destination;
    j.object_place.clear();
    j.object_carrier = "rhino";
    journal.record_handover({"rhino", "rhino/job-1/load/1", true, "meeting-table", "letter-red", "job-1"});
    journal.save_progress({&j}, {{"rhino/job-1/load/1", "completed"}});
    journal.record_handover({"rhino", "rhino/job-1/unload/2", false, "michael-desk", "letter-red", "job-1"});
    EXPECT_EQ(journal.run(), 1);
  }
  Journal journal(path);
  EXPECT_EQ(journal.run(), 2);
  EXPECT_EQ(*journal.reply_for("c1"), R"({"accepted":true})");
  EXPECT_EQ(*journal.reply_for("c2"), R"({"accepted":false})");
  EXPECT_FALSE(journal.reply_for("c3"));
  const Journal::Contents c = journal.load();
  EXPECT_EQ(c.jobs_created, 1);
  ASSERT_EQ(c.jobs.size(), 1u);
  const Job& j = c.jobs[0];
  EXPECT_EQ(j.id, "job-1");
  EXPECT_EQ(j.object.colour, "red");
  EXPECT_EQ(j.state, JobState::underway);
  EXPECT_EQ(j.phase, JobPhase::to_destination);
  EXPECT_EQ(j.object_carrier, "rhino");
  EXPECT_TRUE(j.object_place.empty());
  EXPECT_DOUBLE_EQ(*j.deadline_s, 37800.0);
  EXPECT_FALSE(j.estimated_completion_s);
  // The load was answered for good (with its consequence); the unload never was: asked again.
  ASSERT_EQ(c.unanswered.size(), 1u);
  EXPECT_EQ(c.unanswered[0].request_id, "rhino/job-1/unload/2");
  EXPECT_FALSE(c.unanswered[0].load);
  EXPECT_EQ(c.unanswered[0].robot, "rhino");
}

TEST(Journal, UnusableFilesAreReportedWithThePath) {
  EXPECT_THROW(Journal("/nonexistent-folder/x.db"), std::runtime_error);
  const std::string path = fresh_path("garbage");
  std::ofstream(path) << "this is not a database, just text that is long enough to have a header...........";
  try {
    Journal j(path);
    FAIL() << "opened a text file as a journal";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
}

TEST(Journal, AStrandedJobIsKeptWithItsReason) {
  const std::string path = fresh_path("stranded");
  {
    Journal journal(path);
    Job j = red_letter();
    journal.record_command("c1", R"({"accepted":true})", &j);
    j.state = JobState::stranded;
    j.object_place.clear();
    j.object_carrier = "rhino2";
    j.robot = "rhino2";
    j.reason = "letter-red stranded aboard rhino2, last seen at (19.2, 3.1) near a114-desk in A-114 at 09:01:17";
    journal.save_progress({&j}, {});
  }
  const Journal::Contents c = Journal(path).load();
  ASSERT_EQ(c.jobs.size(), 1u);
  EXPECT_EQ(c.jobs[0].state, JobState::stranded);
  EXPECT_FALSE(c.jobs[0].finished());  // a restarted courier waits for rhino2 with it
  EXPECT_EQ(c.jobs[0].object_carrier, "rhino2");
  EXPECT_NE(c.jobs[0].reason.find("last seen at (19.2, 3.1)"), std::string::npos);
}

}  // namespace
}  // namespace autonomy::courier

namespace autonomy::courier {
namespace {

TEST(Journal, WhatWasLearnedSurvivesReopeningAndIsReadableWithoutCountingARun) {
  const std::string path = fresh_path("learned");
  {
    Journal journal(path);
    Experience e;
    e.handover("Michael", 20);
    e.handover("Michael", 40);
    e.presence("Michael", 36000, false, 1);
    e.door("A-120", 36000, false, 1);
    e.door("A-120", 37800, true, 1);
    e.travel("mailroom", "a120-desk", 55);
    journal.save_experience(e);
    e.door("A-120", 36000, false, 2);
    journal.save_experience(e);  // replaces, does not add up
  }
  const Experience read = Journal::read_experience(path);
  EXPECT_EQ(read.handovers().at("Michael").n, 2);
  EXPECT_DOUBLE_EQ(read.handovers().at("Michael").mean, 30);
  EXPECT_DOUBLE_EQ(read.handovers().at("Michael").stddev(), std::sqrt(200.0));
  EXPECT_EQ(read.presence().at("Michael").no[HalfHourCounts::slot_of(36000)], 1);
  EXPECT_EQ(read.doors().at("A-120").no[HalfHourCounts::slot_of(36000)], 2);
  EXPECT_EQ(read.doors().at("A-120").yes[HalfHourCounts::slot_of(37800)], 1);
  EXPECT_EQ(read.travel().at({"mailroom", "a120-desk"}).n, 1);
  Journal again(path);
  EXPECT_EQ(again.run(), 2);  // reading did not count a run
  EXPECT_EQ(again.load_experience().doors().at("A-120").no[HalfHourCounts::slot_of(36000)], 2);
  std::remove(path.c_str());
}

TEST(Journal, ReadingKnowledgeFromSomethingElseSaysWhy) {
  EXPECT_THROW(
      {
        try {
          Journal::read_experience("/nonexistent/courier.db");
        } catch (const std::runtime_error& e) {
          EXPECT_NE(std::string(e.what()).find("/nonexistent/courier.db"), std::string::npos);
          throw;
        }
      },
      std::runtime_error);
}

}  // namespace
}  // namespace autonomy::courier
