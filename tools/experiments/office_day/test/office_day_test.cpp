// The day-in-office experiment's pure parts: seeded days (the same for every strategy), what a
// day came to, and the report's findings from synthetic days.
#include <google/protobuf/text_format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include "tools/experiments/office_day/day_plan.hpp"
#include "tools/experiments/office_day/day_record.hpp"
#include "tools/experiments/office_day/day_report.hpp"
#include "tools/experiments/office_day/on_time_bound.hpp"

namespace autonomy::office_day {
namespace {

config::Scenario shipped_office() {
  std::ifstream in(std::string(AUTONOMY_SOURCE_DIR) + "/deploy/scenarios/office.pbtxt");
  std::stringstream text;
  text << in.rdbuf();
  config::Scenario s;
  EXPECT_TRUE(google::protobuf::TextFormat::ParseFromString(text.str(), &s));
  return s;
}

DaySettings settings(int couriers = 1) {
  DaySettings d;
  d.habits = default_habits();
  d.couriers = couriers;
  return d;
}

TEST(OfficeDay, ADayIsSeededAndTheSameForOneOrThreeCouriers) {
  const config::Scenario office = shipped_office();
  const DayPlan one = plan_day(office, settings(1), 1001);
  const DayPlan three = plan_day(office, settings(3), 1001);
  const DayPlan other = plan_day(office, settings(1), 1002);
  ASSERT_GE(one.commands.size(), 15u);  // about 4 an hour over 7.5 h
  ASSERT_EQ(one.commands.size(), three.commands.size());
  for (std::size_t i = 0; i < one.commands.size(); ++i) {
    EXPECT_EQ(one.commands[i].object_id, three.commands[i].object_id);
    EXPECT_EQ(one.commands[i].to, three.commands[i].to);
    EXPECT_DOUBLE_EQ(one.commands[i].at_s, three.commands[i].at_s);
  }
  EXPECT_EQ(one.habits_today, three.habits_today);
  EXPECT_NE(one.commands.front().at_s, other.commands.front().at_s);
  EXPECT_EQ(one.scenario.robots_size(), 1);
  ASSERT_EQ(three.scenario.robots_size(), 3);
  EXPECT_EQ(three.scenario.robots(2).id(), "rhino3");
  // A lone courier starts where the office puts it; a fleet on the office's parking spots.
  EXPECT_DOUBLE_EQ(one.scenario.robots(0).start().x(), office.robots(0).start().x());
  ASSERT_GE(office.parking_size(), 3);
  for (int k = 0; k < 3; ++k) {
    EXPECT_DOUBLE_EQ(three.scenario.robots(k).start().x(), office.parking(k).position().x()) << k;
    EXPECT_DOUBLE_EQ(three.scenario.robots(k).start().y(), office.parking(k).position().y()) << k;
  }
  EXPECT_EQ(three.scenario.simulation().step_s(), 0.5);
}

TEST(OfficeDay, EveryCommandHasItsObjectAtItsPickupAndADeadlineAfterIt) {
  const config::Scenario office = shipped_office();
  const DayPlan day = plan_day(office, settings(), 7);
  ASSERT_EQ(static_cast<std::size_t>(day.scenario.objects_size()), day.commands.size());
  std::set<std::string> desks;
  for (const auto& p : office.people()) desks.insert(p.desk());
  double last = 0;
  for (std::size_t i = 0; i < day.commands.size(); ++i) {
    const DayCommand& c = day.commands[i];
    EXPECT_EQ(day.scenario.objects(static_cast<int>(i)).id(), c.object_id);
    EXPECT_EQ(day.scenario.objects(static_cast<int>(i)).place(), c.from);
    EXPECT_NE(c.from, c.to);
    EXPECT_TRUE(desks.count(c.to)) << c.to;
    EXPECT_GE(c.deadline_s, c.at_s + 20 * 60 - 1e-6);
    EXPECT_LE(c.deadline_s, c.at_s + 91 * 60);
    EXPECT_LT(c.at_s, 8 * 3600 - 1800);
    EXPECT_GE(c.at_s, last);
    last = c.at_s;
  }
}

TEST(OfficeDay, DoorHabitsAreScriptedOnMostDaysAndTheFloorsStoryScriptIsGone) {
  const config::Scenario office = shipped_office();
  int closed_a120 = 0;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const DayPlan day = plan_day(office, settings(), seed);
    for (const auto& d : day.scenario.doors()) {
      if (d.id() == "A-120" && d.has_script()) {
        ++closed_a120;
        ASSERT_EQ(d.script().events_size(), 2);
        EXPECT_NEAR(d.script().events(0).time_s(), 3600, 600);
        EXPECT_NEAR(d.script().events(1).time_s(), 9000, 600);
        EXPECT_EQ(d.script().events(0).angle(), 0.0);
      }
      if (d.id() == "A-116") {
        EXPECT_TRUE(d.has_random());  // the floor's own random door stays
      }
    }
  }
  EXPECT_GE(closed_a120, 11);  // 80 % of 20 days, give or take
  EXPECT_LE(closed_a120, 19);
  DaySettings bad = settings();
  bad.habits.push_back({"A-999", 0, 100, 1, 0});
  EXPECT_THROW(plan_day(office, bad, 1), std::invalid_argument);
}

TEST(OfficeDay, ADayCountsOnTimeJobsAndLatenessUnfinishedOnesLateByTheEnd) {
  std::vector<DayCommand> commands(4);
  for (int i = 0; i < 4; ++i) {
    commands[static_cast<std::size_t>(i)].command_id = "c" + std::to_string(i);
    commands[static_cast<std::size_t>(i)].deadline_s = 1000;
  }
  std::map<std::string, JobOutcome> outcomes = {{"c0", {"completed", 900}},
                                                {"c1", {"completed", 1300}},
                                                {"c2", {"failed", 0}}};  // c3 never accepted
  const DayRecord r = summarize(commands, outcomes, 2000);
  EXPECT_EQ(r.jobs, 3);
  EXPECT_EQ(r.completed, 2);
  EXPECT_EQ(r.on_time, 1);
  EXPECT_NEAR(r.on_time_percent, 100.0 / 3, 1e-9);
  EXPECT_DOUBLE_EQ(r.mean_lateness_s, (0 + 300 + 1000) / 3.0);
  EXPECT_DOUBLE_EQ(r.max_lateness_s, 1000);
  EXPECT_EQ(csv_header().substr(0, 13), "strategy,day,");
}

// The shipped office's day with the given commands only (the day starts at 09:00; rhino drives
// at 0.9 m/s; Anna hands over in 10 s, the mail tray in 4 s, Sebastian is in from 11:00).
DayPlan day_with(std::vector<DayCommand> commands) {
  DayPlan plan = plan_day(shipped_office(), settings(1), 7);
  for (DayCommand& c : commands) c.deadline = clock_hhmm(9 * 3600 + c.deadline_s);
  plan.commands = std::move(commands);
  return plan;
}

DayCommand command(const std::string& id, const std::string& from, const std::string& to, double at_s, double due_s) {
  DayCommand c;
  c.command_id = id;
  c.object_id = "item-" + id;
  c.from = from;
  c.to = to;
  c.at_s = at_s;
  c.deadline_s = due_s;
  return c;
}

TEST(OnTimeBound, AnIdealCourierDrivesStraightAtTopSpeedAndHandsOverInTheShortestTime) {
  const std::vector<DayCommand> jobs = {command("tray-anna", "mail-tray", "a114-desk", 1800, 3000),
                                        command("anna-michael", "a114-desk", "michael-desk", 2400, 3600)};
  const auto bound = on_time_bound(day_with(jobs), {}, 8 * 3600);
  ASSERT_EQ(bound.size(), 2u);
  // mail tray (25, 4.5) -> Anna's desk (19, 2.6): 4 s at the tray, the drive, 10 s with Anna.
  EXPECT_TRUE(bound[0].possible);
  EXPECT_NEAR(bound[0].earliest_s, 1800 + 4 + std::hypot(6.0, 1.9) / 0.9 + 10, 1e-6);
  // Anna's desk (19, 2.6) -> Michael's (13, 2.6): Michael hands over in 5-15 s.
  EXPECT_TRUE(bound[1].possible);
  EXPECT_NEAR(bound[1].earliest_s, 2400 + 10 + 6.0 / 0.9 + 5, 1e-6);
  EXPECT_TRUE(bound[0].why.empty());
}

TEST(OnTimeBound, AClosedDoorDelaysTheJobUntilItOpensAndAJobIsLostOnlyWhenThatIsPastItsDeadline) {
  const DayCommand to_anna = command("to-anna", "mail-tray", "a114-desk", 1800, 3000);
  const DayCommand from_michael = command("from-michael", "michael-desk", "a118-desk", 4000, 9000);
  // A-114 closed before the robot can get there, open again in time: done as it opens.
  auto b = on_time_bound(day_with({to_anna}), {{"A-114", 1700, 2500}}, 8 * 3600);
  EXPECT_TRUE(b[0].possible);
  EXPECT_NEAR(b[0].earliest_s, 2500 + 10, 1e-6);
  // Open again after the deadline: lost, and the reason names the door and the times.
  b = on_time_bound(day_with({to_anna}), {{"A-114", 1700, 4000}}, 8 * 3600);
  EXPECT_FALSE(b[0].possible);
  EXPECT_NEAR(b[0].earliest_s, 4010, 1e-6);
  EXPECT_NE(b[0].why.find("delivery at a114-desk: A-114 closed 09:28-10:06"), std::string::npos) << b[0].why;
  EXPECT_NE(b[0].why.find("due 09:50"), std::string::npos) << b[0].why;
  // The pickup's door closed for the rest of the day: never, whatever the deadline.
  b = on_time_bound(day_with({from_michael}), {{"A-120", 3000}}, 8 * 3600);
  EXPECT_FALSE(b[0].possible);
  EXPECT_FALSE(std::isfinite(b[0].earliest_s));
  EXPECT_NE(b[0].why.find("pickup at michael-desk: A-120 closed 09:50-end of day"), std::string::npos) << b[0].why;
  // Another door's closing changes nothing.
  b = on_time_bound(day_with({to_anna}), {{"A-120", 0, 20000}, {"A-118", 1000, 5000}}, 8 * 3600);
  EXPECT_TRUE(b[0].possible);
}

TEST(OnTimeBound, APersonAwayUntilAfterTheDeadlineMakesTheJobImpossible) {
  // Sebastian comes in at 11:00 (7,200 s after 09:00); Wolfram is out 12:00-14:00.
  const auto b = on_time_bound(day_with({command("early", "mail-tray", "a121-desk", 600, 5400),
                                         command("late-enough", "mail-tray", "a121-desk", 600, 7300),
                                         command("lunch", "a114-desk", "a118-desk", 10900, 14000)}),
                               {}, 8 * 3600);
  EXPECT_FALSE(b[0].possible);
  EXPECT_NE(b[0].why.find("Sebastian away"), std::string::npos) << b[0].why;
  EXPECT_TRUE(b[1].possible);
  EXPECT_NEAR(b[1].earliest_s, 7200 + 15, 1e-6);
  EXPECT_FALSE(b[2].possible);
  EXPECT_NEAR(b[2].earliest_s, 5 * 3600 + 5, 1e-6);  // Wolfram back at 14:00, 5 s at the least
}

TEST(OnTimeBound, DoorSamplesFoldIntoClosuresTheLastOneOpenAtTheEnd) {
  DoorHistory h;
  h.observe("A-116", 0, false);
  h.observe("A-116", 100, true);
  h.observe("A-116", 150, true);  // the leaf still moving: the same closure
  h.observe("A-113", 120, true);
  h.observe("A-116", 300, false);
  h.observe("A-116", 400, true);
  const auto c = h.closures();
  ASSERT_EQ(c.size(), 3u);
  EXPECT_EQ(c[0].door, "A-116");
  EXPECT_DOUBLE_EQ(c[0].from_s, 100);
  EXPECT_DOUBLE_EQ(c[0].to_s, 300);
  std::set<std::pair<std::string, double>> open_ended;
  for (std::size_t i = 1; i < c.size(); ++i) {
    EXPECT_FALSE(std::isfinite(c[i].to_s));
    open_ended.insert({c[i].door, c[i].from_s});
  }
  EXPECT_EQ(open_ended, (std::set<std::pair<std::string, double>>{{"A-113", 120}, {"A-116", 400}}));
}

TEST(OfficeDay, TheReportTestsTheFindingsBetweenStrategies) {
  std::vector<DayRecord> records;
  for (int day = 1; day <= 6; ++day) {
    for (const char* s : {"a", "b", "c", "d"}) {
      DayRecord r;
      r.strategy = s;
      r.day = day;
      r.jobs = 10;
      const double base = std::string(s) == "a" ? 40 : std::string(s) == "b" ? 70 : 80;
      r.on_time_percent = base + (std::string(s) == "d" ? 2.0 * day : 0) + (day % 2);
      r.mean_lateness_s = (100 - r.on_time_percent) * 6;
      records.push_back(r);
    }
  }
  const auto f = findings(records);
  ASSERT_EQ(f.size(), 5u);
  EXPECT_TRUE(f[0].evaluated && f[0].holds) << f[0].here;   // b > a
  EXPECT_TRUE(f[1].evaluated && f[1].holds) << f[1].here;   // c < b on lateness
  EXPECT_TRUE(f[3].evaluated && f[3].holds) << f[3].here;   // d later days > earlier
  EXPECT_FALSE(f[4].evaluated);                             // no e days
  const std::string md = write_report(records, "test", {"note"});
  EXPECT_NE(md.find("| a | paper heuristic, waits at closed doors | 6 |"), std::string::npos) << md;
  EXPECT_NE(md.find("not tested"), std::string::npos);
  EXPECT_EQ(on_time_svg(records).rfind("<svg", 0), 0u);
  EXPECT_NE(on_time_by_day_svg(records).find("polyline"), std::string::npos);
}

}  // namespace
}  // namespace autonomy::office_day
