// The day-in-office experiment's pure parts: seeded days (the same for every strategy), what a
// day came to, and the report's findings from synthetic days.
#include <google/protobuf/text_format.h>
#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>

#include "tools/experiments/office_day/day_plan.hpp"
#include "tools/experiments/office_day/day_record.hpp"
#include "tools/experiments/office_day/day_report.hpp"

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
      if (d.id() == "A-116") EXPECT_TRUE(d.has_random());  // the floor's own random door stays
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
