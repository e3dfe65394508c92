#include "planning_request.hpp"

#include <cstdlib>

#include "common/msg/text_limits.hpp"
#include "plan_message.hpp"
#include "plan_validator.hpp"
#include "planner_language.hpp"
#include "search_engine.hpp"

namespace autonomy::planner {

msg::PlanningReply rejected_reply(const msg::PlanningRequest& request, const std::string& reason,
                                  const std::string& detail) {
  msg::PlanningReply r;
  r.request_id = msg::clipped_id(request.request_id);
  r.requester = msg::clipped_id(request.requester, msg::kMaxNameLength);
  r.status = msg::PlanningStatus::Rejected;
  r.reason = reason;
  r.detail = detail;
  r.engine = msg::clipped_id(request.engine, msg::kMaxNameLength);
  r.plan_origin = request.plan_origin;
  return r;
}

std::optional<msg::PlanningReply> check_request(const msg::PlanningRequest& q,
                                                const RequestLimits& limits) {
  using msg::kMaxDocumentLength;
  using msg::kMaxIdLength;
  using msg::kMaxNameLength;
  using msg::kMaxTextLength;
  if (auto p = msg::first_length_problem({{"request_id", q.request_id, kMaxIdLength},
                                          {"requester", q.requester, kMaxNameLength},
                                          {"engine", q.engine, kMaxNameLength},
                                          {"model_file", q.model_file, kMaxTextLength},
                                          {"problem_file", q.problem_file, kMaxTextLength},
                                          {"model_text", q.model_text, kMaxDocumentLength},
                                          {"problem_text", q.problem_text, kMaxDocumentLength}}))
    return rejected_reply(q, "too_long", *p);
  for (const auto& [field, size] :
       {std::pair<const char*, std::size_t>{"model_protobuf", q.model_protobuf.size()},
        {"problem_protobuf", q.problem_protobuf.size()}})
    if (size > kMaxDocumentLength)
      return rejected_reply(q, "too_long",
                            std::string(field) + " has " + std::to_string(size) +
                                " bytes, more than " + std::to_string(kMaxDocumentLength));
  if (q.state.size() > 10000)
    return rejected_reply(
        q, "too_long", "state has " + std::to_string(q.state.size()) + " values, more than 10000");
  for (std::size_t i = 0; i < q.state.size(); ++i) {
    const auto& v = q.state[i];
    const std::string at = "state[" + std::to_string(i) + "].";
    if (auto p = msg::first_length_problem({{"timeline", v.timeline, kMaxNameLength * 2 + 1},
                                            {"predicate", v.predicate, kMaxNameLength}}))
      return rejected_reply(q, "too_long", at + *p);
    if (v.parameters.size() > 64)
      return rejected_reply(q, "too_long", at + "parameters: more than 64");
    for (const std::string& p : v.parameters)
      if (auto x = msg::length_problem("parameter", p, kMaxNameLength))
        return rejected_reply(q, "too_long", at + *x);
  }
  if (q.request_id.empty()) return rejected_reply(q, "missing_field", "request_id is empty");
  const bool model_text = !q.model_text.empty(), model_pb = !q.model_protobuf.empty();
  const bool problem_text = !q.problem_text.empty(), problem_pb = !q.problem_protobuf.empty();
  if (!model_text && !model_pb)
    return rejected_reply(q, "missing_field", "no model: give model_text or model_protobuf");
  if (model_text && model_pb)
    return rejected_reply(q, "ambiguous_model",
                          "both model_text and model_protobuf are given; send one");
  if (!problem_text && !problem_pb)
    return rejected_reply(q, "missing_field", "no problem: give problem_text or problem_protobuf");
  if (problem_text && problem_pb)
    return rejected_reply(q, "ambiguous_problem",
                          "both problem_text and problem_protobuf are given; send one");
  if (!q.engine.empty() && !make_search_engine(q.engine)) {
    std::string known;
    for (const std::string& n : search_engine_names()) known += (known.empty() ? "" : ", ") + n;
    return rejected_reply(q, "unknown_engine",
                          "unknown search engine '" + q.engine + "' (known: " + known + ")");
  }
  if (q.budget_ms < 0 || q.budget_ms > limits.max_budget_ms)
    return rejected_reply(q, "bad_budget",
                          "budget_ms " + std::to_string(q.budget_ms) + " is outside [0, " +
                              std::to_string(limits.max_budget_ms) +
                              "] (0: the service's default)");
  if (q.max_decisions < 0)
    return rejected_reply(q, "bad_budget",
                          "max_decisions " + std::to_string(q.max_decisions) + " is negative");
  return std::nullopt;
}

namespace {

void add_diagnostics(msg::PlanningReply& r, const Diagnostics& errors) {
  for (const Diagnostic& d : errors) r.diagnostics.push_back({d.file, d.line, d.column, d.message});
  if (!errors.empty() && r.detail.empty()) r.detail = errors.front().to_string();
  if (r.detail.size() > msg::kMaxTextLength)
    r.detail = msg::clipped_for_log(r.detail, msg::kMaxTextLength - 32);
}

// An executive's timeline value as the initial fact of its timeline (replacing the problem's).
// Arguments that read as numbers are numbers, the others names (enumeration values, objects).
bool fold_state(const msg::PlanningRequest& q, pb::Problem& problem, std::string* error) {
  for (std::size_t i = 0; i < q.state.size(); ++i) {
    const msg::PlannerTimelineValue& v = q.state[i];
    const auto dot = v.timeline.find('.');
    if (dot == std::string::npos || dot == 0 || dot + 1 == v.timeline.size() ||
        v.predicate.empty()) {
      *error = "state[" + std::to_string(i) + "]: timeline '" + v.timeline +
               "' is not object.attribute or its predicate is empty";
      return false;
    }
    const std::string object = v.timeline.substr(0, dot), attribute = v.timeline.substr(dot + 1);
    auto* initial = problem.mutable_initial();
    for (int k = initial->size() - 1; k >= 0; --k)
      if (initial->Get(k).object() == object && initial->Get(k).attribute() == attribute)
        initial->DeleteSubrange(k, 1);
    pb::Fact* f = problem.add_initial();
    f->set_object(object);
    f->set_attribute(attribute);
    f->set_predicate(v.predicate);
    f->mutable_location()->set_file("state");
    f->mutable_location()->set_line(static_cast<std::uint32_t>(i + 1));
    f->mutable_location()->set_column(1);
    for (const std::string& p : v.parameters) {
      pb::Argument* a = f->add_arguments();
      char* end = nullptr;
      const double x = std::strtod(p.c_str(), &end);
      if (!p.empty() && end && *end == '\0')
        a->set_number(x);
      else
        a->set_symbol(p);
    }
  }
  return true;
}

}  // namespace

std::variant<PreparedRun, msg::PlanningReply> prepare_run(const msg::PlanningRequest& q) {
  Diagnostics errors;
  std::optional<pb::Model> model_msg;
  std::optional<pb::Problem> problem_msg;
  if (!q.model_text.empty()) {
    model_msg = parse_model(q.model_text, q.model_file.empty() ? "model" : q.model_file, &errors);
  } else {
    pb::Model m;
    if (!m.ParseFromArray(q.model_protobuf.data(), static_cast<int>(q.model_protobuf.size())))
      return rejected_reply(q, "invalid_protobuf",
                            "model_protobuf is not a serialized autonomy.planner.pb.Model");
    model_msg = std::move(m);
  }
  if (!q.problem_text.empty()) {
    problem_msg =
        parse_problem(q.problem_text, q.problem_file.empty() ? "problem" : q.problem_file, &errors);
  } else {
    pb::Problem p;
    if (!p.ParseFromArray(q.problem_protobuf.data(), static_cast<int>(q.problem_protobuf.size())))
      return rejected_reply(q, "invalid_protobuf",
                            "problem_protobuf is not a serialized autonomy.planner.pb.Problem");
    problem_msg = std::move(p);
  }
  if (!model_msg || !problem_msg || !errors.empty()) {
    msg::PlanningReply r = rejected_reply(q, "parse_error", "");
    add_diagnostics(r, errors);
    return r;
  }
  std::string state_error;
  if (!fold_state(q, *problem_msg, &state_error))
    return rejected_reply(q, "invalid_state", state_error);
  std::optional<DomainModel> model = build_domain_model(*model_msg, &errors);
  if (!model) {
    msg::PlanningReply r = rejected_reply(q, "invalid_model", "");
    add_diagnostics(r, errors);
    return r;
  }
  std::optional<PlanningProblem> problem = build_problem(*model, *problem_msg, &errors);
  if (!problem) {
    msg::PlanningReply r =
        rejected_reply(q, q.state.empty() ? "invalid_problem" : "invalid_problem_or_state", "");
    add_diagnostics(r, errors);
    return r;
  }
  return PreparedRun{std::move(*model), std::move(*problem)};
}

std::vector<std::string> conflicting_statements(const std::string& explanation) {
  static const std::string kTemporal = "temporal conflict between: ";
  static const std::string kGoals = "search exhausted: no plan achieves together: ";
  std::size_t at = 0;
  if (explanation.rfind(kTemporal, 0) == 0)
    at = kTemporal.size();
  else if (explanation.rfind(kGoals, 0) == 0)
    at = kGoals.size();
  else
    return {explanation};
  std::vector<std::string> out;
  while (at <= explanation.size()) {
    const std::size_t next = explanation.find("; ", at);
    out.push_back(
        explanation.substr(at, next == std::string::npos ? std::string::npos : next - at));
    if (next == std::string::npos) break;
    at = next + 2;
  }
  return out;
}

msg::PlanningReply run_planning(const msg::PlanningRequest& q, const PreparedRun& run,
                                const RunControl& control) {
  PlanningOptions options;
  options.engine = q.engine.empty() ? "chronological" : q.engine;
  options.engine_options.seed = q.seed == 0 ? 1 : q.seed;
  if (q.max_decisions > 0)
    options.termination.max_decisions = static_cast<std::size_t>(q.max_decisions);
  options.termination.stop = [&] { return control.cancelled() || control.out_of_time(); };
  std::uint32_t improvements = 0;
  options.on_improvement = [&](const FlexiblePlan& p) {
    ++improvements;
    if (control.on_progress)
      control.on_progress({msg::clipped_id(q.request_id), improvements, p.makespan, p.penalty,
                           static_cast<std::uint32_t>(p.tokens.size()), control.elapsed_ms()});
  };
  const PlanResult result = make_plan(run.model, run.problem, options);

  msg::PlanningReply r;
  r.request_id = q.request_id;
  r.requester = q.requester;
  r.engine = options.engine;
  r.plan_origin = q.plan_origin;
  const bool cancelled = control.cancelled();
  const bool optimising = run.problem.objective == pb::Problem::MAKESPAN;
  switch (result.status) {
    case PlanStatus::kOptimal:
      r.status = msg::PlanningStatus::Optimal;
      break;
    case PlanStatus::kPlanFound:
      // With a makespan to minimise, a plan without the proof means the budget ended first.
      r.status = !optimising ? msg::PlanningStatus::PlanFound
                 : cancelled ? msg::PlanningStatus::Cancelled
                             : msg::PlanningStatus::OutOfTime;
      break;
    case PlanStatus::kInfeasible:
      r.status = msg::PlanningStatus::Infeasible;
      r.conflicts = conflicting_statements(result.explanation);
      break;
    case PlanStatus::kOutOfBudget:
      r.status = cancelled ? msg::PlanningStatus::Cancelled : msg::PlanningStatus::OutOfTime;
      break;
    case PlanStatus::kInvalidRequest:
      r.status = msg::PlanningStatus::Rejected;
      r.reason = "unknown_engine";
      break;
  }
  r.detail = result.explanation;
  // Ended inside propagation: say what ended it and where.
  if (result.status == PlanStatus::kOutOfBudget && !r.detail.empty())
    r.detail = (cancelled ? "cancelled: " : "the time budget ended: ") + r.detail;
  if (r.status == msg::PlanningStatus::OutOfTime && r.detail.empty())
    r.detail = control.out_of_time() ? "the time budget ended"
               : q.max_decisions > 0 &&
                       result.statistics.decisions >= static_cast<std::size_t>(q.max_decisions)
                   ? "the decision budget ended"
                   : "the engine gave up before a proof (" + options.engine + " is incomplete)";
  if (r.status == msg::PlanningStatus::Cancelled && r.detail.empty()) r.detail = "cancelled";
  if (result.plan) {
    r.has_plan = true;
    r.plan = to_plan_message(*result.plan);
    r.violations = validate_plan(run.model, run.problem, *result.plan);
  }
  const SearchStatistics& s = result.statistics;
  r.statistics = {s.decisions,         s.backtracks,
                  s.dead_ends,         s.temporal_propagations,
                  s.procedure_calls,   static_cast<std::uint32_t>(result.improvements),
                  control.elapsed_ms()};
  return r;
}

}  // namespace autonomy::planner
