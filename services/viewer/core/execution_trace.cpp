#include "services/viewer/core/execution_trace.hpp"

#include <algorithm>
#include <cctype>

namespace autonomy::viewer {

namespace {

bool is_token_kind(const std::string& kind) { return kind == "started" || kind == "ended"; }

// Commands and their confirmations are the executive's own bookkeeping, one per token: the
// token's bar already shows them.
bool is_quiet_kind(const std::string& kind) { return kind == "command" || kind == "confirmed"; }

// A re-plan or the next horizon: the plan named by the event is the one executing from now on.
bool begins_plan(const std::string& kind) { return kind == "plan_executing" || kind == "horizon_joined"; }

// The open records `which` selects ended unseen at `at_ns` (never before their start).
template <typename Which>
void cut_open(ExecutiveTrace& trace, int64_t at_ns, Which which) {
  for (ExecutedToken& t : trace.tokens)
    if (!t.end_ns && which(t)) {
      t.end_ns = std::max(at_ns, t.start_ns.value_or(at_ns));
      t.cut = true;
    }
}

}  // namespace

bool parse_token_name(const std::string& text, TokenName* out) {
  const std::size_t eq = text.find(" == ");
  if (eq == std::string::npos || eq == 0) return false;
  TokenName name;
  name.timeline = text.substr(0, eq);
  std::string value = text.substr(eq + 4);
  const std::size_t hash = value.rfind(" #");
  if (hash != std::string::npos && hash + 2 < value.size()) {
    const std::string digits = value.substr(hash + 2);
    if (std::all_of(digits.begin(), digits.end(), [](unsigned char c) { return std::isdigit(c) != 0; }) &&
        digits.size() <= 9) {
      name.token = std::stoll(digits);
      value.resize(hash);
    }
  }
  if (value.empty()) return false;
  name.value = std::move(value);
  *out = std::move(name);
  return true;
}

void ExecutionTraces::apply(const msg::ExecutiveEvent& event) {
  ExecutiveTrace& trace = traces_[event.executive];
  const uint64_t n = event.number;
  if (n == 0) {  // unnumbered: nothing to say about losses
    fold(trace, event);
    return;
  }
  if (n > trace.last_number) {
    if (trace.last_number > 0 && n > trace.last_number + 1) {
      // A gap: those samples were lost (or come late). The first sample heard starts no gap: a
      // viewer that joins a running executive never heard its earlier ones.
      const uint64_t gap = n - trace.last_number - 1;
      trace.lost += gap;
      for (uint64_t k = trace.last_number + 1; k < n && trace.missing.size() < limits_.missing; ++k)
        trace.missing.insert(k);
      add_mark(trace, {event.sim_time_ns, event.tick, "lost",
                       std::to_string(gap) + " event(s) not heard (numbers " + std::to_string(trace.last_number + 1) +
                           " to " + std::to_string(n - 1) + ")",
                       event.plan_id});
    }
    trace.last_number = n;
    fold(trace, event);
    return;
  }
  if (trace.missing.erase(n) == 1) {  // a late sample fills its gap
    --trace.lost;
    fold(trace, event);
    return;
  }
  if (n == 1) {
    // Numbering starts again: the executive was restarted. What ran in its previous run ended
    // unseen at the last time heard from it.
    cut_open(trace, trace.latest_ns, [](const ExecutedToken&) { return true; });
    trace.missing.clear();
    trace.last_number = 1;
    add_mark(trace, {event.sim_time_ns, event.tick, "restarted", "the executive's events are numbered from 1 again",
                     event.plan_id});
    fold(trace, event);
    return;
  }
  // A sample heard twice: nothing new.
}

void ExecutionTraces::apply(const msg::LatestPlan& plan) {
  ExecutiveTrace& trace = traces_[plan.requester];
  if (trace.plans.count(plan.request_id) == 0) trace.plans_heard.push_back(plan.request_id);
  trace.plans[plan.request_id] = plan;
  // The oldest go first, never the one executing.
  while (trace.plans_heard.size() > limits_.plans) {
    auto old = std::find_if(trace.plans_heard.begin(), trace.plans_heard.end(),
                            [&](const std::string& id) { return id != trace.plan_id; });
    if (old == trace.plans_heard.end()) break;  // only the executing one (a limit of 0)
    trace.plans.erase(*old);
    trace.plans_heard.erase(old);
  }
  ++version_;
}

void ExecutionTraces::apply(const msg::PlanningReply& reply) {
  // As the planner publishes a requester's latest plan (services/planner/dds/planner_node.cpp).
  if (!reply.has_plan || !reply.violations.empty()) return;
  apply(msg::LatestPlan{reply.requester, reply.request_id, reply.status, reply.engine, reply.plan_origin, reply.plan});
}

void ExecutionTraces::fold(ExecutiveTrace& trace, const msg::ExecutiveEvent& event) {
  ++version_;
  const bool latest = event.sim_time_ns >= trace.latest_ns;
  if (latest) {
    trace.latest_ns = event.sim_time_ns;
    trace.plan_id = event.plan_id;
  }
  if (!event.plan_id.empty() &&
      std::find(trace.plan_order.begin(), trace.plan_order.end(), event.plan_id) == trace.plan_order.end())
    trace.plan_order.push_back(event.plan_id);
  if (is_token_kind(event.kind)) {
    fold_token(trace, event, event.kind == "started");
    return;
  }
  if (is_quiet_kind(event.kind)) return;
  // An abort stops the plan's dispatch: its running tokens end unseen. A new plan (re-plan or
  // next horizon) ends what is still open of the others.
  if (event.kind == "aborted")
    cut_open(trace, event.sim_time_ns, [&](const ExecutedToken& t) { return t.plan_id == event.plan_id; });
  if (begins_plan(event.kind))
    cut_open(trace, event.sim_time_ns, [&](const ExecutedToken& t) { return t.plan_id != event.plan_id; });
  add_mark(trace, {event.sim_time_ns, event.tick, event.kind, event.text, event.plan_id});
}

void ExecutionTraces::fold_token(ExecutiveTrace& trace, const msg::ExecutiveEvent& event, bool start) {
  TokenName name;
  if (!parse_token_name(event.text, &name)) {
    ++trace.refused;
    return;
  }
  const int64_t at = event.sim_time_ns;
  // The record of this token: by id within the plan, else the latest of the same text (for an
  // end, one still open).
  ExecutedToken* found = nullptr;
  for (auto it = trace.tokens.rbegin(); it != trace.tokens.rend() && !found; ++it) {
    if (it->plan_id != event.plan_id) continue;
    if (name.token >= 0 ? it->token == name.token
                        : it->token < 0 && it->timeline == name.timeline && it->value == name.value &&
                              (start ? !it->start_ns : !it->end_ns || it->cut))
      found = &*it;
  }
  if (found && start) {
    if (found->start_ns) return;  // heard before
    if (found->end_ns && !found->cut && *found->end_ns < at) {
      ++trace.refused;  // a start after its end: not this token's
      return;
    }
    found->start_ns = at;  // a late start
    return;
  }
  if (found) {
    if (found->end_ns && !found->cut) return;  // heard before
    if (found->start_ns && at < *found->start_ns) {
      ++trace.refused;  // an end before its start
      return;
    }
    found->end_ns = at;  // the end heard (after a cut: it did end, later)
    found->cut = false;
    return;
  }
  ExecutedToken t;
  t.plan_id = event.plan_id;
  t.token = name.token;
  t.timeline = std::move(name.timeline);
  t.value = std::move(name.value);
  (start ? t.start_ns : t.end_ns) = at;  // an end alone: its start was lost or before we joined
  trace.tokens.push_back(std::move(t));
  while (trace.tokens.size() > limits_.tokens) trace.tokens.pop_front();
}

void ExecutionTraces::add_mark(ExecutiveTrace& trace, ExecutionMark mark) {
  trace.marks.push_back(std::move(mark));
  while (trace.marks.size() > limits_.marks) trace.marks.pop_front();
}

}  // namespace autonomy::viewer
