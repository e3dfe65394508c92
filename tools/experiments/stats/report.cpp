#include "tools/experiments/stats/report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace autonomy::stats {

const std::vector<Configuration>& table1_configurations() {
  static const std::vector<Configuration> kConfigurations = {
      {"reactive", "Reactive only"},
      {"plan_66_34", "66:34 reactive:plan"},
      {"plan_34_66", "34:66 reactive:plan"},
      {"plan_no_comms", "Planning w/o comms"},
      {"comm_parallel", "Planning w/ comms, parallel"},
      {"comm_serial", "Planning w/ comms, serial"},
  };
  return kConfigurations;
}

const std::vector<std::pair<std::string, std::string>>& table1_compared_pairs() {
  // Table 1's t-test rows, in the paper's order.
  static const std::vector<std::pair<std::string, std::string>> kPairs = {
      {"reactive", "plan_66_34"},       {"reactive", "plan_34_66"},
      {"reactive", "plan_no_comms"},    {"plan_66_34", "plan_34_66"},
      {"plan_66_34", "plan_no_comms"},  {"plan_34_66", "plan_no_comms"},
      {"comm_parallel", "comm_serial"},
  };
  return kPairs;
}

const std::vector<Metric>& trial_metrics() {
  static const std::vector<Metric> kMetrics = {
      {"mission_time_s", "Mission time (s)",
       [](const TrialRecord& r) { return r.mission_time_s; }},
      {"distance_m", "Distance (m)", [](const TrialRecord& r) { return r.distance_m; }},
      {"time_connected_s", "Time connected (s)",
       [](const TrialRecord& r) { return r.time_connected_s; }},
      {"percent_time_fully_connected", "% time fully connected",
       [](const TrialRecord& r) { return r.percent_time_fully_connected; }},
      {"coverage_percent", "Coverage (%)",
       [](const TrialRecord& r) { return r.coverage_percent; }},
  };
  return kMetrics;
}

namespace {

std::string format(const char* fmt, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, v);
  return buf;
}

std::string number(double v) { return format("%.6g", v); }

std::string fixed(double v, int decimals) {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  if (std::isnan(v)) return "nan";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

std::string p_value(double p) {
  if (std::isnan(p)) return "nan";
  if (p < 1e-4) return "< 0.0001";
  return fixed(p, 4);
}

std::string label_of(const std::vector<Configuration>& configurations, const std::string& id) {
  for (const auto& c : configurations) {
    if (c.id == id) return c.label;
  }
  return id;
}

}  // namespace

std::string csv_header() {
  std::string out = "configuration,trial,seed";
  for (const auto& m : trial_metrics()) out += "," + m.key;
  return out + ",finished\n";
}

std::string csv_row(const TrialRecord& record) {
  std::string out = record.configuration + "," + std::to_string(record.trial) + "," +
                    std::to_string(record.seed);
  for (const auto& m : trial_metrics()) out += "," + number(m.get(record));
  return out + (record.all_finished ? ",1\n" : ",0\n");
}

std::string write_csv(const std::vector<TrialRecord>& records) {
  std::string out = csv_header();
  for (const auto& r : records) out += csv_row(r);
  return out;
}

std::vector<double> metric_values(const std::vector<TrialRecord>& records,
                                  const std::string& configuration, const Metric& metric) {
  std::vector<double> values;
  for (const auto& r : records) {
    if (r.configuration == configuration) values.push_back(metric.get(r));
  }
  return values;
}

std::string write_markdown_report(
    const std::vector<TrialRecord>& records, const std::vector<Configuration>& configurations,
    const std::vector<std::pair<std::string, std::string>>& pairs, const std::string& title) {
  const auto& metrics = trial_metrics();
  std::ostringstream out;
  out << "# " << title << "\n\n";

  out << "## Mean ± standard deviation per configuration\n\n";
  out << "| Configuration | n | finished |";
  for (const auto& m : metrics) out << " " << m.label << " |";
  out << "\n|---|---:|---:|";
  for (size_t i = 0; i < metrics.size(); ++i) out << "---:|";
  out << "\n";
  for (const auto& c : configurations) {
    const size_t n = metric_values(records, c.id, metrics.front()).size();
    const auto finished = std::count_if(records.begin(), records.end(), [&](const TrialRecord& r) {
      return r.configuration == c.id && r.all_finished;
    });
    out << "| " << c.label << " | " << n << " | " << finished << " |";
    for (const auto& m : metrics) {
      const auto values = metric_values(records, c.id, m);
      if (values.empty()) {
        out << " - |";
      } else {
        out << " " << fixed(mean(values), 2) << " ± " << fixed(sample_stddev(values), 2) << " |";
      }
    }
    out << "\n";
  }

  out << "\n## Welch t-tests (two-sided)\n\n";
  out << "Each cell: t (df), p. \"n/a\" when a configuration has fewer than two trials.\n\n";
  out << "| Comparison |";
  for (const auto& m : metrics) out << " " << m.label << " |";
  out << "\n|---|";
  for (size_t i = 0; i < metrics.size(); ++i) out << "---:|";
  out << "\n";
  for (const auto& [first, second] : pairs) {
    out << "| " << label_of(configurations, first) << " vs " << label_of(configurations, second)
        << " |";
    for (const auto& m : metrics) {
      const WelchResult w =
          welch_t_test(metric_values(records, first, m), metric_values(records, second, m));
      if (!w.valid) {
        out << " n/a |";
      } else {
        out << " t = " << fixed(w.t, 3) << " (" << fixed(w.df, 1) << "), p = " << p_value(w.p)
            << " |";
      }
    }
    out << "\n";
  }
  return out.str();
}

std::string write_markdown_report(const std::vector<TrialRecord>& records,
                                  const std::string& title) {
  return write_markdown_report(records, table1_configurations(), table1_compared_pairs(), title);
}

}  // namespace autonomy::stats
