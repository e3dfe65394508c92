#include <gtest/gtest.h>

#include "gantt_svg.hpp"
#include "stn_text.hpp"

namespace autonomy::planner {
namespace {

TEST(StnText, PrintsEveryTimepointsBounds) {
  StnReport r = run_stn_text(
      "horizon 100\ntimepoint a b\norigin a 10 20\na b 5 5  # b five after a\n", "t.stn");
  ASSERT_TRUE(r.ok) << r.text;
  ASSERT_TRUE(r.consistent);
  EXPECT_EQ(r.text, "a 10 20\nb 15 25\n");
  EXPECT_EQ(run_stn_text("timepoint a\n", "t").text, "a 0 inf\n");
}

TEST(StnText, NamesTheLinesOfTheNegativeCycle) {
  StnReport r = run_stn_text("timepoint a b c\na b 10 20\nb c 10 20\n\nc a -15 0\n", "t.stn");
  ASSERT_TRUE(r.ok);
  EXPECT_FALSE(r.consistent);
  EXPECT_EQ(r.text.rfind("t.stn:5: closes a negative cycle with", 0), 0u) << r.text;
  EXPECT_NE(r.text.find("line 2"), std::string::npos) << r.text;
  EXPECT_NE(r.text.find("line 3"), std::string::npos) << r.text;
}

TEST(StnText, MalformedLinesAreReportedWithTheirNumber) {
  EXPECT_EQ(run_stn_text("timepoint a\na z 1 2\n", "f").text, "f:2: unknown timepoint 'z'");
  EXPECT_EQ(run_stn_text("timepoint a\norigin a 5 2\n", "f").text, "f:2: lb 5 > ub 2");
  EXPECT_EQ(run_stn_text("timepoint a\norigin a x 2\n", "f").text,
            "f:2: bounds must be integers or inf");
  EXPECT_EQ(run_stn_text("timepoint a a\n", "f").text, "f:1: timepoint 'a' declared twice");
  EXPECT_FALSE(run_stn_text("origin a 1\n", "f").ok);
}

TEST(GanttSvg, OneRowPerTimelineAndAWhiskerPerFlexibleBound) {
  FlexiblePlan plan;
  plan.horizon = 100;
  plan.makespan = 30;
  PlanToken t;
  t.object = "m0";
  t.attribute = "busy";
  t.predicate = "op";
  t.start_lb = 0;
  t.start_ub = 10;
  t.end_lb = 30;
  t.end_ub = 40;
  plan.tokens.push_back(t);
  plan.timelines.push_back({"m0.busy", {0}});
  plan.timelines.push_back({"m1.busy", {}});
  std::string svg = gantt_svg(plan);
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_NE(svg.find(">m0.busy<"), std::string::npos);
  EXPECT_NE(svg.find(">m1.busy<"), std::string::npos);
  EXPECT_NE(svg.find("start [0, 10] end [30, 40]"), std::string::npos);
}

}  // namespace
}  // namespace autonomy::planner
