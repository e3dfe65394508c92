#pragma once
// The robot-teams paper's findings, checked against a run's trials: each is a comparison of one
// metric between configurations, with the paper's own figures beside ours. A finding holds when
// the means differ in the paper's direction and a two-sided Welch t-test gives p < 0.05.
#include "tools/experiments/stats/report.hpp"

#include <string>
#include <vector>

namespace autonomy::stats {

struct FindingCheck {
  std::string claim;         // the paper's finding, in words
  std::string paper;         // the paper's figures (Table 1, Figures 11-12)
  std::string here;          // ours: means and the test
  bool evaluated = false;    // false when a configuration has fewer than two trials
  bool holds = false;
};

// The four comparisons: parallel communication plans vs reactive (% time fully connected);
// serial vs parallel (coverage); the better reactive:plan mix vs reactive (mission time); serial
// vs parallel (% time fully connected, where the paper found serial lower).
std::vector<FindingCheck> check_paper_findings(const std::vector<TrialRecord>& records);

// "## The paper's findings" with one row per check.
std::string write_findings_markdown(const std::vector<FindingCheck>& checks);

}  // namespace autonomy::stats
