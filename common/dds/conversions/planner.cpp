#include "common/dds/message_types.hpp"

namespace autonomy::dds {

namespace {

template <typename CSeq, typename V>
CSeq to_c_numbers(const std::vector<V>& v, Arena& arena) {
  const uint32_t n = static_cast<uint32_t>(v.size());
  using E = std::remove_pointer_t<decltype(CSeq{}._buffer)>;
  auto* buf = arena.allocate<E>(n);
  for (uint32_t i = 0; i < n; ++i) buf[i] = static_cast<E>(v[i]);
  return {n, n, buf, false};
}

template <typename V, typename CSeq>
std::vector<V> from_c_numbers(const CSeq& s) {
  return std::vector<V>(s._buffer, s._buffer + s._length);
}

void plan_to_c(const msg::FlexiblePlan& v, autonomy_FlexiblePlan& out, Arena& arena) {
  out.horizon = v.horizon;
  out.makespan = v.makespan;
  out.penalty = v.penalty;
  out.omitted_goals = to_c_strings(v.omitted_goals, arena);
  {
    const uint32_t n = static_cast<uint32_t>(v.timelines.size());
    auto* buf = arena.allocate<autonomy_PlanTimeline>(n);
    for (uint32_t i = 0; i < n; ++i) {
      buf[i].name = c_str(v.timelines[i].name);
      buf[i].tokens = to_c_numbers<dds_sequence_uint32>(v.timelines[i].tokens, arena);
    }
    out.timelines = {n, n, buf, false};
  }
  {
    const uint32_t n = static_cast<uint32_t>(v.tokens.size());
    auto* buf = arena.allocate<autonomy_PlanToken>(n);
    for (uint32_t i = 0; i < n; ++i) {
      const msg::PlanToken& t = v.tokens[i];
      autonomy_PlanToken& c = buf[i];
      c.id = t.id;
      c.object = c_str(t.object);
      c.attribute = c_str(t.attribute);
      c.predicate = c_str(t.predicate);
      c.parameters = to_c_strings(t.parameters, arena);
      c.parameter_lo = to_c_numbers<dds_sequence_double>(t.parameter_lo, arena);
      c.parameter_hi = to_c_numbers<dds_sequence_double>(t.parameter_hi, arena);
      c.start_lb = t.start_lb;
      c.start_ub = t.start_ub;
      c.end_lb = t.end_lb;
      c.end_ub = t.end_ub;
      c.duration_lb = t.duration_lb;
      c.duration_ub = t.duration_ub;
      c.origin = c_str(t.origin);
      c.fact = t.fact;
    }
    out.tokens = {n, n, buf, false};
  }
  {
    const uint32_t n = static_cast<uint32_t>(v.constraints.size());
    auto* buf = arena.allocate<autonomy_PlanConstraint>(n);
    for (uint32_t i = 0; i < n; ++i) {
      const msg::PlanConstraint& k = v.constraints[i];
      buf[i] = {c_str(k.from), c_str(k.to), k.lb, k.ub};
    }
    out.constraints = {n, n, buf, false};
  }
}

msg::FlexiblePlan plan_from_c(const autonomy_FlexiblePlan& in) {
  msg::FlexiblePlan v;
  v.horizon = in.horizon;
  v.makespan = in.makespan;
  v.penalty = in.penalty;
  v.omitted_goals = from_c_strings(in.omitted_goals);
  for (uint32_t i = 0; i < in.timelines._length; ++i) {
    const auto& t = in.timelines._buffer[i];
    v.timelines.push_back({from_c_str(t.name), from_c_numbers<uint32_t>(t.tokens)});
  }
  for (uint32_t i = 0; i < in.tokens._length; ++i) {
    const auto& c = in.tokens._buffer[i];
    msg::PlanToken t;
    t.id = c.id;
    t.object = from_c_str(c.object);
    t.attribute = from_c_str(c.attribute);
    t.predicate = from_c_str(c.predicate);
    t.parameters = from_c_strings(c.parameters);
    t.parameter_lo = from_c_numbers<double>(c.parameter_lo);
    t.parameter_hi = from_c_numbers<double>(c.parameter_hi);
    t.start_lb = c.start_lb;
    t.start_ub = c.start_ub;
    t.end_lb = c.end_lb;
    t.end_ub = c.end_ub;
    t.duration_lb = c.duration_lb;
    t.duration_ub = c.duration_ub;
    t.origin = from_c_str(c.origin);
    t.fact = c.fact;
    v.tokens.push_back(std::move(t));
  }
  for (uint32_t i = 0; i < in.constraints._length; ++i) {
    const auto& c = in.constraints._buffer[i];
    v.constraints.push_back({from_c_str(c.from), from_c_str(c.to), c.lb, c.ub});
  }
  return v;
}

}  // namespace

void DdsType<msg::PlanningRequest>::to_c(const msg::PlanningRequest& v, C& out, Arena& arena) {
  out.request_id = c_str(v.request_id);
  out.requester = c_str(v.requester);
  out.model_file = c_str(v.model_file);
  out.model_text = c_str(v.model_text);
  out.model_protobuf = to_c_numbers<dds_sequence_octet>(v.model_protobuf, arena);
  out.problem_file = c_str(v.problem_file);
  out.problem_text = c_str(v.problem_text);
  out.problem_protobuf = to_c_numbers<dds_sequence_octet>(v.problem_protobuf, arena);
  const uint32_t n = static_cast<uint32_t>(v.state.size());
  auto* state = arena.allocate<autonomy_PlannerTimelineValue>(n);
  for (uint32_t i = 0; i < n; ++i)
    state[i] = {c_str(v.state[i].timeline), c_str(v.state[i].predicate),
                to_c_strings(v.state[i].parameters, arena)};
  out.state = {n, n, state, false};
  out.plan_origin = v.plan_origin;
  out.engine = c_str(v.engine);
  out.seed = v.seed;
  out.budget_ms = v.budget_ms;
  out.max_decisions = v.max_decisions;
}

msg::PlanningRequest DdsType<msg::PlanningRequest>::from_c(const C& in) {
  msg::PlanningRequest v;
  v.request_id = from_c_str(in.request_id);
  v.requester = from_c_str(in.requester);
  v.model_file = from_c_str(in.model_file);
  v.model_text = from_c_str(in.model_text);
  v.model_protobuf = from_c_numbers<uint8_t>(in.model_protobuf);
  v.problem_file = from_c_str(in.problem_file);
  v.problem_text = from_c_str(in.problem_text);
  v.problem_protobuf = from_c_numbers<uint8_t>(in.problem_protobuf);
  for (uint32_t i = 0; i < in.state._length; ++i) {
    const auto& s = in.state._buffer[i];
    v.state.push_back(
        {from_c_str(s.timeline), from_c_str(s.predicate), from_c_strings(s.parameters)});
  }
  v.plan_origin = in.plan_origin;
  v.engine = from_c_str(in.engine);
  v.seed = in.seed;
  v.budget_ms = in.budget_ms;
  v.max_decisions = in.max_decisions;
  return v;
}

void DdsType<msg::PlanningReply>::to_c(const msg::PlanningReply& v, C& out, Arena& arena) {
  out.request_id = c_str(v.request_id);
  out.requester = c_str(v.requester);
  out.status = static_cast<autonomy_PlanningStatus>(v.status);
  out.reason = c_str(v.reason);
  out.detail = c_str(v.detail);
  const uint32_t n = static_cast<uint32_t>(v.diagnostics.size());
  auto* d = arena.allocate<autonomy_PlannerDiagnostic>(n);
  for (uint32_t i = 0; i < n; ++i) {
    const msg::PlannerDiagnostic& x = v.diagnostics[i];
    d[i] = {c_str(x.file), x.line, x.column, c_str(x.message)};
  }
  out.diagnostics = {n, n, d, false};
  out.conflicts = to_c_strings(v.conflicts, arena);
  out.engine = c_str(v.engine);
  out.has_plan = v.has_plan;
  plan_to_c(v.plan, out.plan, arena);
  out.violations = to_c_strings(v.violations, arena);
  const msg::PlanningStatistics& s = v.statistics;
  out.statistics = {s.decisions,       s.backtracks,   s.dead_ends, s.temporal_propagations,
                    s.procedure_calls, s.improvements, s.elapsed_ms};
  out.plan_origin = v.plan_origin;
}

msg::PlanningReply DdsType<msg::PlanningReply>::from_c(const C& in) {
  msg::PlanningReply v;
  v.request_id = from_c_str(in.request_id);
  v.requester = from_c_str(in.requester);
  v.status = static_cast<msg::PlanningStatus>(in.status);
  v.reason = from_c_str(in.reason);
  v.detail = from_c_str(in.detail);
  for (uint32_t i = 0; i < in.diagnostics._length; ++i) {
    const auto& x = in.diagnostics._buffer[i];
    v.diagnostics.push_back({from_c_str(x.file), x.line, x.column, from_c_str(x.message)});
  }
  v.conflicts = from_c_strings(in.conflicts);
  v.engine = from_c_str(in.engine);
  v.has_plan = in.has_plan;
  v.plan = plan_from_c(in.plan);
  v.violations = from_c_strings(in.violations);
  const auto& s = in.statistics;
  v.statistics = {s.decisions,       s.backtracks,   s.dead_ends, s.temporal_propagations,
                  s.procedure_calls, s.improvements, s.elapsed_ms};
  v.plan_origin = in.plan_origin;
  return v;
}

void DdsType<msg::PlanningProgress>::to_c(const msg::PlanningProgress& v, C& out, Arena&) {
  out.request_id = c_str(v.request_id);
  out.improvement = v.improvement;
  out.makespan = v.makespan;
  out.penalty = v.penalty;
  out.tokens = v.tokens;
  out.elapsed_ms = v.elapsed_ms;
}

msg::PlanningProgress DdsType<msg::PlanningProgress>::from_c(const C& in) {
  return {
      from_c_str(in.request_id), in.improvement, in.makespan, in.penalty, in.tokens, in.elapsed_ms};
}

void DdsType<msg::PlanningCancel>::to_c(const msg::PlanningCancel& v, C& out, Arena&) {
  out.request_id = c_str(v.request_id);
  out.requester = c_str(v.requester);
}

msg::PlanningCancel DdsType<msg::PlanningCancel>::from_c(const C& in) {
  return {from_c_str(in.request_id), from_c_str(in.requester)};
}

void DdsType<msg::LatestPlan>::to_c(const msg::LatestPlan& v, C& out, Arena& arena) {
  out.requester = c_str(v.requester);
  out.request_id = c_str(v.request_id);
  out.status = static_cast<autonomy_PlanningStatus>(v.status);
  out.engine = c_str(v.engine);
  out.plan_origin = v.plan_origin;
  plan_to_c(v.plan, out.plan, arena);
}

msg::LatestPlan DdsType<msg::LatestPlan>::from_c(const C& in) {
  msg::LatestPlan v;
  v.requester = from_c_str(in.requester);
  v.request_id = from_c_str(in.request_id);
  v.status = static_cast<msg::PlanningStatus>(in.status);
  v.engine = from_c_str(in.engine);
  v.plan_origin = in.plan_origin;
  v.plan = plan_from_c(in.plan);
  return v;
}

}  // namespace autonomy::dds
