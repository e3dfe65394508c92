// ExecutionTraces: an order of executive event samples in, executed-token records out (lost and
// late samples, an end before its start, re-plans, a restart), and the page's frame of them.
#include "services/viewer/core/execution_trace.hpp"
#include "services/viewer/core/frames.hpp"

#include <gtest/gtest.h>

namespace autonomy::viewer {
namespace {

constexpr int64_t kSecond = 1000000000LL;

msg::ExecutiveEvent event(uint64_t number, int64_t t_s, const std::string& kind, const std::string& text,
                          const std::string& plan = "plan-1") {
  return {"executive/main", number, t_s, t_s * kSecond, kind, text, plan};
}

TEST(ExecutionTraceTest, ParsesTheExecutivesTokenNames) {
  TokenName n;
  ASSERT_TRUE(parse_token_name("dsone.camera == imaging(target1, 5) #12", &n));
  EXPECT_EQ(n.timeline, "dsone.camera");
  EXPECT_EQ(n.value, "imaging(target1, 5)");
  EXPECT_EQ(n.token, 12);
  ASSERT_TRUE(parse_token_name("rover.at == at(lander)", &n));  // no id: matched by text
  EXPECT_EQ(n.value, "at(lander)");
  EXPECT_EQ(n.token, -1);
  ASSERT_TRUE(parse_token_name("a.b == c() #x", &n));  // not an id: part of the value
  EXPECT_EQ(n.value, "c() #x");
  EXPECT_EQ(n.token, -1);
  EXPECT_FALSE(parse_token_name("camera on (c-1)", &n));
  EXPECT_FALSE(parse_token_name(" == x() #1", &n));
  EXPECT_FALSE(parse_token_name("a.b ==  #3", &n));
}

TEST(ExecutionTraceTest, FoldsStartsAndEndsByPlanAndTokenId) {
  ExecutionTraces traces;
  // Two tokens with the same text on one timeline: told apart by their ids.
  traces.apply(event(1, 10, "plan_executing", "plan-1: plan for [10, 100) s executing"));
  traces.apply(event(2, 10, "started", "dsone.engine == idle() #0"));
  traces.apply(event(3, 10, "command", "engine standby()"));
  traces.apply(event(4, 20, "ended", "dsone.engine == idle() #0"));
  traces.apply(event(5, 20, "started", "dsone.engine == thrusting(1) #1"));
  traces.apply(event(6, 30, "ended", "dsone.engine == thrusting(1) #1"));
  traces.apply(event(7, 30, "started", "dsone.engine == idle() #2"));
  traces.apply(event(8, 35, "violation", "dsone.engine: stuck"));

  const ExecutiveTrace& t = traces.executives().at("executive/main");
  ASSERT_EQ(t.tokens.size(), 3u);
  EXPECT_EQ(t.tokens[0].token, 0);
  EXPECT_EQ(t.tokens[0].timeline, "dsone.engine");
  EXPECT_EQ(t.tokens[0].value, "idle()");
  EXPECT_EQ(t.tokens[0].start_ns, 10 * kSecond);
  EXPECT_EQ(t.tokens[0].end_ns, 20 * kSecond);
  EXPECT_EQ(t.tokens[1].value, "thrusting(1)");
  EXPECT_EQ(t.tokens[1].end_ns, 30 * kSecond);
  EXPECT_EQ(t.tokens[2].token, 2);
  EXPECT_EQ(t.tokens[2].start_ns, 30 * kSecond);
  EXPECT_FALSE(t.tokens[2].end_ns.has_value());  // running
  // Commands are not marks; the plan's start and the violation are.
  ASSERT_EQ(t.marks.size(), 2u);
  EXPECT_EQ(t.marks[0].kind, "plan_executing");
  EXPECT_EQ(t.marks[1].kind, "violation");
  EXPECT_EQ(t.marks[1].sim_time_ns, 35 * kSecond);
  EXPECT_EQ(t.lost, 0u);
  EXPECT_EQ(t.refused, 0u);
  EXPECT_EQ(t.plan_id, "plan-1");
}

TEST(ExecutionTraceTest, AnEndBeforeItsStartIsRefusedAndNeverRecorded) {
  ExecutionTraces traces;
  traces.apply(event(1, 50, "started", "a.b == on() #4"));
  traces.apply(event(2, 40, "ended", "a.b == on() #4"));
  const ExecutiveTrace& t = traces.executives().at("executive/main");
  ASSERT_EQ(t.tokens.size(), 1u);
  EXPECT_FALSE(t.tokens[0].end_ns.has_value());
  EXPECT_EQ(t.refused, 1u);
  // Text that names no token is refused too.
  traces.apply(event(3, 60, "started", "garbled"));
  EXPECT_EQ(t.refused, 2u);
  EXPECT_EQ(t.tokens.size(), 1u);
}

TEST(ExecutionTraceTest, AGapInNumbersCountsLostSamplesAndALateOneIsMergedWhereItBelongs) {
  ExecutionTraces traces;
  traces.apply(event(1, 0, "started", "a.b == on() #0"));
  // 2 (a.b's end) and 3 (c.d's start) are not heard yet: 4 ends c.d alone.
  traces.apply(event(4, 7, "ended", "c.d == move(x) #1"));
  const ExecutiveTrace& t = traces.executives().at("executive/main");
  EXPECT_EQ(t.lost, 2u);
  ASSERT_EQ(t.marks.size(), 1u);
  EXPECT_EQ(t.marks[0].kind, "lost");
  EXPECT_EQ(t.marks[0].text, "2 event(s) not heard (numbers 2 to 3)");
  ASSERT_EQ(t.tokens.size(), 2u);
  EXPECT_FALSE(t.tokens[1].start_ns.has_value());  // its start not heard
  EXPECT_EQ(t.tokens[1].end_ns, 7 * kSecond);

  // Sample 3 comes late: c.d's start joins the record that already ended.
  traces.apply(event(3, 5, "started", "c.d == move(x) #1"));
  EXPECT_EQ(t.lost, 1u);
  ASSERT_EQ(t.tokens.size(), 2u);
  EXPECT_EQ(t.tokens[1].start_ns, 5 * kSecond);
  EXPECT_EQ(t.tokens[1].end_ns, 7 * kSecond);
  EXPECT_EQ(t.latest_ns, 7 * kSecond);  // a late sample does not move the time back

  // A sample heard twice changes nothing.
  const uint64_t version = traces.version();
  traces.apply(event(3, 5, "started", "c.d == move(x) #1"));
  EXPECT_EQ(traces.version(), version);
  EXPECT_EQ(t.lost, 1u);

  // A joining viewer's first sample is no gap.
  traces.apply({"executive/other", 40, 9, 9 * kSecond, "started", "e.f == g() #2", "p"});
  EXPECT_EQ(traces.executives().at("executive/other").lost, 0u);
}

TEST(ExecutionTraceTest, AReplanCutsTheAbandonedPlansRunningTokensAndShowsBothPlans) {
  ExecutionTraces traces;
  traces.apply(event(1, 0, "plan_executing", "plan-1: plan for [0, 100) s executing"));
  traces.apply(event(2, 0, "started", "cam.mode == ready() #0"));
  traces.apply(event(3, 10, "ended", "cam.mode == ready() #0"));
  traces.apply(event(4, 10, "started", "cam.mode == imaging(t1) #1"));
  traces.apply(event(5, 12, "fault abort", "camera stuck: aborting"));
  traces.apply(event(6, 12, "aborted", "camera stuck"));
  // The new plan: its token 0 is another token than plan-1's token 0.
  traces.apply(event(7, 14, "plan_executing", "plan-2: new plan from 12 s executing", "plan-2"));
  traces.apply(event(8, 14, "started", "cam.mode == off() #0", "plan-2"));

  const ExecutiveTrace& t = traces.executives().at("executive/main");
  ASSERT_EQ(t.tokens.size(), 3u);
  EXPECT_EQ(t.tokens[1].plan_id, "plan-1");
  EXPECT_TRUE(t.tokens[1].cut);  // imaging was running when plan-1 was aborted
  EXPECT_EQ(t.tokens[1].end_ns, 12 * kSecond);
  EXPECT_EQ(t.tokens[2].plan_id, "plan-2");
  EXPECT_EQ(t.tokens[2].token, 0);
  EXPECT_EQ(t.tokens[0].end_ns, 10 * kSecond);  // plan-1's token 0 untouched
  EXPECT_EQ(t.plan_order, (std::vector<std::string>{"plan-1", "plan-2"}));
  EXPECT_EQ(t.plan_id, "plan-2");

  // The plans, heard from the planner: plan-2 with an unbounded end.
  auto plan = [](const std::string& id, int64_t origin, const std::string& predicate) {
    msg::LatestPlan p;
    p.requester = "executive/main";
    p.request_id = id;
    p.plan_origin = origin;
    p.plan.horizon = 100;
    msg::PlanToken tok;
    tok.id = 0;
    tok.object = "cam";
    tok.attribute = "mode";
    tok.predicate = predicate;
    tok.start_lb = 0;
    tok.start_ub = 2;
    tok.end_lb = 10;
    tok.end_ub = int64_t{1} << 52;
    p.plan.tokens = {tok};
    p.plan.timelines = {{"cam.mode", {0}}};
    return p;
  };
  traces.apply(plan("plan-1", 0, "ready"));
  // plan-2 from the planner's reply (the latest-plan state may have been overwritten unread);
  // a reply without a valid plan brings none.
  msg::PlanningReply reply;
  reply.requester = "executive/main";
  reply.request_id = "plan-2";
  reply.plan_origin = 12;
  reply.plan = plan("plan-2", 12, "off").plan;
  reply.violations = {"token 0 ends before it starts"};
  reply.has_plan = true;
  traces.apply(reply);
  EXPECT_EQ(traces.executives().at("executive/main").plans.count("plan-2"), 0u);
  reply.violations.clear();
  traces.apply(reply);
  msg::LatestPlan other = plan("cli-1", 0, "x");
  other.requester = "autonomy-cli";  // asked for a plan, never executed one: not drawn
  traces.apply(other);

  const auto f = execution_frame(traces);
  EXPECT_EQ(f["type"], "execution");
  ASSERT_EQ(f["executives"].size(), 1u);
  const auto& e = f["executives"]["executive/main"];
  EXPECT_EQ(e["plan_id"], "plan-2");
  ASSERT_EQ(e["plans"].size(), 2u);
  EXPECT_EQ(e["plans"][1]["id"], "plan-2");
  EXPECT_EQ(e["plans"][1]["origin_s"], 12);
  const auto& planned = e["plans"][1]["timelines"][0]["tokens"][0];
  EXPECT_EQ(planned["predicate"], "off");
  EXPECT_EQ(planned["start"], (nlohmann::json{12, 14}));
  EXPECT_EQ(planned["end"][0], 22);
  EXPECT_TRUE(planned["end"][1].is_null());  // no latest end
  ASSERT_EQ(e["executed"].size(), 3u);
  EXPECT_EQ(e["executed"][1]["start_s"], 10.0);
  EXPECT_EQ(e["executed"][1]["end_s"], 12.0);
  EXPECT_TRUE(e["executed"][1]["cut"].get<bool>());
  EXPECT_TRUE(e["executed"][2]["end_s"].is_null());  // running
  std::vector<std::string> kinds;
  for (const auto& m : e["marks"]) kinds.push_back(m["kind"]);
  EXPECT_EQ(kinds, (std::vector<std::string>{"plan_executing", "fault abort", "aborted", "plan_executing"}));

  // One plan shown: plan-1's records are left out.
  const auto one = execution_frame(traces, 1)["executives"]["executive/main"];
  ASSERT_EQ(one["plans"].size(), 1u);
  ASSERT_EQ(one["executed"].size(), 1u);
  EXPECT_EQ(one["executed"][0]["plan"], "plan-2");
}

TEST(ExecutionTraceTest, NumbersFromOneAgainMeanARestartThatEndsWhatRan) {
  ExecutionTraces traces;
  traces.apply(event(1, 0, "started", "a.b == on() #0"));
  traces.apply(event(2, 5, "goal_achieved", "g1: a.b == on() #0"));
  traces.apply(event(1, 9, "resumed", "from the journal"));
  const ExecutiveTrace& t = traces.executives().at("executive/main");
  ASSERT_EQ(t.tokens.size(), 1u);
  EXPECT_TRUE(t.tokens[0].cut);
  EXPECT_EQ(t.tokens[0].end_ns, 5 * kSecond);  // the last time heard from the first run
  ASSERT_EQ(t.marks.size(), 3u);
  EXPECT_EQ(t.marks[1].kind, "restarted");
  EXPECT_EQ(t.marks[2].kind, "resumed");
  EXPECT_EQ(t.last_number, 1u);
}

TEST(ExecutionTraceTest, KeepsBoundedRecordsAndNeverDropsTheExecutingPlan) {
  ExecutionLimits limits;
  limits.tokens = 3;
  limits.plans = 2;
  ExecutionTraces traces(limits);
  for (uint64_t i = 0; i < 5; ++i)
    traces.apply(event(i + 1, static_cast<int64_t>(i), "started", "a.b == v() #" + std::to_string(i)));
  const ExecutiveTrace& t = traces.executives().at("executive/main");
  ASSERT_EQ(t.tokens.size(), 3u);
  EXPECT_EQ(t.tokens.front().token, 2);  // the oldest went first
  for (const std::string id : {"plan-1", "p2", "p3"}) {
    msg::LatestPlan p;
    p.requester = "executive/main";
    p.request_id = id;
    traces.apply(p);
  }
  EXPECT_EQ(t.plans.size(), 2u);
  EXPECT_EQ(t.plans.count("plan-1"), 1u);  // executing (the events' plan): kept
  EXPECT_EQ(t.plans.count("p3"), 1u);
}

}  // namespace
}  // namespace autonomy::viewer
