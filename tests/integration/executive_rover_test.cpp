// The executive's robot domain over DDS: the planner, the executive
// (services/executive/examples/field-rover.pbtxt), the rover's behavior controller and the
// simulator (deploy/scenarios/field.pbtxt) as separate processes in lockstep. The plan's drives
// become go-to goals of the behavior controller, whose goal status ends them; samples are
// monitored dwells; reports go to the lander through the simulated radio.
//
//   domain  test
//   ------  -----------------------------------------------------------
//    218    ExecutiveRoverTest.TheSurveyDrivesToEverySiteSamplesReportsAndComesHome
//    219    ExecutiveRoverTest.ReportsTheRadioDoesNotDeliverStopTheRadioAndTheSurveyGoesOn
// (ctest names them integration.<suite>.<test>.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "tests/support/executive_watch.hpp"
#include "tests/support/process_test.hpp"

namespace autonomy::test {
namespace {

const std::string kRoverScenario = std::string(AUTONOMY_SOURCE_DIR) + "/deploy/scenarios/field.pbtxt";
const std::string kRoverConfig = std::string(AUTONOMY_SOURCE_DIR) + "/services/executive/examples/field-rover.pbtxt";

struct Site {
  const char* name;
  double x, y;
};
// As in field-rover.pbtxt.
const std::vector<Site> kSites = {{"lander", 7, 5}, {"rock1", 16, 9}, {"rock2", 31, 6}, {"crater", 29, 23}};

class ExecutiveRoverTest : public ProcessTest {
 protected:
  void survey(int domain, const std::string& scenario_text) {
    join(domain);
    watch_.emplace(participant());
    goals_.emplace(participant(), dds::topics::nav_goal);
    inbox_.emplace(participant(), dds::topics::team_inbox);
    states_.emplace(participant(), dds::topics::robot_state);
    const std::string scenario = dir().file("field.pbtxt");
    write_file(scenario, scenario_text);
    start("planner", AUTONOMY_PLANNER_BIN, {"--domain", std::to_string(domain), "--log-dir", dir().path()});
    start("executive", AUTONOMY_EXECUTIVE_BIN,
          {"--config", kRoverConfig, "--domain", std::to_string(domain), "--log-dir", dir().path(),
           "--log-level", "debug", "--report-dir", dir().file("report")});
    start_behavior("rover");
    start_simulator({"--config", scenario, "--wait-for", "executive/main", "--wait-for", "behavior/rover"});
  }
  ::testing::AssertionResult finished() {
    return await("the executive finished the survey", [&] {
      poll();
      return watch_->finished();
    }, std::chrono::seconds(150));
  }
  void poll() {
    watch_->poll();
    goals_->poll();
    inbox_->poll();
    for (const auto& s : states_->poll())
      if (s.robot_id == "rover") last_pose_ = s;
  }
  msg::ExecutiveStatus final_status() const { return watch_->final_status(); }
  std::vector<std::string> achieved() const { return watch_->achieved(); }
  std::vector<std::string> lost() const { return watch_->lost(); }
  std::vector<msg::ExecutiveEvent> events(const std::string& kind) const { return watch_->events(kind); }
  std::string story() const { return watch_->story(); }
  // The site a go-to goal was sent to ("" if none is there).
  static std::string site_of(const msg::NavGoal& g) {
    for (const Site& s : kSites)
      if (std::hypot(g.x - s.x, g.y - s.y) < 1e-6) return s.name;
    return "";
  }
  std::vector<std::string> reports_delivered() const {
    std::vector<std::string> out;
    for (const auto& d : inbox_->matching([](const auto& d) { return d.recipient == "lander" && d.from == "rover"; }))
      out.push_back(d.payload);
    return sorted(out);
  }

  std::optional<ExecutiveWatch> watch_;
  std::optional<Recorder<msg::NavGoal>> goals_;
  std::optional<Recorder<msg::TeamDelivery>> inbox_;
  std::optional<Recorder<msg::RobotState>> states_;
  std::optional<msg::RobotState> last_pose_;
};

TEST_F(ExecutiveRoverTest, TheSurveyDrivesToEverySiteSamplesReportsAndComesHome) {
  survey(218, read_file(kRoverScenario));
  ASSERT_TRUE(finished()) << story();
  EXPECT_EQ(achieved(), sorted({"s1", "s2", "s3", "r1", "r2", "r3", "home"})) << story();
  EXPECT_TRUE(lost().empty()) << story();
  EXPECT_TRUE(events("aborted").empty()) << story();
  EXPECT_TRUE(events("violation").empty()) << story();
  // Every drive of the plan was one go-to goal of the behavior controller, to a site's
  // coordinates, each site once and the lander last; each drive ended when the rover got there.
  std::vector<std::string> visited;
  for (const auto& g : goals_->all()) {
    EXPECT_EQ(g.robot_id, "rover");
    EXPECT_DOUBLE_EQ(g.tolerance, 0.5);
    visited.push_back(site_of(g));
  }
  ASSERT_EQ(visited.size(), 4u) << story();
  EXPECT_EQ(visited.back(), "lander");
  EXPECT_EQ(sorted({visited[0], visited[1], visited[2]}), sorted({"rock1", "rock2", "crater"}));
  const auto drives = watch_->events_where([](const auto& e) {
    return e.kind == "ended" && e.text.find("rover.location == driving") != std::string::npos;
  });
  EXPECT_EQ(drives.size(), 4u) << story();
  // The rover is home, stopped.
  ASSERT_TRUE(last_pose_);
  EXPECT_LT(std::hypot(last_pose_->x - 7.0, last_pose_->y - 5.0), 0.5 + 0.05);
  // The three reports reached the lander through the radio.
  EXPECT_EQ(reports_delivered(), sorted({"sample rock1", "sample rock2", "sample crater"}));
  const std::string md = read_file(dir().file("report/report.md"));
  EXPECT_NE(md.find("7 goals achieved, 0 lost"), std::string::npos) << md;
}

TEST_F(ExecutiveRoverTest, ReportsTheRadioDoesNotDeliverStopTheRadioAndTheSurveyGoesOn) {
  // The radio model's default power: behind the boulder field the lander no longer hears the rover.
  std::string text = read_file(kRoverScenario);
  const std::string strong = "radio { tx_power_dbm: 30 }";
  ASSERT_NE(text.find(strong), std::string::npos);
  text.erase(text.find(strong), strong.size());
  survey(219, text);
  ASSERT_TRUE(finished()) << story();
  // The report from the crater is not delivered: the radio is no longer commanded (the
  // Remote Agent's answer to an unconfirmed command), without an abort; its goal is lost with
  // the reason, everything that does not need the radio is done.
  const auto stopped = events("fault stop_commanding");
  ASSERT_EQ(stopped.size(), 1u) << story();
  EXPECT_NE(stopped[0].text.find("rover_radio"), std::string::npos);
  EXPECT_TRUE(events("aborted").empty()) << story();
  EXPECT_EQ(lost(), std::vector<std::string>{"r3"}) << story();
  ASSERT_EQ(final_status().goals_lost.size(), 1u) << story();
  EXPECT_NE(final_status().goals_lost[0].find("rover_radio no longer commanded"), std::string::npos);
  EXPECT_EQ(achieved(), sorted({"s1", "s2", "s3", "r1", "r2", "home"})) << story();
  EXPECT_EQ(reports_delivered(), sorted({"sample rock1", "sample rock2"}));
  // The crater's report was sent after its sample, from there, and the rover drove home after.
  ASSERT_EQ(goals_->all().size(), 4u);
  EXPECT_EQ(site_of(goals_->all().back()), "lander");
  ASSERT_TRUE(last_pose_);
  EXPECT_LT(std::hypot(last_pose_->x - 7.0, last_pose_->y - 5.0), 0.55);
}

}  // namespace
}  // namespace autonomy::test
