#include "plan_message.hpp"

namespace autonomy::planner {

msg::FlexiblePlan to_plan_message(const FlexiblePlan& plan) {
  msg::FlexiblePlan m;
  m.horizon = plan.horizon;
  m.makespan = plan.makespan;
  m.penalty = plan.penalty;
  m.omitted_goals = plan.omitted_goals;
  for (const PlanTimeline& tl : plan.timelines) m.timelines.push_back({tl.name, tl.tokens});
  for (const PlanToken& t : plan.tokens) {
    msg::PlanToken x;
    x.id = t.id;
    x.object = t.object;
    x.attribute = t.attribute;
    x.predicate = t.predicate;
    x.parameters = t.parameters;
    for (const auto& [lo, hi] : t.parameter_bounds) {
      x.parameter_lo.push_back(lo);
      x.parameter_hi.push_back(hi);
    }
    x.start_lb = t.start_lb;
    x.start_ub = t.start_ub;
    x.end_lb = t.end_lb;
    x.end_ub = t.end_ub;
    x.duration_lb = t.duration_lb;
    x.duration_ub = t.duration_ub;
    x.origin = t.origin;
    x.fact = t.fact;
    m.tokens.push_back(std::move(x));
  }
  for (const PlanConstraint& c : plan.constraints)
    m.constraints.push_back({c.from, c.to, c.lb, c.ub});
  return m;
}

FlexiblePlan from_plan_message(const msg::FlexiblePlan& m) {
  FlexiblePlan plan;
  plan.horizon = m.horizon;
  plan.makespan = m.makespan;
  plan.penalty = m.penalty;
  plan.omitted_goals = m.omitted_goals;
  for (const msg::PlanTimeline& tl : m.timelines) plan.timelines.push_back({tl.name, tl.tokens});
  for (const msg::PlanToken& x : m.tokens) {
    PlanToken t;
    t.id = x.id;
    t.object = x.object;
    t.attribute = x.attribute;
    t.predicate = x.predicate;
    t.parameters = x.parameters;
    // A sender with fewer bounds than parameters: the missing ones stay unknown (0, 0).
    for (std::size_t i = 0; i < x.parameter_lo.size() && i < x.parameter_hi.size(); ++i)
      t.parameter_bounds.push_back({x.parameter_lo[i], x.parameter_hi[i]});
    t.start_lb = x.start_lb;
    t.start_ub = x.start_ub;
    t.end_lb = x.end_lb;
    t.end_ub = x.end_ub;
    t.duration_lb = x.duration_lb;
    t.duration_ub = x.duration_ub;
    t.origin = x.origin;
    t.fact = x.fact;
    plan.tokens.push_back(std::move(t));
  }
  for (const msg::PlanConstraint& c : m.constraints)
    plan.constraints.push_back({c.from, c.to, c.lb, c.ub});
  return plan;
}

}  // namespace autonomy::planner
