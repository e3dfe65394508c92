#include "tools/experiments/stats/findings.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace autonomy::stats {
namespace {

TrialRecord trial(const std::string& cfg, int k, double time, double fully, double coverage) {
  TrialRecord r;
  r.configuration = cfg;
  r.trial = k;
  r.mission_time_s = time + k;  // a little spread, so the tests have a variance
  r.percent_time_fully_connected = fully + k;
  r.coverage_percent = coverage + 0.1 * k;
  return r;
}

// Three trials per configuration shaped like the paper's Table 1.
std::vector<TrialRecord> paper_like() {
  std::vector<TrialRecord> out;
  for (int k = 0; k < 3; ++k) {
    out.push_back(trial("reactive", k, 66, 21, 5));
    out.push_back(trial("plan_66_34", k, 50, 21, 5));
    out.push_back(trial("plan_34_66", k, 45, 21, 5));
    out.push_back(trial("plan_no_comms", k, 54, 20, 5));
    out.push_back(trial("comm_parallel", k, 60, 98, 2));
    out.push_back(trial("comm_serial", k, 117, 76, 4));
  }
  return out;
}

TEST(Findings, PaperLikeTrialsShowEveryFinding) {
  const auto checks = check_paper_findings(paper_like());
  ASSERT_EQ(checks.size(), 4u);
  for (const auto& c : checks) {
    EXPECT_TRUE(c.evaluated) << c.claim;
    EXPECT_TRUE(c.holds) << c.claim << ": " << c.here;
  }
  // The better mix (34:66 here) is the one compared with reactive.
  EXPECT_NE(checks[2].here.find("34:66 reactive:plan 46.0"), std::string::npos) << checks[2].here;
  EXPECT_NE(checks[0].here.find("Planning w/ comms, parallel 99.0 vs Reactive only 22.0"), std::string::npos)
      << checks[0].here;
}

TEST(Findings, EqualOrReversedMeansDoNotHold) {
  auto records = paper_like();
  for (auto& r : records) {
    if (r.configuration == "comm_serial") r.coverage_percent -= 3.0;  // now below parallel
    if (r.configuration == "comm_parallel") r.percent_time_fully_connected = 21 + r.trial;  // = reactive
  }
  const auto checks = check_paper_findings(records);
  EXPECT_FALSE(checks[0].holds) << checks[0].here;  // same values: p = 1
  EXPECT_FALSE(checks[1].holds) << checks[1].here;  // reversed
  EXPECT_TRUE(checks[2].holds);
  const std::string md = write_findings_markdown(checks);
  EXPECT_NE(md.find("## The paper's findings"), std::string::npos);
  EXPECT_NE(md.find("| **no** |"), std::string::npos) << md;
  EXPECT_NE(md.find("| yes |"), std::string::npos) << md;
}

TEST(Findings, TheMixThatRanIsTheOneCompared) {
  auto records = paper_like();
  records.erase(std::remove_if(records.begin(), records.end(),
                               [](const TrialRecord& r) { return r.configuration == "plan_34_66"; }),
                records.end());
  const auto checks = check_paper_findings(records);
  EXPECT_TRUE(checks[2].evaluated);
  EXPECT_NE(checks[2].here.find("66:34 reactive:plan 51.0"), std::string::npos) << checks[2].here;
}

TEST(Findings, TooFewTrialsAreNotEvaluated) {
  const auto checks = check_paper_findings({trial("reactive", 0, 66, 21, 5), trial("comm_parallel", 0, 60, 98, 2)});
  for (const auto& c : checks) EXPECT_FALSE(c.evaluated) << c.claim;
  EXPECT_NE(write_findings_markdown(checks).find("not evaluated"), std::string::npos);
}

}  // namespace
}  // namespace autonomy::stats
