// The behavior journal against real SQLite files in a temporary folder: what a behavior killed
// (-9) and started again must find, and the journals it must refuse.
#include "services/behavior/journal/behavior_journal.hpp"

#include <sqlite3.h>

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

namespace autonomy::behavior {
namespace {

class BehaviorJournalTest : public ::testing::Test {
 protected:
  BehaviorJournalTest() {
    std::string pattern = (std::filesystem::temp_directory_path() / "behavior_journal_XXXXXX").string();
    if (!::mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed");
    dir_ = pattern;
    path_ = dir_ + "/behavior-r1.db";
  }
  ~BehaviorJournalTest() override { std::filesystem::remove_all(dir_); }

  // Runs SQL on the file as another program would (a damaged or foreign journal).
  void tamper(const std::string& path, const char* sql) {
    sqlite3* db = nullptr;
    ASSERT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
    char* error = nullptr;
    const int rc = sqlite3_exec(db, sql, nullptr, nullptr, &error);
    const std::string why = error ? error : "";
    sqlite3_free(error);
    sqlite3_close(db);
    ASSERT_EQ(rc, SQLITE_OK) << why;
  }

  // The message of the error opening `path` as r1's goal-mode journal throws ("" if none).
  std::string opening_error(const std::string& path, const std::string& robot = "r1", const std::string& mission = "") {
    try {
      BehaviorJournal j(path, robot, mission);
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    return "";
  }

  std::string dir_;
  std::string path_;
};

TEST_F(BehaviorJournalTest, GoalsAndTheirStatesAreFoundAfterReopening) {
  {
    BehaviorJournal j(path_, "r1", "");
    EXPECT_EQ(j.run(), 1);
    EXPECT_TRUE(j.goals().empty());
    EXPECT_FALSE(j.mission());
    const long long a = j.goal_arrived({"r1", "to-a", 18.0, 2.5, 0.3, "comm_attenuation"});
    j.goal_state("to-a", GoalState::Accepted, "");
    j.goal_state("to-a", GoalState::Active, "");
    EXPECT_GT(a, 0);
  }
  BehaviorJournal again(path_, "r1", "");
  EXPECT_EQ(again.run(), 2);
  const auto goals = again.goals();
  ASSERT_EQ(goals.size(), 1u);
  EXPECT_EQ(goals[0].goal.goal_id, "to-a");
  EXPECT_EQ(goals[0].goal.x, 18.0);
  EXPECT_EQ(goals[0].goal.y, 2.5);
  EXPECT_EQ(goals[0].goal.tolerance, 0.3);
  EXPECT_EQ(goals[0].goal.constraint_set, "comm_attenuation");
  EXPECT_EQ(goals[0].state, GoalState::Active);
  EXPECT_TRUE(goals[0].open());
}

TEST_F(BehaviorJournalTest, AGoalWithNoStatusYetIsOpenAndEndedGoalsBeforeTheLastToEndAreDropped) {
  BehaviorJournal j(path_, "r1", "");
  j.goal_arrived({"r1", "g1", 1.0, 1.0, 0.0, ""});
  j.goal_state("g1", GoalState::Accepted, "");
  j.goal_state("g1", GoalState::Reached, "");
  j.goal_arrived({"r1", "g2", 2.0, 2.0, 0.0, ""});
  j.goal_state("g1", GoalState::Preempted, "late news for an older goal");  // the latest row with that id
  j.goal_state("g2", GoalState::Accepted, "");
  j.goal_state("g2", GoalState::Cancelled, "test cancels");
  j.goal_arrived({"r1", "g3", 3.0, 3.0, 0.0, ""});  // drops g1: g2 ended after it
  j.goal_state("nobody", GoalState::Reached, "");     // no goal has that id: nothing changes
  const auto goals = j.goals();
  ASSERT_EQ(goals.size(), 2u);
  EXPECT_EQ(goals[0].goal.goal_id, "g2");
  EXPECT_EQ(goals[0].state, GoalState::Cancelled);
  EXPECT_EQ(goals[0].reason, "test cancels");
  EXPECT_FALSE(goals[0].open());
  EXPECT_EQ(goals[1].goal.goal_id, "g3");
  EXPECT_FALSE(goals[1].state);
  EXPECT_TRUE(goals[1].open());
  EXPECT_LT(goals[0].seq, goals[1].seq);
}

TEST_F(BehaviorJournalTest, TheSameGoalIdSentAgainIsANewGoal) {
  BehaviorJournal j(path_, "r1", "");
  j.goal_arrived({"r1", "dock", 1.0, 1.0, 0.0, ""});
  j.goal_state("dock", GoalState::Reached, "");
  j.goal_arrived({"r1", "dock", 4.0, 1.0, 0.0, ""});
  j.goal_state("dock", GoalState::Accepted, "");
  const auto goals = j.goals();
  ASSERT_EQ(goals.size(), 2u);
  EXPECT_EQ(goals[0].state, GoalState::Reached);
  EXPECT_EQ(goals[1].state, GoalState::Accepted);
  EXPECT_EQ(goals[1].goal.x, 4.0);
}

TEST_F(BehaviorJournalTest, MissionProgressAndItsEventsAreFoundAfterReopening) {
  {
    BehaviorJournal j(path_, "r2", "recon_r2");
    j.mission_progress({"to_gap", 0.1, "", false, 0}, {{0.1, "started", "to_gap", ""}});
    j.mission_progress({"to_goal", 12.5, "via_north", false, 0},
                       {{12.5, "transition", "to_goal", "at goal"}, {12.5, "plan_chosen", "to_goal", "via_north"}});
  }
  BehaviorJournal again(path_, "r2", "recon_r2");
  const auto m = again.mission();
  ASSERT_TRUE(m);
  EXPECT_EQ(m->state, "to_goal");
  EXPECT_EQ(m->entered_at_s, 12.5);
  EXPECT_EQ(m->plan, "via_north");
  EXPECT_FALSE(m->finished);
  EXPECT_EQ(m->events, 3);
  const auto events = again.mission_events();
  ASSERT_EQ(events.size(), 3u);
  EXPECT_EQ(events[0].event, "started");
  EXPECT_EQ(events[1].event, "transition");
  EXPECT_EQ(events[1].reason, "at goal");
  EXPECT_EQ(events[2].state, "to_goal");
  EXPECT_TRUE(again.goals().empty());
}

TEST_F(BehaviorJournalTest, AnotherRobotsOrAnotherModesJournalIsRefusedNamingThePath) {
  { BehaviorJournal j(path_, "r1", ""); }
  EXPECT_EQ(opening_error(path_, "r2"), "journal " + path_ +
                                             ": it is the journal of robot r1, not of r2; name another journal "
                                             "file or remove this one");
  EXPECT_EQ(opening_error(path_, "r1", "recon_r1"),
            "journal " + path_ +
                ": it is the journal of goal mode, not of mission recon_r1; name another journal file or remove this one");
  const std::string mission_path = dir_ + "/mission.db";
  { BehaviorJournal j(mission_path, "r1", "recon_r1"); }
  EXPECT_EQ(opening_error(mission_path, "r1", "recon_r2"),
            "journal " + mission_path +
                ": it is the journal of mission recon_r1, not of mission recon_r2; name another journal file or "
                "remove this one");
  EXPECT_EQ(BehaviorJournal(path_, "r1", "").run(), 2);  // its own opens; the refusals wrote nothing
}

TEST_F(BehaviorJournalTest, AnotherServicesDatabaseIsRefused) {
  const std::string other = dir_ + "/executive.db";
  tamper(other, "CREATE TABLE meta (key TEXT PRIMARY KEY, value INTEGER); CREATE TABLE flight (key TEXT, value TEXT)");
  EXPECT_EQ(opening_error(other), "journal " + other +
                                      ": not a behavior journal (its tables: flight, meta); name another file, "
                                      "e.g. {run}/behavior-<robot>.db");
}

TEST_F(BehaviorJournalTest, AFileThatIsNoDatabaseIsRefused) {
  const std::string garbage = dir_ + "/garbage.db";
  std::ofstream(garbage) << std::string(4096, 'x');
  const std::string error = opening_error(garbage);
  EXPECT_EQ(error.rfind("journal " + garbage + ": ", 0), 0u) << error;
  EXPECT_NE(error.find("not a database"), std::string::npos) << error;
}

TEST_F(BehaviorJournalTest, DamagedValuesAreRefusedNamingTheGoal) {
  {
    BehaviorJournal j(path_, "r1", "");
    j.goal_arrived({"r1", "g1", 1.0, 1.0, 0.0, ""});
  }
  tamper(path_, "UPDATE goals SET state = 'flying'");
  EXPECT_EQ(opening_error(path_), "journal " + path_ + ": a damaged value: goal g1 has state 'flying'");
  tamper(path_, "UPDATE goals SET state = NULL, x = 'east'");
  EXPECT_EQ(opening_error(path_), "journal " + path_ + ": a damaged value: goal g1 x is not a number");

  const std::string mission_path = dir_ + "/mission.db";
  {
    BehaviorJournal j(mission_path, "r1", "m");
    j.mission_progress({"go", 1.0, "", false, 0}, {});
  }
  tamper(mission_path, "UPDATE mission SET entered_at_s = 'soon'");
  EXPECT_EQ(opening_error(mission_path, "r1", "m"),
            "journal " + mission_path + ": a damaged value: the mission state's entry time is not a number");
}

}  // namespace
}  // namespace autonomy::behavior
