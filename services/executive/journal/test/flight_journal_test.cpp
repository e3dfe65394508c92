// The flight journal against real SQLite files: what a killed executive must find again.
#include "flight_journal.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <unistd.h>

namespace autonomy::executive {
namespace {

class FlightJournalTest : public ::testing::Test {
 protected:
  FlightJournalTest() : path_("/tmp/flight_journal_test_" + std::to_string(getpid()) + ".db") { remove_files(); }
  ~FlightJournalTest() override { remove_files(); }
  void remove_files() {
    for (const char* suffix : {"", "-wal", "-shm"}) std::remove((path_ + suffix).c_str());
  }
  std::string path_;
};

TEST_F(FlightJournalTest, ANewJournalIsFreshAndEverythingWrittenIsFoundAfterReopening) {
  {
    FlightJournal j(path_, "ds1-day.problem");
    EXPECT_TRUE(j.record().fresh());
    EXPECT_EQ(j.record().run, 1);
    j.goal("nav1_1", true, "picture(braille) taken", 600);
    j.goal("thrust1", false, "ips failed", 900);
    j.goal("thrust1", true, "late news", 950);  // an outcome is final
    j.device_disabled("ips", "ips failed", 900);
    j.sensor_ignored("camera_switch_voltage_a", 910);
    j.plan("plan-3", 14400,
           {{"dsone.attitude", "pointAt", {"earth"}}, {"dsone.engine", "thrusting", {"1"}},
            {"dsone.camera", "ready", {}}},
           {{"adcs", {"pointing", "dsone.attitude", msg::PlannerTimelineValue{"dsone.attitude", "pointAt", {"mars"}}}}},
           {"thrust1", "hidden1"}, 1000);
    j.alive(1030);  // within a minute of the last write: not written
  }
  FlightJournal again(path_, "ds1-day.problem");
  const FlightRecord& r = again.record();
  EXPECT_FALSE(r.fresh());
  EXPECT_EQ(r.run, 2);
  EXPECT_EQ(*r.alive_until, 1000);
  EXPECT_EQ(r.achieved.at("nav1_1"), "picture(braille) taken");
  EXPECT_EQ(r.lost.at("thrust1"), "ips failed");
  EXPECT_EQ(r.achieved.count("thrust1"), 0u);
  EXPECT_EQ(r.disabled.at("ips"), "ips failed");
  EXPECT_EQ(r.ignored_sensors.count("camera_switch_voltage_a"), 1u);
  EXPECT_EQ(r.plan_id, "plan-3");
  EXPECT_EQ(r.horizon_end, 14400);
  EXPECT_EQ(r.state_at, 1000);
  ASSERT_EQ(r.state.size(), 3u);  // by timeline
  EXPECT_EQ(r.state[0].timeline, "dsone.attitude");
  EXPECT_EQ(r.state[0].parameters, std::vector<std::string>{"earth"});
  EXPECT_EQ(r.state[1].predicate, "ready");
  EXPECT_TRUE(r.state[1].parameters.empty());
  EXPECT_EQ(r.state[2].parameters, std::vector<std::string>{"1"});
  ASSERT_EQ(r.settling.count("adcs"), 1u);
  EXPECT_EQ(r.settling.at("adcs").end_mode, "pointing");
  ASSERT_TRUE(r.settling.at("adcs").if_blocked);
  EXPECT_EQ(r.settling.at("adcs").if_blocked->parameters, std::vector<std::string>{"mars"});
  EXPECT_EQ(r.executing_goals, (std::set<std::string>{"hidden1", "thrust1"}));
}

TEST_F(FlightJournalTest, AliveIsWrittenOncePerMinuteOfMissionTime) {
  {
    FlightJournal j(path_, "m");
    j.alive(0);
    j.alive(59);
    j.alive(120);
    j.alive(150);
  }
  EXPECT_EQ(*FlightJournal(path_, "m").record().alive_until, 120);
}

TEST_F(FlightJournalTest, AJournalOfAnotherMissionIsRefusedNamingBoth) {
  { FlightJournal j(path_, "ds1-day.problem"); }
  try {
    FlightJournal other(path_, "rover.problem");
    FAIL() << "opened";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(path_), std::string::npos) << what;
    EXPECT_NE(what.find("journal of mission ds1-day.problem, not of rover.problem"), std::string::npos) << what;
  }
}

TEST_F(FlightJournalTest, AFileThatIsNoDatabaseIsRefusedNamingIt) {
  { std::FILE* f = std::fopen(path_.c_str(), "w"); std::fputs("not a database, certainly not", f); std::fclose(f); }
  try {
    FlightJournal j(path_, "m");
    FAIL() << "opened";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path_), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace autonomy::executive
