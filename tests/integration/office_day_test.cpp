// The day-in-office experiment end to end (tools/experiments/office_day): two short seeded days
// of two strategies through the real simulator, behavior and courier processes over DDS give a
// CSV row per day and strategy, the report, the pictures, and (strategy d) the knowledge of
// day 1 carried into day 2.
//
//   domain  test
//   ------  -----------------------------------------------
//   92-93   OfficeDayTest.TwoShortDaysOfTwoStrategiesWriteCsvReportAndPictures (its two lanes)
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <sstream>

#include "tests/support/process_test.hpp"

namespace autonomy::test {
namespace {

class OfficeDayTest : public ProcessTest {};

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
    ASSERT_EQ(f.size(), 17u) << line;
    ++rows;
    const int n = std::stoi(f[3]), completed = std::stoi(f[4]), on_time = std::stoi(f[5]);
    jobs[f[0] + f[1]] = n;
    EXPECT_GT(n, 0) << line;
    EXPECT_GT(completed, 0) << line;  // a courier that works
    EXPECT_LE(on_time, completed) << line;
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
