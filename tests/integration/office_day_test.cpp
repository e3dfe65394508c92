// The day-in-office experiment end to end (tools/experiments/office_day): two short seeded days
// of two strategies through the real simulator, behavior and courier processes over DDS give a
// CSV row per day and strategy, the report, the pictures, and (strategy d) the knowledge of
// day 1 carried into day 2.
//
//   domain  test
//   ------  -----------------------------------------------
//   92-93   OfficeDayTest.TwoShortDaysOfTwoStrategiesWriteCsvReportAndPictures (its two lanes)
//   94      OfficeDayTest.QuietTicksSkipTheIdleHoursAndDeliverTheSameDay
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <sstream>

#include "tests/support/process_test.hpp"

namespace autonomy::test {
namespace {

class OfficeDayTest : public ProcessTest {
 protected:
  // Runs one short day of strategy (c) into `out`; returns its CSV row split into fields.
  std::vector<std::string> run_day(const std::string& out, bool every_tick) {
    std::vector<std::string> args = {"--days", "1", "--strategies", "c", "--hours", "1", "--jobs-per-hour", "6",
                                     "--parallel", "1", "--domain-base", "94", "--seed", "5", "--out", out};
    if (every_tick) args.push_back("--every-tick");
    auto& run = start(every_tick ? "office_day_every_tick" : "office_day_quiet", AUTONOMY_OFFICE_DAY_EXPERIMENT_BIN,
                      args, false);
    const auto ended = run.wait_for_exit(std::chrono::minutes(4));
    if (!ended || !ended->exited || ended->code != 0) {
      ADD_FAILURE() << "the day did not run to its end\n" << run.log_tail();
      return {};
    }
    std::stringstream csv(read_file(out + "/days.csv"));
    std::string header, row;
    std::getline(csv, header);
    std::getline(csv, row);
    std::vector<std::string> f;
    std::stringstream fields(row);
    for (std::string x; std::getline(fields, x, ',');) f.push_back(x);
    return f;
  }
};

// The courier parks between jobs most of the hour: the simulator steps those ticks without
// publishing them (idl/clock.idl), and the day comes out as it does with every tick published.
TEST_F(OfficeDayTest, QuietTicksSkipTheIdleHoursAndDeliverTheSameDay) {
  join(94);
  const std::vector<std::string> every = run_day(dir().file("every-tick"), true);
  const std::vector<std::string> quiet = run_day(dir().file("quiet"), false);
  ASSERT_EQ(every.size(), 19u);
  ASSERT_EQ(quiet.size(), 19u);
  EXPECT_EQ(quiet[3], every[3]);  // the same seeded commands
  EXPECT_GT(std::stoi(every[4]), 0);
  EXPECT_EQ(quiet[4], every[4]) << "completed jobs";
  EXPECT_NEAR(std::stod(quiet[9]), std::stod(every[9]), 0.1 * std::stod(every[9]) + 5.0) << "metres driven";

  // "stopped at tick 7200: ... participants dropped, N ticks quiet"
  const auto quiet_ticks = [&](const std::string& out) {
    const std::string log = read_file(out + "/logs/c-1-simulator.out");
    const auto at = log.find(" ticks quiet");
    if (at == std::string::npos) return -1L;
    const auto from = log.rfind(' ', at - 1) + 1;
    return std::stol(log.substr(from, at - from));
  };
  EXPECT_EQ(quiet_ticks(dir().file("every-tick")), 0);
  // An hour is 7,200 ticks of 0.5 s; six jobs keep the courier busy for well under half of it.
  EXPECT_GT(quiet_ticks(dir().file("quiet")), 7200 / 3);
}

TEST_F(OfficeDayTest, TwoShortDaysOfTwoStrategiesWriteCsvReportAndPictures) {
  join(92);
  const std::string out = dir().file("office-day");
  auto& run = start("office_day", AUTONOMY_OFFICE_DAY_EXPERIMENT_BIN,
                    {"--days", "2", "--strategies", "c,d", "--hours", "1", "--jobs-per-hour", "8", "--parallel", "2",
                     "--domain-base", "92", "--seed", "3", "--out", out},
                    false);
  const auto ended = run.wait_for_exit(std::chrono::minutes(5));
  ASSERT_TRUE(ended.has_value()) << "the experiment did not finish in 5 minutes";
  ASSERT_TRUE(ended->exited && ended->code == 0) << ended->describe() << "\n" << run.log_tail();
  const std::string progress = read_file(run.log_file());
  EXPECT_NE(progress.find("(c) day 2/2"), std::string::npos) << progress;
  EXPECT_NE(progress.find("(d) day 2/2"), std::string::npos) << progress;

  // One row per day and strategy; the same seeded day gives both strategies the same commands.
  std::stringstream csv(read_file(out + "/days.csv"));
  std::string line;
  ASSERT_TRUE(std::getline(csv, line));
  EXPECT_EQ(line.rfind("strategy,day,seed,jobs,completed,on_time,", 0), 0u) << line;
  std::map<std::string, int> jobs;  // "c1" -> jobs
  int rows = 0;
  while (std::getline(csv, line)) {
    std::vector<std::string> f;
    std::stringstream fields(line);
    for (std::string x; std::getline(fields, x, ',');) f.push_back(x);
    ASSERT_EQ(f.size(), 19u) << line;
    ++rows;
    const int n = std::stoi(f[3]), completed = std::stoi(f[4]), on_time = std::stoi(f[5]);
    const int possible = std::stoi(f[17]);  // the day's ceiling (on_time_bound.hpp)
    jobs[f[0] + f[1]] = n;
    EXPECT_GT(n, 0) << line;
    EXPECT_GT(completed, 0) << line;  // a courier that works
    EXPECT_LE(on_time, completed) << line;
    EXPECT_LE(on_time, possible) << line;  // no strategy beats the ideal fleet
    EXPECT_LE(possible, n) << line;
    EXPECT_GT(std::stod(f[9]), 10.0) << line;  // it drove
  }
  EXPECT_EQ(rows, 4);
  EXPECT_EQ(jobs["c1"], jobs["d1"]);
  EXPECT_EQ(jobs["c2"], jobs["d2"]);

  const std::string report = read_file(out + "/report.md");
  EXPECT_NE(report.find("| c | exact/large engines"), std::string::npos) << report;
  EXPECT_NE(report.find("| d | (c) + learning"), std::string::npos) << report;
  EXPECT_NE(report.find("## Findings"), std::string::npos);
  for (const char* picture : {"on-time.svg", "on-time-by-day.svg", "day1-c-trajectory.svg", "day1-d-gantt.svg"})
    EXPECT_EQ(read_file(out + "/" + picture).find("<svg"), 0u) << picture;
  // Day 2 of (d) starts with what day 1 taught; (c) does not learn.
  const std::string d2 = read_file(out + "/logs/d-2-courier.out");
  EXPECT_NE(d2.find("known from earlier runs"), std::string::npos) << d2;
  EXPECT_EQ(d2.find("learning: 0 people, 0 doors"), std::string::npos) << d2;
  EXPECT_EQ(read_file(out + "/logs/c-2-courier.out").find("known from earlier runs"), std::string::npos);
}

}  // namespace
}  // namespace autonomy::test
