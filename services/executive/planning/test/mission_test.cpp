// The mission cut into planning requests: goals moved to the request's origin, settled and
// impossible goals left out, passed windows reported; and every cut of the DS1-like day is
// planned by the real planner (its pure request path) from the values the last one left.
#include "mission.hpp"

#include <gtest/gtest.h>

#include "planning_request.hpp"
#include "planner_language.hpp"

namespace autonomy::executive {
namespace {

const std::string kPlannerExamples = PLANNER_EXAMPLES_DIR;

Mission ds1(const std::string& problem) {
  std::string error;
  auto m = Mission::load(kPlannerExamples + "/ds1.model", kPlannerExamples + "/" + problem, &error);
  EXPECT_TRUE(m) << error;
  return std::move(*m);
}

const pb::Fact* goal(const pb::Problem& p, const std::string& label) {
  for (const pb::Fact& g : p.goals())
    if (g.label() == label) return &g;
  return nullptr;
}

pb::Problem problem_of(const GoalWindowCut& cut) {
  pb::Problem p;
  EXPECT_TRUE(p.ParseFromArray(cut.request.problem_protobuf.data(),
                               static_cast<int>(cut.request.problem_protobuf.size())));
  return p;
}

msg::PlanningReply plan(GoalWindowCut cut) {
  cut.request.request_id = "t";
  cut.request.requester = "test";
  auto prepared = planner::prepare_run(cut.request);
  if (auto* r = std::get_if<msg::PlanningReply>(&prepared)) return *r;
  planner::RunControl control{[] { return false; }, [] { return false; }, [] { return 0.0; }, nullptr};
  return planner::run_planning(cut.request, std::get<planner::PreparedRun>(prepared), control);
}

TEST(Mission, TheSecondHorizonIsMovedToItsOriginAndLeavesTheFirstsGoals) {
  const Mission m = ds1("ds1-4h.problem");
  EXPECT_EQ(m.horizon(), 14400);
  EXPECT_EQ(m.goal_labels().size(), 16u);
  EXPECT_EQ(m.goal_timeline("thrust2"), "dsone.engine");
  const std::set<std::string> first = {"hidden1", "pass1", "thrust1", "nav1_1", "nav1_2",
                                       "nav1_3", "nav1_4", "down1"};
  const GoalWindowCut cut = m.request(7200, 14400, {}, first, {});
  const pb::Problem p = problem_of(cut);
  EXPECT_EQ(p.horizon(), 7200);
  EXPECT_EQ(cut.goals, (std::vector<std::string>{"hidden2", "pass2", "thrust2", "nav2_1", "nav2_2",
                                                 "nav2_3", "nav2_4", "down2"}));
  ASSERT_TRUE(goal(p, "pass2"));
  EXPECT_EQ(goal(p, "pass2")->start().lb(), 4800);  // 12000 - 7200
  EXPECT_EQ(goal(p, "pass2")->end().ub(), 7200);
  EXPECT_EQ(goal(p, "thrust2")->start().ub(), 3600);
  EXPECT_EQ(goal(p, "thrust2")->duration().lb(), 2400);  // durations do not move
  EXPECT_EQ(cut.request.plan_origin, 7200);
  EXPECT_TRUE(cut.lost.empty());
  // Unsettled, the first block's goals whose windows closed before 7200 are lost (a downlink
  // could still start at 7200 by its own window: the planner would then say whether it fits).
  const GoalWindowCut late = m.request(7200, 14400, {}, {}, {});
  EXPECT_EQ(late.lost.size(), 7u);
  EXPECT_NE(late.lost.at("pass1").find("closed before 7200"), std::string::npos);
}

TEST(Mission, SettledImpossibleAndExecutingGoals) {
  const Mission m = ds1("ds1-4h.problem");
  const std::set<std::string> settled = {"hidden1", "nav1_1"};
  const std::map<std::string, std::string> impossible = {{"dsone.camera", "camera stuck imaging"}};
  const GoalWindowCut cut = m.request(900, 7200, {}, settled, impossible, {"thrust1"});
  const pb::Problem p = problem_of(cut);
  EXPECT_FALSE(goal(p, "hidden1"));
  EXPECT_FALSE(goal(p, "nav1_2"));
  EXPECT_EQ(cut.lost.at("nav1_2"), "camera stuck imaging");
  EXPECT_EQ(cut.lost.count("nav1_1"), 0u);  // settled, not lost again
  ASSERT_TRUE(goal(p, "thrust1"));           // begun under the old plan: starts again at once
  EXPECT_EQ(goal(p, "thrust1")->start().lb(), 0);
  EXPECT_EQ(goal(p, "thrust1")->start().ub(), 0);
  EXPECT_EQ(goal(p, "pass1")->start().lb(), 3900);
  EXPECT_EQ(m.state_timelines(), (std::set<std::string>{"dsone.attitude", "dsone.camera", "dsone.engine"}));
}

// Horizon by horizon through the whole day, each from the values the previous plan ends with:
// every cut has a plan (what the executive relies on to join horizons without a gap).
TEST(Mission, EveryHorizonOfTheDayIsPlannedFromTheLastOnesValues) {
  const Mission m = ds1("ds1-day.problem");
  std::set<std::string> settled;
  std::vector<msg::PlannerTimelineValue> state;
  for (MissionTime origin = 0; origin < m.horizon(); origin += 14400) {
    GoalWindowCut cut = m.request(origin, origin + 14400, state, settled, {});
    EXPECT_TRUE(cut.lost.empty()) << "at " << origin << ": " << cut.lost.begin()->first;
    const msg::PlanningReply reply = plan(cut);
    ASSERT_TRUE(reply.has_plan) << "horizon at " << origin << ": " << reply.reason << " " << reply.detail;
    EXPECT_TRUE(reply.violations.empty());
    settled.insert(cut.goals.begin(), cut.goals.end());
    state.clear();
    for (const msg::PlanTimeline& line : reply.plan.timelines) {
      if (!m.state_timelines().count(line.name) || line.tokens.empty()) continue;
      const msg::PlanToken& last = reply.plan.tokens[line.tokens.back()];
      if (last.end_ub < reply.plan.horizon)  // a thrust arc: the engine rests at its initial value
        state.push_back(*m.initial_value(line.name));
      else
        state.push_back({line.name, last.predicate, last.parameters});
    }
    EXPECT_EQ(state.size(), 3u);
  }
  EXPECT_EQ(settled.size(), m.goal_labels().size());
}

// With the camera no longer commanded (stuck on), the second block is planned without its
// pictures, and without the downlink that needed them.
TEST(Mission, AHorizonWithoutTheCamerasGoalsIsPlanned) {
  const Mission m = ds1("ds1-4h.problem");
  const std::set<std::string> first = {"hidden1", "pass1", "thrust1", "nav1_1", "nav1_2",
                                       "nav1_3", "nav1_4", "down1"};
  const std::vector<msg::PlannerTimelineValue> state = {
      {"dsone.engine", "off", {}}, {"dsone.camera", "ready", {}}, {"dsone.attitude", "pointAt", {"earth"}}};
  GoalWindowCut cut = m.request(7200, 14400, state, first, {{"dsone.camera", "camera imaging"}});
  EXPECT_EQ(cut.goals, (std::vector<std::string>{"hidden2", "pass2", "thrust2", "down2"}));
  EXPECT_EQ(cut.lost.size(), 4u);
  // Downlinks need pictures (storage): as asked, the horizon has no plan...
  EXPECT_EQ(plan(cut).status, msg::PlanningStatus::Infeasible);
  // ...with every goal optional the planner keeps what the stuck camera still allows.
  cut = m.request(7200, 14400, state, first, {{"dsone.camera", "camera imaging"}}, {}, true);
  EXPECT_TRUE(goal(problem_of(cut), "thrust2")->optional());
  const msg::PlanningReply reply = plan(cut);
  ASSERT_TRUE(reply.has_plan) << reply.reason << " " << reply.detail;
  EXPECT_EQ(reply.plan.omitted_goals, std::vector<std::string>{"down2"});
}

}  // namespace
}  // namespace autonomy::executive
