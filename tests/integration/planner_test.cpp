// The planner service over DDS: the real `planner` process, requests from this test (another
// process) and from the `autonomy plan` CLI, over Cyclone DDS on loopback. Every plan that comes
// back goes through the plan validator here, on the test's own parse of the model and problem.
//
// One DDS domain per test (ctest runs them in parallel); this file uses 170-178 only:
//
//   domain  test
//   ------  -----------------------------------------------------------------
//    170    PlannerTest.ARequestFromAnotherProcessGetsAValidPlan
//    171    PlannerTest.AnInfeasibleProblemIsAnsweredWithItsConflict
//    172    PlannerTest.BadRequestsGetReasonsAndTheNextGoodOneIsServed
//    173    PlannerTest.CancellingALongSearchEndsItWithTheBestPlanSoFar
//    174    PlannerTest.AnExhaustedBudgetIsAnsweredOutOfTimeWithTheBestPlanSoFar
//    175    PlannerTest.ALateJoiningReaderGetsTheLatestPlan
//    176    PlannerTest.TheCliPlansFilesAndJobShops
//    177    PlannerTest.AModelThatPropagatesForeverHoldsUpNoOtherClient
//    178    PlannerTest.ARequestWaitingBehindAnotherIsAnsweredAtItsOwnDeadline
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "jobshop_instance.hpp"
#include "plan_message.hpp"
#include "plan_validator.hpp"
#include "planning_request.hpp"
#include "tests/support/process_test.hpp"

namespace autonomy::test {
namespace {

using namespace std::chrono_literals;

const std::string kExamples = std::string(AUTONOMY_SOURCE_DIR) + "/services/planner/examples";

msg::PlanningRequest camera_request(const std::string& id) {
  msg::PlanningRequest q;
  q.request_id = id;
  q.requester = "test";
  q.model_file = "camera.model";
  q.model_text = read_file(kExamples + "/camera.model");
  q.problem_file = "camera.problem";
  q.problem_text = read_file(kExamples + "/camera.problem");
  return q;
}

std::vector<uint8_t> bytes_of(const google::protobuf::MessageLite& m) {
  const std::string s = m.SerializeAsString();
  return {s.begin(), s.end()};
}

// A job-shop instance sent as protobuf messages (the path a program or GUI takes).
msg::PlanningRequest jobshop_request(const std::string& id, const std::string& instance) {
  planner::Diagnostics errors;
  const std::string file = kExamples + "/jobshop/" + instance;
  auto parsed = planner::parse_jobshop(read_file(file), file, &errors);
  EXPECT_TRUE(parsed) << planner::to_string(errors);
  msg::PlanningRequest q;
  q.request_id = id;
  q.requester = "test";
  if (!parsed) return q;
  q.model_protobuf = bytes_of(planner::jobshop_model(*parsed));
  q.problem_protobuf = bytes_of(planner::jobshop_problem(*parsed));
  return q;
}

// The validator's findings on a reply's plan, checked against the request's own model and
// problem (parsed here, in the test), after the plan's trip through DDS and back.
std::vector<std::string> violations_of(const msg::PlanningRequest& q, const msg::PlanningReply& r) {
  auto prepared = planner::prepare_run(q);
  if (const auto* rejected = std::get_if<msg::PlanningReply>(&prepared))
    return {"not parsed: " + rejected->detail};
  const auto& run = std::get<planner::PreparedRun>(prepared);
  return planner::validate_plan(run.model, run.problem, planner::from_plan_message(r.plan));
}

class PlannerTest : public ProcessTest {
 protected:
  void start_planner(int domain, std::vector<std::string> args = {}) {
    join(domain);
    beats_.emplace(participant(), dds::topics::heartbeat);
    replies_.emplace(participant(), dds::topics::planner_reply);
    progress_.emplace(participant(), dds::topics::planner_progress);
    request_topic_.emplace(participant(), dds::topics::planner_request);
    request_writer_.emplace(participant(), *request_topic_);
    cancel_topic_.emplace(participant(), dds::topics::planner_cancel);
    cancel_writer_.emplace(participant(), *cancel_topic_);
    args.insert(args.end(), {"--domain", std::to_string(domain), "--log-dir", dir().path()});
    planner_ = &start("planner", AUTONOMY_PLANNER_BIN, args);
    ASSERT_TRUE(await_ready(*beats_, *planner_));
    // Replies and progress are volatile: the test's readers must be matched before they come.
    ASSERT_TRUE(await("the planner's endpoints matched", [&] {
      return request_writer_->matched_readers() > 0 && cancel_writer_->matched_readers() > 0 &&
             replies_->reader().matched_writers() > 0 && progress_->reader().matched_writers() > 0;
    }));
  }
  void send(const msg::PlanningRequest& q) { request_writer_->write(q); }
  void cancel(const std::string& id) { cancel_writer_->write({id, "test"}); }
  std::vector<msg::PlanningReply> replies_to(const std::string& id) {
    return replies_->matching([&](const msg::PlanningReply& r) { return r.request_id == id; });
  }
  // The first reply to `id` (waits for it).
  msg::PlanningReply reply_to(const std::string& id,
                              std::chrono::milliseconds timeout = kDeadline) {
    const bool got = await(
        "the reply to " + id,
        [&] {
          replies_->poll();
          return !replies_to(id).empty();
        },
        timeout);
    EXPECT_TRUE(got) << "no reply to " << id;
    return got ? replies_to(id).front() : msg::PlanningReply{};
  }

  ChildProcess* planner_ = nullptr;
  std::optional<Recorder<msg::Heartbeat>> beats_;
  std::optional<Recorder<msg::PlanningReply>> replies_;
  std::optional<Recorder<msg::PlanningProgress>> progress_;
  std::optional<dds::Topic<msg::PlanningRequest>> request_topic_;
  std::optional<dds::Writer<msg::PlanningRequest>> request_writer_;
  std::optional<dds::Topic<msg::PlanningCancel>> cancel_topic_;
  std::optional<dds::Writer<msg::PlanningCancel>> cancel_writer_;
};

TEST_F(PlannerTest, ARequestFromAnotherProcessGetsAValidPlan) {
  start_planner(170);
  const msg::PlanningRequest camera = camera_request("camera-1");
  send(camera);
  const msg::PlanningReply r = reply_to("camera-1");
  ASSERT_EQ(r.status, msg::PlanningStatus::PlanFound) << r.reason << ": " << r.detail;
  ASSERT_TRUE(r.has_plan);
  EXPECT_TRUE(r.violations.empty()) << r.violations.front();
  EXPECT_TRUE(violations_of(camera, r).empty()) << violations_of(camera, r).front();
  EXPECT_EQ(r.requester, "test");
  EXPECT_EQ(r.engine, "chronological");
  EXPECT_GT(r.statistics.decisions, 0u);
  // The paper's picture: turn to the asteroid, picture it inside the pointing, camera ready around.
  std::vector<std::string> predicates;
  for (const auto& t : r.plan.tokens) predicates.push_back(t.predicate);
  EXPECT_NE(std::find(predicates.begin(), predicates.end(), "picture"), predicates.end());
  EXPECT_NE(std::find(predicates.begin(), predicates.end(), "turning"), predicates.end());
  EXPECT_FALSE(r.plan.constraints.empty());

  // The same over the protobuf path, with an objective: ft06 is planned to its proved optimum.
  const msg::PlanningRequest ft06 = jobshop_request("ft06-1", "ft06");
  send(ft06);
  const msg::PlanningReply j = reply_to("ft06-1");
  ASSERT_EQ(j.status, msg::PlanningStatus::Optimal) << j.reason << ": " << j.detail;
  EXPECT_EQ(j.plan.makespan, 55);
  EXPECT_TRUE(violations_of(ft06, j).empty()) << violations_of(ft06, j).front();
  // Each better plan was published on the way, the last one being the optimum.
  ASSERT_TRUE(await("ft06's progress events", [&] {
    progress_->poll();
    return progress_
               ->matching([](const msg::PlanningProgress& p) { return p.request_id == "ft06-1"; })
               .size() == j.statistics.improvements;
  }));
  const auto steps =
      progress_->matching([](const msg::PlanningProgress& p) { return p.request_id == "ft06-1"; });
  ASSERT_FALSE(steps.empty());
  for (std::size_t i = 1; i < steps.size(); ++i) {
    EXPECT_EQ(steps[i].improvement, steps[i - 1].improvement + 1);
    EXPECT_LT(steps[i].makespan, steps[i - 1].makespan);
  }
  EXPECT_EQ(steps.back().makespan, 55);
}

TEST_F(PlannerTest, AnInfeasibleProblemIsAnsweredWithItsConflict) {
  start_planner(171);
  msg::PlanningRequest q = camera_request("tight-1");
  q.problem_file = "tight.problem";
  q.problem_text =
      "problem tight\nhorizon 100\nobject s : Spacecraft\n"
      "goal g: s.camera == picture(comet) start [10, 20] end [0, 12]\n";
  send(q);
  const msg::PlanningReply r = reply_to("tight-1");
  ASSERT_EQ(r.status, msg::PlanningStatus::Infeasible) << r.reason << ": " << r.detail;
  EXPECT_FALSE(r.has_plan);
  ASSERT_FALSE(r.conflicts.empty());
  bool names_goal = false;
  for (const auto& c : r.conflicts) names_goal |= c.find("tight.problem:4") != std::string::npos;
  EXPECT_TRUE(names_goal) << r.detail;
  EXPECT_TRUE(planner_->running());
}

TEST_F(PlannerTest, BadRequestsGetReasonsAndTheNextGoodOneIsServed) {
  start_planner(172);
  msg::PlanningRequest engine = camera_request("bad-engine");
  engine.engine = "simulated-annealing";
  msg::PlanningRequest syntax = camera_request("bad-syntax");
  syntax.model_file = "broken.model";
  syntax.model_text = "model broken\npredicate p() duration [5 1]\n";
  msg::PlanningRequest long_id = camera_request(std::string(300, 'q'));
  msg::PlanningRequest no_problem = camera_request("no-problem");
  no_problem.problem_text.clear();
  msg::PlanningRequest garbage = jobshop_request("bad-protobuf", "ft06");
  garbage.model_protobuf = {0xff, 0xff, 0xff, 0xff};
  msg::PlanningRequest huge = camera_request("huge");
  huge.model_text.append(std::size_t{1} << 21, ' ');
  for (const auto* q : {&engine, &syntax, &long_id, &no_problem, &garbage, &huge}) send(*q);
  const std::string clipped(128, 'q');
  EXPECT_EQ(reply_to("bad-engine").reason, "unknown_engine");
  const msg::PlanningReply s = reply_to("bad-syntax");
  EXPECT_EQ(s.status, msg::PlanningStatus::Rejected);
  EXPECT_EQ(s.reason, "parse_error");
  ASSERT_FALSE(s.diagnostics.empty());
  EXPECT_EQ(s.diagnostics[0].file, "broken.model");
  EXPECT_EQ(s.diagnostics[0].line, 2u);
  EXPECT_EQ(s.diagnostics[0].column, 27u);  // the 1 where a comma belongs
  EXPECT_EQ(reply_to(clipped).reason, "too_long");
  EXPECT_EQ(reply_to("no-problem").reason, "missing_field");
  EXPECT_EQ(reply_to("bad-protobuf").reason, "invalid_protobuf");
  const msg::PlanningReply h = reply_to("huge");
  EXPECT_EQ(h.reason, "too_long");
  EXPECT_NE(h.detail.find("model_text"), std::string::npos) << h.detail;

  // The service goes on: a good request is planned, and a repeat of its id gets the same reply
  // again without planning anew.
  const msg::PlanningRequest good = camera_request("good-1");
  send(good);
  const msg::PlanningReply g = reply_to("good-1");
  ASSERT_EQ(g.status, msg::PlanningStatus::PlanFound) << g.reason << ": " << g.detail;
  EXPECT_TRUE(violations_of(good, g).empty());
  msg::PlanningRequest again = camera_request("good-1");
  again.problem_text = "this is not read again";
  send(again);
  send(engine);
  ASSERT_TRUE(await("the repeated replies", [&] {
    replies_->poll();
    return replies_to("good-1").size() == 2 && replies_to("bad-engine").size() == 2;
  }));
  const msg::PlanningReply g2 = replies_to("good-1")[1];
  EXPECT_EQ(g2.status, g.status);
  EXPECT_EQ(g2.plan.tokens.size(), g.plan.tokens.size());
  EXPECT_EQ(g2.statistics.decisions, g.statistics.decisions);
  EXPECT_EQ(g2.statistics.elapsed_ms,
            g.statistics.elapsed_ms);  // the remembered reply, not a new run
  EXPECT_EQ(replies_to("bad-engine")[1].reason, "unknown_engine");
  EXPECT_TRUE(planner_->running());
}

TEST_F(PlannerTest, CancellingALongSearchEndsItWithTheBestPlanSoFar) {
  start_planner(173, {"--workers", "1"});  // one search at a time: the others queue
  // la01 is not proved optimal within minutes: it runs until cancelled.
  msg::PlanningRequest la01 = jobshop_request("la01", "la01");
  la01.budget_ms = 600000;
  send(la01);
  ASSERT_TRUE(await("a first plan of la01", [&] {
    progress_->poll();
    return !progress_
                ->matching([](const msg::PlanningProgress& p) { return p.request_id == "la01"; })
                .empty();
  }));
  // Two more wait their turn behind it; the second is cancelled before it starts.
  const msg::PlanningRequest camera = camera_request("camera-queued");
  send(camera);
  send(jobshop_request("la02-queued", "la02"));
  ASSERT_TRUE(await("the planner took both", [&] {
    return read_file(dir().file("planner-main.log")).find("la02-queued from test") !=
           std::string::npos;
  }));
  cancel("la02-queued");
  const msg::PlanningReply q = reply_to("la02-queued");
  EXPECT_EQ(q.status, msg::PlanningStatus::Cancelled);
  EXPECT_FALSE(q.has_plan);
  EXPECT_TRUE(replies_to("la01").empty());  // still searching
  cancel("la01");
  const msg::PlanningReply r = reply_to("la01");
  ASSERT_EQ(r.status, msg::PlanningStatus::Cancelled) << r.reason << ": " << r.detail;
  ASSERT_TRUE(r.has_plan);
  EXPECT_GE(r.plan.makespan, 666);  // la01's optimum
  EXPECT_TRUE(violations_of(la01, r).empty()) << violations_of(la01, r).front();
  EXPECT_GE(r.statistics.improvements, 1u);
  // The queued request is served next.
  const msg::PlanningReply c = reply_to("camera-queued");
  EXPECT_EQ(c.status, msg::PlanningStatus::PlanFound) << c.reason << ": " << c.detail;
  EXPECT_TRUE(violations_of(camera, c).empty());
}

TEST_F(PlannerTest, AnExhaustedBudgetIsAnsweredOutOfTimeWithTheBestPlanSoFar) {
  start_planner(174);
  // A decision budget (deterministic, unlike a time budget) ends la01's search long before the
  // proof.
  msg::PlanningRequest la01 = jobshop_request("la01-budget", "la01");
  la01.max_decisions = 5000;
  // The service's largest time budget, so that only the decisions can end it: under ASan on a
  // loaded machine 5,000 decisions took more than the default 10 s (3,749 done when it ended).
  la01.budget_ms = 600000;
  send(la01);
  const msg::PlanningReply r = reply_to("la01-budget");
  ASSERT_EQ(r.status, msg::PlanningStatus::OutOfTime) << r.reason << ": " << r.detail;
  EXPECT_EQ(r.detail, "the decision budget ended");
  ASSERT_TRUE(r.has_plan);
  EXPECT_GE(r.plan.makespan, 666);
  EXPECT_LE(r.statistics.decisions, 5000u);
  EXPECT_TRUE(violations_of(la01, r).empty()) << violations_of(la01, r).front();
}

TEST_F(PlannerTest, ALateJoiningReaderGetsTheLatestPlan) {
  start_planner(175);
  msg::PlanningRequest first = jobshop_request("exec-1", "ft06");
  first.requester = "executive/ds1";
  first.plan_origin = 1000;
  send(first);
  ASSERT_EQ(reply_to("exec-1").status, msg::PlanningStatus::Optimal);
  msg::PlanningRequest second = camera_request("exec-2");
  second.requester = "executive/ds1";
  second.plan_origin = 2000;
  send(second);
  const msg::PlanningReply r = reply_to("exec-2");
  ASSERT_EQ(r.status, msg::PlanningStatus::PlanFound);
  // A participant that joins now (an executive started late) gets the latest plan of its
  // requester from the planner's transient-local history.
  dds::Participant late(domain_);
  Recorder<msg::LatestPlan> plans(late, dds::topics::planner_plan);
  ASSERT_TRUE(await("the latest plan of executive/ds1", [&] {
    plans.poll();
    return !plans.matching([](const msg::LatestPlan& p) { return p.requester == "executive/ds1"; })
                .empty();
  }));
  const auto seen =
      plans.matching([](const msg::LatestPlan& p) { return p.requester == "executive/ds1"; });
  ASSERT_EQ(seen.size(), 1u);  // keep-last 1 per requester: only the newest
  EXPECT_EQ(seen[0].request_id, "exec-2");
  EXPECT_EQ(seen[0].plan_origin, 2000);
  EXPECT_EQ(seen[0].status, msg::PlanningStatus::PlanFound);
  EXPECT_EQ(seen[0].plan.tokens.size(), r.plan.tokens.size());
  msg::PlanningReply as_reply;
  as_reply.plan = seen[0].plan;
  EXPECT_TRUE(violations_of(second, as_reply).empty());
}

TEST_F(PlannerTest, TheCliPlansFilesAndJobShops) {
  start_planner(176);
  const auto cli = [&](const std::string& name, std::vector<std::string> args) {
    args.insert(args.end(), {"--domain", std::to_string(domain_)});
    ChildProcess& p = start(name, AUTONOMY_AUTONOMY_BIN, args, false);
    const auto status = p.wait_for_exit(60s);
    EXPECT_TRUE(status) << name << " did not end";
    return std::make_pair(status ? (status->exited ? status->code : 128 + status->signal) : -1,
                          read_file(p.log_file()));
  };
  const std::string json = dir().file("camera.json"), svg = dir().file("camera.svg");
  const auto [code, out] =
      cli("plan-camera", {"plan", kExamples + "/camera.model", kExamples + "/camera.problem",
                          "--json", json, "--svg", svg});
  EXPECT_EQ(code, 0) << out;
  EXPECT_NE(out.find("status: plan_found"), std::string::npos) << out;
  EXPECT_NE(out.find("decisions"), std::string::npos) << out;
  EXPECT_NE(out.find("picture(asteroid)"), std::string::npos) << out;
  const auto plan = nlohmann::json::parse(read_file(json), nullptr, false);
  ASSERT_FALSE(plan.is_discarded()) << read_file(json);
  EXPECT_GE(plan["tokens"].size(), 5u);
  EXPECT_EQ(read_file(svg).rfind("<svg", 0), 0u);

  const auto [jcode, jout] =
      cli("plan-ft06", {"plan", "--jobshop", kExamples + "/jobshop/ft06", "-q"});
  EXPECT_EQ(jcode, 0) << jout;
  EXPECT_NE(jout.find("makespan 55 (proved optimal)"), std::string::npos) << jout;
  EXPECT_NE(jout.find("plan 1: makespan"), std::string::npos) << jout;  // progress as it came

  const std::string bad = dir().file("bad.model");
  write_file(bad, "model bad\npredicate p() duration [5 1]\n");
  const auto [bcode, bout] = cli("plan-bad", {"plan", bad, kExamples + "/camera.problem"});
  EXPECT_EQ(bcode, 2) << bout;
  EXPECT_NE(bout.find("status: rejected (parse_error)"), std::string::npos) << bout;
  EXPECT_NE(bout.find(bad + ":2:27:"), std::string::npos) << bout;
}

// A model whose parameter propagation steps through a range of 10^12 without a cycle of
// differences (issue 29): only the budget ends it.
msg::PlanningRequest endless_request(const std::string& id, std::int64_t budget_ms) {
  msg::PlanningRequest q;
  q.request_id = id;
  q.requester = "test";
  q.model_file = "endless.model";
  q.model_text =
      "model endless\npredicate p(a: int[1, 1000000000000], b: int[0, 1000000000000],"
      " c: int[0, 1000000000000]) where a + 1 * b == c, c < b\n"
      "class C { attribute x = p }\n";
  q.problem_file = "endless.problem";
  q.problem_text = "problem one\nhorizon 100\nobject o : C\ngoal o.x == p(_, _, _)\n";
  q.budget_ms = budget_ms;
  return q;
}

TEST_F(PlannerTest, AModelThatPropagatesForeverHoldsUpNoOtherClient) {
  start_planner(177);  // two workers (the default)
  send(endless_request("endless-long", 60000));
  ASSERT_TRUE(await("the planner took it", [&] {
    return read_file(dir().file("planner-main.log")).find("endless-long from test") !=
           std::string::npos;
  }));
  // Another client (the CLI, its own process) with an ordinary request and a short budget: had
  // it waited behind the endless one, its budget would have ended in the queue.
  ChildProcess& cli = start("plan-camera", AUTONOMY_AUTONOMY_BIN,
                            {"plan", kExamples + "/camera.model", kExamples + "/camera.problem",
                             "--budget-ms", "3000", "--domain", std::to_string(domain_)},
                            false);
  const auto status = cli.wait_for_exit(60s);
  ASSERT_TRUE(status && status->exited) << read_file(cli.log_file());
  EXPECT_EQ(status->code, 0) << read_file(cli.log_file());
  EXPECT_NE(read_file(cli.log_file()).find("status: plan_found"), std::string::npos)
      << read_file(cli.log_file());
  replies_->poll();
  EXPECT_TRUE(replies_to("endless-long").empty());  // still propagating
  cancel("endless-long");
  const msg::PlanningReply c = reply_to("endless-long");
  EXPECT_EQ(c.status, msg::PlanningStatus::Cancelled);
  EXPECT_EQ(c.detail, "cancelled: stopped during parameter propagation (the problem's parameters)");

  // The budget ends the propagation: answered out_of_time, saying where it stopped.
  send(endless_request("endless", 1000));
  const msg::PlanningReply r = reply_to("endless");
  EXPECT_EQ(r.status, msg::PlanningStatus::OutOfTime) << r.reason << ": " << r.detail;
  EXPECT_EQ(r.detail,
            "the time budget ended: stopped during parameter propagation (the problem's "
            "parameters)");
  EXPECT_FALSE(r.has_plan);
  EXPECT_GE(r.statistics.elapsed_ms, 1000);
}

TEST_F(PlannerTest, ARequestWaitingBehindAnotherIsAnsweredAtItsOwnDeadline) {
  start_planner(178, {"--workers", "1"});
  send(endless_request("endless", 4000));
  ASSERT_TRUE(await("the planner took it", [&] {
    return read_file(dir().file("planner-main.log")).find("endless from test") !=
           std::string::npos;
  }));
  msg::PlanningRequest camera = camera_request("camera-waits");
  camera.budget_ms = 500;
  send(camera);
  const msg::PlanningReply w = reply_to("camera-waits");
  EXPECT_EQ(w.status, msg::PlanningStatus::OutOfTime) << w.reason << ": " << w.detail;
  EXPECT_NE(w.detail.find("waited for a worker"), std::string::npos) << w.detail;
  EXPECT_FALSE(w.has_plan);
  EXPECT_TRUE(replies_to("endless").empty());  // answered before the one it waited behind
  const msg::PlanningReply r = reply_to("endless");
  EXPECT_EQ(r.status, msg::PlanningStatus::OutOfTime) << r.reason << ": " << r.detail;
  // The worker is free again: the next request is planned.
  send(camera_request("camera-next"));
  EXPECT_EQ(reply_to("camera-next").status, msg::PlanningStatus::PlanFound);
}

}  // namespace
}  // namespace autonomy::test
