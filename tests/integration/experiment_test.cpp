// The experiment runner end to end: a small run of the paper's six configurations (two trials
// each) through the real simulator and behavior processes produces a well-formed CSV, a report
// with every configuration and every compared pair, and the typical runs' pictures.
//
//   domain  test
//   ------  -----------------------------------------------
//   90-91   ExperimentTest.SmallRunWritesCsvReportAndPictures (the runner's two jobs)
//   187-188 ExperimentTest.ALockstepTrialRepeatsExactly (two runners side by side)
// SmallRun runs each trial in one process (the runner's default); ALockstepTrialRepeatsExactly
// runs the same trials that way and with a process per node.
#include "tests/support/process_test.hpp"
#include "tools/experiments/stats/report.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <set>
#include <sstream>

namespace autonomy::test {
namespace {

using namespace std::chrono_literals;

std::vector<std::string> split(const std::string& line, char sep) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  std::string field;
  while (std::getline(ss, field, sep)) out.push_back(field);
  return out;
}

class ExperimentTest : public ProcessTest {};

TEST_F(ExperimentTest, SmallRunWritesCsvReportAndPictures) {
  join(90);
  const std::string out = dir().file("experiment");
  auto& runner = start("experiment_runner", AUTONOMY_EXPERIMENT_RUNNER_BIN,
                       {"--trials", "2", "--seed", "5", "--jobs", "2", "--domain", "90", "--out", out}, false);
  const auto ended = runner.wait_for_exit(std::chrono::minutes(6));
  ASSERT_TRUE(ended.has_value()) << "the runner did not finish in 6 minutes";
  ASSERT_TRUE(ended->exited && ended->code == 0) << ended->describe() << "\n" << runner.log_tail();
  // Progress: one line per trial, counted up to the total.
  const std::string progress = read_file(runner.log_file());
  EXPECT_NE(progress.find("[ 12/12]"), std::string::npos) << progress;
  // Each trial's four nodes ran in one process, which logged them to the trial's own file.
  EXPECT_NE(progress.find("one process per trial"), std::string::npos) << progress;
  EXPECT_NE(read_file(out + "/logs/trial-reactive-0.log").find("trial reactive-0: 4 nodes in one process"),
            std::string::npos);

  // CSV: the header, then 2 rows per configuration in the paper's order, values in range.
  std::stringstream csv(read_file(out + "/trials.csv"));
  std::string line;
  ASSERT_TRUE(std::getline(csv, line));
  EXPECT_EQ(line + "\n", stats::csv_header());
  const auto columns = split(line, ',');
  std::map<std::string, int> rows_per_configuration;
  std::vector<std::string> order;
  std::set<std::string> seeds;
  while (std::getline(csv, line)) {
    const auto f = split(line, ',');
    ASSERT_EQ(f.size(), columns.size()) << line;
    if (order.empty() || order.back() != f[0]) order.push_back(f[0]);
    ++rows_per_configuration[f[0]];
    seeds.insert(f[2]);
    const double mission_time = std::stod(f[3]), distance = std::stod(f[4]), connected = std::stod(f[5]);
    const double fully = std::stod(f[6]), coverage = std::stod(f[7]);
    EXPECT_GT(mission_time, 60.0) << line;  // 240 m at 2 m/s at best
    EXPECT_LE(mission_time, 400.0) << line;  // the 4000-tick limit
    EXPECT_GT(distance, 3 * 240.0) << line;  // three robots, each at least the straight line
    EXPECT_GE(connected, 0.0) << line;
    EXPECT_LE(connected, 3 * mission_time + 0.1) << line;
    EXPECT_GE(fully, 0.0) << line;
    EXPECT_LE(fully, 100.0) << line;
    EXPECT_GT(coverage, 0.0) << line;
    EXPECT_LT(coverage, 100.0) << line;
    EXPECT_TRUE(f[8] == "0" || f[8] == "1") << line;
  }
  std::vector<std::string> expected_order;
  for (const auto& c : stats::table1_configurations()) {
    expected_order.push_back(c.id);
    EXPECT_EQ(rows_per_configuration[c.id], 2) << c.id;
  }
  EXPECT_EQ(order, expected_order);
  // Only the three controllers' robots took part: the scenario's own scouts were not spawned.
  for (const auto& c : stats::table1_configurations()) {
    const std::string metrics = read_file(out + "/" + c.id + "-0.json");
    for (const char* robot : {"\"r1\"", "\"r2\"", "\"r3\""}) EXPECT_NE(metrics.find(robot), std::string::npos) << c.id;
    EXPECT_EQ(metrics.find("scout"), std::string::npos) << c.id;
  }
  EXPECT_EQ(seeds.size(), 12u) << "every trial has its own seed";

  // Report: every configuration with n = 2, every compared pair with a t-test, six pictures.
  const std::string report = read_file(out + "/report.md");
  for (const auto& c : stats::table1_configurations()) {
    EXPECT_NE(report.find("| " + c.label + " | 2 |"), std::string::npos) << c.label << "\n" << report;
    const std::string picture = out + "/typical-" + c.id + ".svg";
    EXPECT_NE(report.find("(typical-" + c.id + ".svg)"), std::string::npos) << report;
    const std::string svg = read_file(picture);
    EXPECT_NE(svg.find("<svg"), std::string::npos) << picture;
    EXPECT_NE(svg.find("</svg>"), std::string::npos) << picture;
  }
  EXPECT_NE(report.find("## The paper's findings"), std::string::npos) << report;
  for (const auto& [a, b] : stats::table1_compared_pairs()) {
    std::string label_a, label_b;
    for (const auto& c : stats::table1_configurations()) {
      if (c.id == a) label_a = c.label;
      if (c.id == b) label_b = c.label;
    }
    EXPECT_NE(report.find("| " + label_a + " vs " + label_b + " | t = "), std::string::npos) << report;
  }
}

// Lockstep is deterministic: the same trials, run twice side by side (each run's processes
// scheduled differently, on a loaded machine), give byte-identical metrics and pictures. With team messages (comm_parallel) and the reactive
// missions, every input of a tick (scans, team messages, mission status) must count at that tick
// whatever order the processes read them in (EventLoop::drain); before it, repeated trials
// differed by tenths of a second of mission time. One run puts each trial's simulator and
// behaviors in one process (experiment_trial_host: one thread, no network), the other gives each
// node a process of its own, as deployed: the experiment's results do not depend on which.
TEST_F(ExperimentTest, ALockstepTrialRepeatsExactly) {
  join(187);
  join(188);
  const std::string first = dir().file("first"), second = dir().file("second");
  const std::vector<std::string> common = {"--trials", "2", "--seed", "11", "--jobs", "1", "--only", "comm_parallel",
                                           "reactive"};
  auto args = [&](const std::string& domain, const std::string& out, const std::string& processes) {
    std::vector<std::string> a = common;
    a.insert(a.end(), {"--domain", domain, "--out", out, "--processes", processes});
    return a;
  };
  auto& a = start("experiment_runner_a", AUTONOMY_EXPERIMENT_RUNNER_BIN, args("187", first, "one"), false);
  auto& b = start("experiment_runner_b", AUTONOMY_EXPERIMENT_RUNNER_BIN, args("188", second, "separate"), false);
  for (auto* runner : {&a, &b}) {
    const auto ended = runner->wait_for_exit(std::chrono::minutes(4));
    ASSERT_TRUE(ended.has_value()) << "a runner did not finish in 4 minutes";
    ASSERT_TRUE(ended->exited && ended->code == 0) << ended->describe() << "\n" << runner->log_tail();
  }
  for (const char* configuration : {"comm_parallel", "reactive"}) {
    for (int trial = 0; trial < 2; ++trial) {
      const std::string stem = std::string("/") + configuration + "-" + std::to_string(trial);
      for (const char* extension : {".json", ".csv", ".svg"}) {
        const std::string x = read_file(first + stem + extension), y = read_file(second + stem + extension);
        ASSERT_FALSE(x.empty()) << first + stem + extension;
        EXPECT_EQ(x, y) << stem << extension << " differs between two runs of the same trial";
      }
    }
  }
  // The trials themselves differ (their seeds place the robots apart): the comparison means something.
  EXPECT_NE(read_file(first + "/reactive-0.json"), read_file(first + "/reactive-1.json"));
}

}  // namespace
}  // namespace autonomy::test
