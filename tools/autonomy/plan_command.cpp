// autonomy plan MODEL PROBLEM: asks a running planner (services/planner) over DDS for a plan,
// prints each better plan as it comes, the reply's statistics and the plan, and writes the plan
// as JSON and as a Gantt SVG. --jobshop FILE reads an OR-Library instance here and sends the
// model and problem as protobuf messages instead. Ctrl-C cancels the request: the planner
// answers with the best plan so far. The offline tool without DDS is planner_tool.
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <variant>

#include "common/dds/reader.hpp"
#include "common/dds/topics.hpp"
#include "common/dds/writer.hpp"
#include "gantt_svg.hpp"
#include "jobshop_instance.hpp"
#include "plan_json.hpp"
#include "plan_message.hpp"
#include "planner_language.hpp"
#include "tools/autonomy/commands.hpp"

namespace autonomy::tools {

namespace {

struct PlanOptions {
  int domain = 0;
  std::string model, problem, jobshop;
  std::string engine;
  int64_t budget_ms = 0;
  int64_t max_decisions = 0;
  uint32_t seed = 0;
  std::string json, svg;
  std::string id, requester = "autonomy-cli";
  double timeout_s = 30.0;
  bool quiet = false;
};

std::vector<uint8_t> bytes_of(const google::protobuf::MessageLite& m) {
  const std::string s = m.SerializeAsString();
  return {s.begin(), s.end()};
}

std::string bound(int64_t v) {
  return v >= (int64_t{1} << 52) ? "inf" : v <= -(int64_t{1} << 52) ? "-inf" : std::to_string(v);
}

void print_plan(const msg::FlexiblePlan& plan) {
  for (const auto& tl : plan.timelines) {
    print_line(tl.name + ":");
    for (uint32_t i : tl.tokens) {
      if (i >= plan.tokens.size()) continue;
      const msg::PlanToken& t = plan.tokens[i];
      std::string params;
      for (const auto& p : t.parameters) params += (params.empty() ? "" : ", ") + p;
      print_line("  " + std::to_string(t.id) + " " + t.predicate + "(" + params + ") start [" +
                 bound(t.start_lb) + ", " + bound(t.start_ub) + "] end [" + bound(t.end_lb) + ", " +
                 bound(t.end_ub) + "] duration [" + bound(t.duration_lb) + ", " +
                 bound(t.duration_ub) + "]");
    }
  }
  for (const auto& g : plan.omitted_goals) print_line("omitted goal: " + g);
}

// What the reply says, in lines; the exit code.
int report(const msg::PlanningReply& r, const PlanOptions& o) {
  print_line(std::string("status: ") + msg::to_string(r.status) +
             (r.reason.empty() ? "" : " (" + r.reason + ")"));
  if (!r.detail.empty()) print_line("why: " + r.detail);
  for (const auto& d : r.diagnostics)
    print_line("  " + d.file + ":" + std::to_string(d.line) + ":" + std::to_string(d.column) +
               ": " + d.message);
  for (const auto& c : r.conflicts) print_line("  conflict: " + c);
  if (r.status == msg::PlanningStatus::Rejected) return kExitUsage;
  const auto& s = r.statistics;
  char line[512];
  std::snprintf(
      line, sizeof line,
      "engine %s: decisions %llu, backtracks %llu, dead ends %llu, temporal propagations %llu, "
      "procedure calls %llu, plans %u, %.1f ms",
      r.engine.c_str(), static_cast<unsigned long long>(s.decisions),
      static_cast<unsigned long long>(s.backtracks), static_cast<unsigned long long>(s.dead_ends),
      static_cast<unsigned long long>(s.temporal_propagations),
      static_cast<unsigned long long>(s.procedure_calls), s.improvements, s.elapsed_ms);
  print_line(line);
  if (!r.has_plan) return kExitFailed;
  print_line("makespan " + std::to_string(r.plan.makespan) +
             (r.status == msg::PlanningStatus::Optimal ? " (proved optimal)" : ""));
  for (const auto& v : r.violations) print_line("INVALID: " + v);
  if (!o.quiet) print_plan(r.plan);
  const planner::FlexiblePlan plan = planner::from_plan_message(r.plan);
  bool written = true;
  if (!o.json.empty()) {
    std::ofstream out(o.json);
    out << planner::plan_json(plan);
    if (!out) std::cerr << "autonomy plan: cannot write " << o.json << "\n";
    written = written && out.good();
  }
  if (!o.svg.empty()) {
    std::ofstream out(o.svg);
    out << planner::gantt_svg(plan);
    if (!out) std::cerr << "autonomy plan: cannot write " << o.svg << "\n";
    written = written && out.good();
  }
  return written && r.violations.empty() ? kExitOk : kExitFailed;
}

// The request from the files, or an exit code after saying what is wrong with them.
std::variant<msg::PlanningRequest, int> build_request(const PlanOptions& o) {
  msg::PlanningRequest q;
  planner::Diagnostics errors;
  if (!o.jobshop.empty()) {
    auto text = planner::read_text_file(o.jobshop, &errors);
    auto instance = text ? planner::parse_jobshop(*text, o.jobshop, &errors) : std::nullopt;
    if (!instance) {
      std::cerr << planner::to_string(errors);
      return kExitUsage;
    }
    q.model_protobuf = bytes_of(planner::jobshop_model(*instance));
    q.problem_protobuf = bytes_of(planner::jobshop_problem(*instance));
  } else {
    if (o.model.empty() || o.problem.empty()) {
      std::cerr << "autonomy plan: give MODEL and PROBLEM files, or --jobshop FILE\n";
      return kExitUsage;
    }
    auto model = planner::read_text_file(o.model, &errors);
    auto problem = planner::read_text_file(o.problem, &errors);
    if (!model || !problem) {
      std::cerr << planner::to_string(errors);
      return kExitUsage;
    }
    // Sent as text: the planner reports mistakes with these file names, lines and columns.
    q.model_file = o.model;
    q.model_text = std::move(*model);
    q.problem_file = o.problem;
    q.problem_text = std::move(*problem);
  }
  q.engine = o.engine;
  q.budget_ms = o.budget_ms;
  q.max_decisions = o.max_decisions;
  q.seed = o.seed;
  q.requester = o.requester;
  q.request_id =
      o.id.empty() ? "plan-" + std::to_string(getpid()) + "-" +
                         std::to_string(std::chrono::steady_clock::now().time_since_epoch().count())
                   : o.id;
  return q;
}

int plan(const PlanOptions& o, Context& ctx) {
  auto built = build_request(o);
  if (auto* code = std::get_if<int>(&built)) return *code;
  const msg::PlanningRequest& request = std::get<msg::PlanningRequest>(built);

  dds::Participant participant(o.domain);
  Interrupt interrupt(ctx.signals, participant);
  dds::Topic<msg::PlanningRequest> request_topic(participant, dds::topics::planner_request);
  dds::Topic<msg::PlanningReply> reply_topic(participant, dds::topics::planner_reply);
  dds::Topic<msg::PlanningProgress> progress_topic(participant, dds::topics::planner_progress);
  dds::Topic<msg::PlanningCancel> cancel_topic(participant, dds::topics::planner_cancel);
  dds::Reader<msg::PlanningReply> replies(participant, reply_topic);
  dds::Reader<msg::PlanningProgress> progress(participant, progress_topic);
  dds::Writer<msg::PlanningRequest> writer(participant, request_topic);
  dds::Writer<msg::PlanningCancel> cancel_writer(participant, cancel_topic);
  auto deadline = std::chrono::steady_clock::now() + seconds(o.timeout_s);
  // Requests are volatile: wait until the planner's reader and our reply reader are matched.
  while (writer.matched_readers() == 0 || replies.matched_writers() == 0 ||
         progress.matched_writers() == 0 || cancel_writer.matched_readers() == 0) {
    if (std::chrono::steady_clock::now() >= deadline) {
      std::cerr << "autonomy plan: no planner on domain " << o.domain << " within " << o.timeout_s
                << " s (is it running? autonomy node list)\n";
      return kExitFailed;
    }
    if (!sleep_for(interrupt, participant, std::chrono::milliseconds(10))) return kExitInterrupted;
  }
  writer.write(request);
  ResendSchedule resend(std::chrono::steady_clock::now());
  // The search may use its whole budget; the timeout counts from its end.
  deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(o.budget_ms) +
             seconds(o.timeout_s);
  dds::WaitSet waitset(participant);
  waitset.attach(replies.data_condition(), 1);
  waitset.attach(progress.data_condition(), 2);
  waitset.attach(interrupt.condition(), 3);
  bool cancelled = false;
  uint32_t improvements_seen = 0;
  std::optional<msg::PlanningReply> reply;
  // DDS orders samples per writer, not across topics: the reply may overtake the last progress
  // events, so after it the command waits a moment for the improvements it counts.
  std::chrono::steady_clock::time_point grace{};
  for (;;) {
    for (const auto& s : progress.take()) {
      if (!s.valid || s.value.request_id != request.request_id) continue;
      ++improvements_seen;
      char line[160];
      std::snprintf(line, sizeof line, "plan %u: makespan %lld at %.1f ms", s.value.improvement,
                    static_cast<long long>(s.value.makespan), s.value.elapsed_ms);
      print_line(line);
    }
    for (auto& s : replies.take()) {
      if (!s.valid || s.value.request_id != request.request_id || reply) continue;
      reply = std::move(s.value);
      grace = std::chrono::steady_clock::now() + std::chrono::milliseconds(500);
    }
    if (reply && (improvements_seen >= reply->statistics.improvements ||
                  std::chrono::steady_clock::now() >= grace)) {
      const int code = report(*reply, o);
      return cancelled && code == kExitOk ? kExitInterrupted : code;
    }
    if (interrupt.requested() && !cancelled) {
      // First Ctrl-C: ask for the best plan so far instead of leaving the search running.
      cancelled = true;
      waitset.detach(interrupt.condition());
      cancel_writer.write({request.request_id, request.requester});
      std::cerr << "autonomy plan: cancelling " << request.request_id << "\n";
      deadline = std::chrono::steady_clock::now() + seconds(o.timeout_s);
    }
    const auto now = std::chrono::steady_clock::now();
    const auto left = (reply ? grace : deadline) - now;
    if (!reply && left <= std::chrono::nanoseconds::zero()) {
      std::cerr << "autonomy plan: no reply to " << request.request_id << " in time\n";
      return kExitFailed;
    }
    if (!reply && resend.due(now)) {
      writer.write(request);
      resend.resent(now);
    }
    const auto until_resend = reply ? left : std::min(left, resend.next() - now);
    waitset.wait(std::max(until_resend, std::chrono::nanoseconds::zero()));
  }
}

}  // namespace

Command add_plan(CLI::App& app) {
  auto o = std::make_shared<PlanOptions>();
  auto* cmd =
      app.add_subcommand("plan", "Ask the planner service for a plan of a model and a problem");
  add_domain_option(cmd, o->domain);
  cmd->add_option("model", o->model, "Model file (planner language, docs/planner-language.md)");
  cmd->add_option("problem", o->problem, "Problem file (planner language)");
  cmd->add_option("--jobshop", o->jobshop,
                  "An OR-Library job-shop instance instead of MODEL and PROBLEM");
  cmd->add_option("--engine", o->engine,
                  "Search engine: chronological (default), discrepancy, sampling, repair, lns");
  cmd->add_option("--budget-ms", o->budget_ms, "Time budget, ms (0: the planner's default)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--max-decisions", o->max_decisions, "Decision budget (0: none)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--seed", o->seed, "Seed of the sampling, repair and lns engines");
  cmd->add_option("--json", o->json, "Write the plan as JSON here");
  cmd->add_option("--svg", o->svg, "Write a Gantt chart of the plan here");
  cmd->add_option("--id", o->id,
                  "Request id (default: a fresh one); resending an id gets the same reply")
      ->check(CLI::Validator(
          [](std::string& v) { return v.size() <= 128 ? "" : "at most 128 bytes"; }, "ID"));
  cmd->add_option("--requester", o->requester,
                  "Who asks: the key of its latest plan on autonomy/planner/plan")
      ->capture_default_str();
  cmd->add_option("-t,--timeout", o->timeout_s,
                  "Seconds to wait for the planner, and for the reply after the budget")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_flag("-q,--quiet", o->quiet, "Statistics and makespan only, no plan listing");
  cmd->footer(
      "Exit codes: 0 a valid plan; 1 no plan (infeasible, out of time without one), an invalid "
      "plan, no planner or "
      "no reply; 2 rejected request or unreadable files; 130 Ctrl-C (the request is cancelled; a "
      "best plan so far is "
      "still printed and written).");
  return {cmd, [o](Context& ctx) { return plan(*o, ctx); }};
}

}  // namespace autonomy::tools
