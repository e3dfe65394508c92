#pragma once
// The experiment of Wagner & Arkin, "Internalized Plans for Communication-Sensitive Robot Team
// Behaviors", Table 1: the six configurations, the per-trial metrics, the pairs the paper tests
// against each other, and the CSV and Markdown outputs. Pure: strings in, strings out.

#include "tools/experiments/stats/stats.hpp"

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace autonomy::stats {

struct Configuration {
  std::string id;     // file-name stem, e.g. deploy/missions/<id>_r1.pbtxt
  std::string label;  // as in the paper's table
};

// The six configurations of Table 1, in the paper's order.
const std::vector<Configuration>& table1_configurations();

// The pairs of configuration ids the paper compares with two-sided t-tests (Table 1 rows
// "t-Test for ..."). The one place listing them.
const std::vector<std::pair<std::string, std::string>>& table1_compared_pairs();

// One trial's results (one CSV row).
struct TrialRecord {
  std::string configuration;  // Configuration::id
  int trial = 0;
  uint64_t seed = 0;
  double mission_time_s = 0.0;
  double distance_m = 0.0;
  double time_connected_s = 0.0;
  double percent_time_fully_connected = 0.0;
  double coverage_percent = 0.0;
  bool all_finished = true;   // every robot finished its mission before the run's tick limit
};

struct Metric {
  std::string key;    // CSV column
  std::string label;  // report heading
  double (*get)(const TrialRecord&);
};

// The per-trial metrics, in CSV column order.
const std::vector<Metric>& trial_metrics();

// "configuration,trial,seed,<metric keys>,finished\n" then one row per record, in the given
// order (finished: 1 or 0).
std::string csv_header();
std::string csv_row(const TrialRecord& record);
std::string write_csv(const std::vector<TrialRecord>& records);

// The values of one metric over the trials of one configuration.
std::vector<double> metric_values(const std::vector<TrialRecord>& records,
                                  const std::string& configuration, const Metric& metric);

// Markdown: a title, a table (configuration, n, how many finished, mean ± sd per metric) with one row per
// configuration of `configurations` (rows with no trials show n = 0 and "-"), and a table of
// Welch t-tests (t, df, two-sided p per metric) for each pair in `pairs`.
std::string write_markdown_report(
    const std::vector<TrialRecord>& records, const std::vector<Configuration>& configurations,
    const std::vector<std::pair<std::string, std::string>>& pairs, const std::string& title);

// The same with the paper's configurations and pairs.
std::string write_markdown_report(const std::vector<TrialRecord>& records,
                                  const std::string& title = "Experiment results (Table 1)");

}  // namespace autonomy::stats
