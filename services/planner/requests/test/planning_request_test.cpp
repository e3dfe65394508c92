// The planner service's pure part: request checks, parsing with diagnostics, the executive's
// state folded into the problem, replies and the plan message round trip.
#include "planning_request.hpp"

#include <gtest/gtest.h>

#include "jobshop_instance.hpp"
#include "plan_message.hpp"
#include "plan_validator.hpp"
#include "planner_language.hpp"

namespace autonomy::planner {
namespace {

std::string example(const std::string& name) {
  Diagnostics errors;
  auto text = read_text_file(std::string(PLANNER_EXAMPLES_DIR) + "/" + name, &errors);
  EXPECT_TRUE(text) << to_string(errors);
  return text.value_or("");
}

msg::PlanningRequest camera_request() {
  msg::PlanningRequest q;
  q.request_id = "r1";
  q.requester = "test";
  q.model_file = "camera.model";
  q.model_text = example("camera.model");
  q.problem_file = "camera.problem";
  q.problem_text = example("camera.problem");
  return q;
}

RunControl never_stop() {
  return {[] { return false; }, [] { return false; }, [] { return 0.0; }, nullptr};
}

msg::PlanningReply plan(const msg::PlanningRequest& q) {
  if (auto rejected = check_request(q)) return *rejected;
  auto prepared = prepare_run(q);
  if (auto* r = std::get_if<msg::PlanningReply>(&prepared)) return *r;
  return run_planning(q, std::get<PreparedRun>(prepared), never_stop());
}

TEST(PlanningRequest, TheCameraRequestGetsAValidPlanThatSurvivesTheMessage) {
  msg::PlanningReply r = plan(camera_request());
  ASSERT_EQ(r.status, msg::PlanningStatus::PlanFound) << r.reason << " " << r.detail;
  ASSERT_TRUE(r.has_plan);
  EXPECT_TRUE(r.violations.empty());
  EXPECT_EQ(r.engine, "chronological");
  EXPECT_GT(r.statistics.decisions, 0u);
  EXPECT_EQ(r.statistics.improvements, 1u);
  // The plan through the message and back is the same plan: it still validates.
  const FlexiblePlan back = from_plan_message(r.plan);
  const msg::FlexiblePlan again = to_plan_message(back);
  ASSERT_EQ(again.tokens.size(), r.plan.tokens.size());
  for (std::size_t i = 0; i < again.tokens.size(); ++i) {
    EXPECT_EQ(again.tokens[i].predicate, r.plan.tokens[i].predicate);
    EXPECT_EQ(again.tokens[i].parameters, r.plan.tokens[i].parameters);
    EXPECT_EQ(again.tokens[i].parameter_lo, r.plan.tokens[i].parameter_lo);
    EXPECT_EQ(again.tokens[i].start_ub, r.plan.tokens[i].start_ub);
    EXPECT_EQ(again.tokens[i].duration_lb, r.plan.tokens[i].duration_lb);
  }
  EXPECT_EQ(again.constraints.size(), r.plan.constraints.size());
  auto prepared = prepare_run(camera_request());
  const auto& run = std::get<PreparedRun>(prepared);
  EXPECT_TRUE(validate_plan(run.model, run.problem, back).empty());
}

TEST(PlanningRequest, BadRequestsAreRejectedWithReasons) {
  msg::PlanningRequest q = camera_request();
  q.engine = "simulated-annealing";
  EXPECT_EQ(plan(q).reason, "unknown_engine");
  q = camera_request();
  q.request_id = std::string(200, 'x');
  msg::PlanningReply r = plan(q);
  EXPECT_EQ(r.reason, "too_long");
  EXPECT_EQ(r.request_id.size(), 128u);
  EXPECT_NE(r.detail.find("request_id has 200 bytes"), std::string::npos) << r.detail;
  q = camera_request();
  q.model_text.clear();
  EXPECT_EQ(plan(q).reason, "missing_field");
  q = camera_request();
  q.model_protobuf = {1, 2, 3};
  EXPECT_EQ(plan(q).reason, "ambiguous_model");
  q = camera_request();
  q.model_text.clear();
  q.model_protobuf = {0xff, 0xff, 0xff};
  EXPECT_EQ(plan(q).reason, "invalid_protobuf");
  q = camera_request();
  q.budget_ms = -5;
  EXPECT_EQ(plan(q).reason, "bad_budget");
}

TEST(PlanningRequest, AParseErrorNamesFileLineAndColumn) {
  msg::PlanningRequest q = camera_request();
  q.model_text = "model m\npredicate p() duration [5 1]\n";
  msg::PlanningReply r = plan(q);
  EXPECT_EQ(r.status, msg::PlanningStatus::Rejected);
  EXPECT_EQ(r.reason, "parse_error");
  ASSERT_FALSE(r.diagnostics.empty());
  EXPECT_EQ(r.diagnostics[0].file, "camera.model");
  EXPECT_EQ(r.diagnostics[0].line, 2u);
  EXPECT_GT(r.diagnostics[0].column, 20u);  // at the 1, not the line start
  EXPECT_NE(r.detail.find("camera.model:2:"), std::string::npos) << r.detail;
}

TEST(PlanningRequest, AnInfeasibleProblemNamesItsConflictingStatements) {
  msg::PlanningRequest q = camera_request();
  q.problem_file = "tight.problem";
  q.problem_text =
      "problem p\nhorizon 100\nobject s : Spacecraft\n"
      "goal g: s.camera == picture(comet) start [10, 20] end [0, 12]\n";
  msg::PlanningReply r = plan(q);
  ASSERT_EQ(r.status, msg::PlanningStatus::Infeasible) << r.reason;
  ASSERT_FALSE(r.conflicts.empty());
  bool names_goal = false;
  for (const auto& c : r.conflicts) names_goal |= c.find("tight.problem:4") != std::string::npos;
  EXPECT_TRUE(names_goal) << r.detail;
  EXPECT_FALSE(r.has_plan);
}

TEST(PlanningRequest, TheExecutivesStateReplacesTheInitialValues) {
  msg::PlanningRequest q = camera_request();
  // Already pointing at the asteroid: no turn is needed for the picture.
  q.state = {{"dsone.attitude", "pointAt", {"asteroid"}}};
  q.plan_origin = 5000;
  msg::PlanningReply r = plan(q);
  ASSERT_EQ(r.status, msg::PlanningStatus::PlanFound) << r.reason << " " << r.detail;
  EXPECT_EQ(r.plan_origin, 5000);
  EXPECT_TRUE(r.violations.empty());
  for (const auto& t : r.plan.tokens) EXPECT_NE(t.predicate, "turning");
  q.state = {{"dsone.nowhere", "pointAt", {"asteroid"}}};
  r = plan(q);
  EXPECT_EQ(r.status, msg::PlanningStatus::Rejected);
  EXPECT_EQ(r.reason, "invalid_problem_or_state");
  ASSERT_FALSE(r.diagnostics.empty());
  EXPECT_EQ(r.diagnostics[0].file, "state");
  q.state = {{"attitude", "pointAt", {}}};
  EXPECT_EQ(plan(q).reason, "invalid_state");
}

TEST(PlanningRequest, ACancelledSearchReportsCancelled) {
  msg::PlanningRequest q = camera_request();
  auto prepared = prepare_run(q);
  RunControl stop = never_stop();
  stop.cancelled = [] { return true; };
  msg::PlanningReply r = run_planning(q, std::get<PreparedRun>(prepared), stop);
  EXPECT_EQ(r.status, msg::PlanningStatus::Cancelled);
  EXPECT_FALSE(r.has_plan);
}

TEST(PlanningRequest, AJobShopAsProtobufIsPlannedToItsOptimumWithEachImprovementReported) {
  Diagnostics errors;
  const std::string file = std::string(PLANNER_EXAMPLES_DIR) + "/jobshop/ft06";
  auto text = read_text_file(file, &errors);
  ASSERT_TRUE(text) << to_string(errors);
  auto instance = parse_jobshop(*text, file, &errors);
  ASSERT_TRUE(instance) << to_string(errors);
  msg::PlanningRequest q;
  q.request_id = "ft06";
  const std::string model = jobshop_model(*instance).SerializeAsString();
  const std::string problem = jobshop_problem(*instance).SerializeAsString();
  q.model_protobuf.assign(model.begin(), model.end());
  q.problem_protobuf.assign(problem.begin(), problem.end());
  ASSERT_FALSE(check_request(q));
  auto prepared = prepare_run(q);
  ASSERT_TRUE(std::holds_alternative<PreparedRun>(prepared));
  std::vector<msg::PlanningProgress> progress;
  RunControl control = never_stop();
  control.on_progress = [&](const msg::PlanningProgress& p) { progress.push_back(p); };
  msg::PlanningReply r = run_planning(q, std::get<PreparedRun>(prepared), control);
  ASSERT_EQ(r.status, msg::PlanningStatus::Optimal);
  EXPECT_EQ(r.plan.makespan, 55);
  EXPECT_TRUE(r.violations.empty());
  ASSERT_EQ(progress.size(), r.statistics.improvements);
  for (std::size_t i = 1; i < progress.size(); ++i)
    EXPECT_LT(progress[i].makespan, progress[i - 1].makespan);
  EXPECT_EQ(progress.back().makespan, 55);
  // A decision budget ends it early with the best plan so far, and says so.
  q.max_decisions = 100;
  r = run_planning(q, std::get<PreparedRun>(prepared), never_stop());
  EXPECT_EQ(r.status, msg::PlanningStatus::OutOfTime);
  EXPECT_EQ(r.detail, "the decision budget ended");
  EXPECT_EQ(r.statistics.decisions, 100u);
}

TEST(PlanningRequest, ConflictExplanationsSplitIntoStatements) {
  EXPECT_EQ(conflicting_statements("temporal conflict between: a:1: x; b:2: y"),
            (std::vector<std::string>{"a:1: x", "b:2: y"}));
  EXPECT_EQ(conflicting_statements("overload on s.camera"),
            (std::vector<std::string>{"overload on s.camera"}));
  EXPECT_EQ(conflicting_statements(
                "search exhausted: no plan achieves together: goal a (p:5); goal b (p:6)"),
            (std::vector<std::string>{"goal a (p:5)", "goal b (p:6)"}));
}

}  // namespace
}  // namespace autonomy::planner
