// The flight report: planned against executed tokens of each plan, an abort cutting a token
// short, faults and responses on the time axis, goals.
#include "run_report.hpp"

#include <gtest/gtest.h>

#include "dispatchable_network.hpp"

namespace autonomy::executive {
namespace {

planner::FlexiblePlan camera_plan() {
  planner::FlexiblePlan plan;
  plan.horizon = 100;
  plan.timelines.push_back({"sc.camera", {0, 1, 2}});
  auto token = [&](std::string predicate, std::int64_t s_lb, std::int64_t s_ub, std::int64_t d, std::string origin) {
    planner::PlanToken t;
    t.id = static_cast<std::uint32_t>(plan.tokens.size());
    t.object = "sc";
    t.attribute = "camera";
    t.predicate = std::move(predicate);
    t.start_lb = s_lb;
    t.start_ub = s_ub;
    t.end_lb = s_lb + d;
    t.end_ub = kUnbounded;
    t.duration_lb = t.duration_ub = d;
    t.origin = std::move(origin);
    plan.tokens.push_back(t);
  };
  token("ready", 0, 0, 10, "initial");
  token("picture", 10, 10, 20, "goal shot");
  token("ready", 30, 30, 70, "after of token 1");
  plan.constraints = {{"0.end", "1.start", 0, 0}, {"1.end", "2.start", 0, 0}};
  return plan;
}

TEST(RunReport, PlannedAgainstExecutedWithAnAbortAndItsFault) {
  planner::FlexiblePlan plan = camera_plan();
  std::string error;
  auto net = make_dispatchable(plan, &error);
  ASSERT_TRUE(net) << error;
  Dispatcher d(plan, std::move(*net), 1000);
  d.step(1000);
  d.step(1010);
  d.step(1020);  // aborted here, the picture under way

  RunReport report;
  report.add_event(1020, "fault abort_and_replan", "camera reports imaging but the plan expects ready");
  report.add_event(1020, "started", "not drawn");
  report.add_plan("plan-1", d, 1020);
  report.set_goals({}, {"shot: camera imaging"});
  ASSERT_EQ(report.tokens().size(), 3u);
  const ReportToken& shot = report.tokens()[1];
  EXPECT_EQ(shot.text, "picture()");
  EXPECT_TRUE(shot.goal);
  EXPECT_EQ(shot.start_lb, 1010);
  EXPECT_EQ(shot.end_lb, 1030);
  ASSERT_TRUE(shot.started && shot.ended);
  EXPECT_EQ(*shot.started, 1010);
  EXPECT_EQ(*shot.ended, 1020);
  EXPECT_TRUE(shot.cut_short);
  EXPECT_FALSE(report.tokens()[2].started);
  ASSERT_EQ(report.events().size(), 1u);  // only faults, responses, plans and goals are kept

  const std::string svg = report.svg(1200);
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_NE(svg.find("sc.camera"), std::string::npos);
  EXPECT_NE(svg.find("#c33"), std::string::npos);  // the picture cut short
  EXPECT_NE(svg.find("00:17:00 fault abort_and_replan"), std::string::npos);
  const std::string md = report.markdown("test flight", 1200);
  EXPECT_NE(md.find("| 00:17:00 | fault abort_and_replan | camera reports imaging"), std::string::npos);
  EXPECT_NE(md.find("0 goals achieved, 1 lost"), std::string::npos);
  EXPECT_NE(md.find("- shot: camera imaging"), std::string::npos);
}

}  // namespace
}  // namespace autonomy::executive
