#include "tools/experiments/stats/report.hpp"

#include <gtest/gtest.h>

#include <set>

namespace autonomy::stats {
namespace {

TrialRecord record(const std::string& cfg, int trial, double time) {
  TrialRecord r;
  r.configuration = cfg;
  r.trial = trial;
  r.seed = 100 + trial;
  r.mission_time_s = time;
  r.distance_m = 10.0 * trial;
  r.time_connected_s = 5.0;
  r.percent_time_fully_connected = 50.0 + trial;
  r.coverage_percent = 12.5;
  return r;
}

TEST(ReportTest, ConfigurationsAndPairsAreConsistent) {
  const auto& configs = table1_configurations();
  ASSERT_EQ(configs.size(), 6u);
  std::set<std::string> ids;
  for (const auto& c : configs) ids.insert(c.id);
  EXPECT_EQ(ids.size(), 6u);
  EXPECT_EQ(table1_compared_pairs().size(), 7u);
  for (const auto& [a, b] : table1_compared_pairs()) {
    EXPECT_TRUE(ids.count(a)) << a;
    EXPECT_TRUE(ids.count(b)) << b;
    EXPECT_NE(a, b);
  }
}

TEST(ReportTest, Csv) {
  EXPECT_EQ(csv_header(),
            "configuration,trial,seed,mission_time_s,distance_m,time_connected_s,"
            "percent_time_fully_connected,coverage_percent,finished\n");
  EXPECT_EQ(csv_row(record("reactive", 2, 66.5)), "reactive,2,102,66.5,20,5,52,12.5,1\n");
  TrialRecord unfinished = record("comm_serial", 1, 2.0);
  unfinished.all_finished = false;
  const std::string csv = write_csv({record("reactive", 0, 1.0), unfinished});
  EXPECT_EQ(csv, csv_header() + "reactive,0,100,1,0,5,50,12.5,1\ncomm_serial,1,101,2,10,5,51,12.5,0\n");
}

TEST(ReportTest, MarkdownHasMeansAndTests) {
  std::vector<TrialRecord> records = {
      record("reactive", 0, 60.0),   record("reactive", 1, 70.0),
      record("reactive", 2, 65.0),   record("plan_66_34", 0, 50.0),
      record("plan_66_34", 1, 48.0), record("plan_66_34", 2, 52.0),
      record("comm_serial", 0, 116.0),
  };
  records[1].all_finished = false;  // reactive trial 1 ran out of ticks
  const std::string md = write_markdown_report(records, "Test");
  EXPECT_NE(md.find("# Test\n"), std::string::npos);
  // Reactive mission time: mean 65, sd 5.
  EXPECT_NE(md.find("| Reactive only | 3 | 2 | 65.00 ± 5.00 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| 66:34 reactive:plan | 3 | 3 | 50.00 ± 2.00 |"), std::string::npos) << md;
  // No trials: n = 0 and dashes.
  EXPECT_NE(md.find("| Planning w/o comms | 0 | 0 | - |"), std::string::npos) << md;
  // Every compared pair has a row.
  EXPECT_NE(md.find("| Reactive only vs 66:34 reactive:plan | t = "), std::string::npos) << md;
  EXPECT_NE(md.find("| Planning w/ comms, parallel vs Planning w/ comms, serial | n/a |"),
            std::string::npos)
      << md;
  // Reactive vs 66:34, mission time: the Welch t of the same data.
  const WelchResult w = welch_t_test({60, 70, 65}, {50, 48, 52});
  char expected[64];
  std::snprintf(expected, sizeof expected, "t = %.3f (%.1f)", w.t, w.df);
  EXPECT_NE(md.find(expected), std::string::npos) << md;
  // Identical samples (time connected is constant in both): p = 1, t = 0.
  EXPECT_NE(md.find("t = 0.000 (4.0), p = 1.0000"), std::string::npos) << md;
}

}  // namespace
}  // namespace autonomy::stats
