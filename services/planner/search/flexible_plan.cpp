#include "flexible_plan.hpp"

#include <algorithm>
#include <map>

#include "token_network.hpp"

namespace autonomy::planner {

FlexiblePlan extract_plan(const TokenNetwork& net) {
  FlexiblePlan plan;
  const TemporalNetwork& tn = net.temporal();
  const DomainModel& model = net.model();
  const PlanningProblem& problem = net.problem();
  plan.horizon = tn.horizon();
  auto representative = [&](TokenId t) {
    while (net.tokens()[t].state == Token::State::kMerged) t = net.tokens()[t].merged_into;
    return t;
  };
  std::map<TokenId, std::uint32_t> index;  // network token -> plan token
  std::map<TimepointId, std::string> names{{TemporalNetwork::origin(), "origin"}};
  for (const Timeline& tl : net.timelines()) {
    PlanTimeline ptl{tl.name, {}};
    for (TokenId id : tl.sequence) {
      const Token& t = net.tokens()[id];
      PlanToken pt;
      pt.id = std::uint32_t(plan.tokens.size());
      pt.object = problem.objects[tl.object].name;
      pt.attribute =
          model.classes[problem.objects[tl.object].class_index].attributes[tl.attribute].name;
      pt.predicate = model.predicates[t.predicate].name;
      for (std::size_t i = 0; i < t.parameters.size(); ++i) {
        pt.parameters.push_back(net.parameter_text(id, i));
        const Domain& d = net.constraints().domain(t.parameters[i]);
        pt.parameter_bounds.push_back({d.lo(), d.hi()});
      }
      pt.start_lb = tn.earliest(t.start);
      pt.start_ub = tn.latest(t.start);
      pt.end_lb = tn.earliest(t.end);
      pt.end_ub = tn.latest(t.end);
      // The minimal network's distance bounds between this token's two timepoints.
      pt.duration_ub = tn.shortest_distance(t.start, t.end);
      pt.duration_lb = -tn.shortest_distance(t.end, t.start);
      pt.fact = t.fact;
      ptl.tokens.push_back(pt.id);
      index[id] = pt.id;
      names[t.start] = std::to_string(pt.id) + ".start";
      names[t.end] = std::to_string(pt.id) + ".end";
      plan.makespan = std::max<std::int64_t>(plan.makespan, pt.end_lb);
      plan.tokens.push_back(std::move(pt));
    }
    plan.timelines.push_back(std::move(ptl));
  }
  // Origins, and the timepoints of merged tokens under their target's names.
  for (TokenId id = 0; id < net.tokens().size(); ++id) {
    const Token& t = net.tokens()[id];
    if (t.state == Token::State::kOmitted && t.fact >= 0) {
      plan.omitted_goals.push_back(problem.facts[t.fact].label);
      plan.penalty += t.penalty;
      continue;
    }
    if (t.state != Token::State::kPlaced && t.state != Token::State::kMerged) continue;
    auto it = index.find(representative(id));
    if (it == index.end()) continue;
    PlanToken& pt = plan.tokens[it->second];
    names.emplace(t.start, std::to_string(pt.id) + ".start");
    names.emplace(t.end, std::to_string(pt.id) + ".end");
    std::string origin;
    if (t.fact >= 0) {
      const FactDef& f = problem.facts[t.fact];
      origin = std::string(f.initial ? "initial" : "goal") + (f.label.empty() ? "" : " " + f.label);
      if (pt.fact < 0) pt.fact = t.fact;
      if (std::find(pt.facts.begin(), pt.facts.end(), t.fact) == pt.facts.end()) {
        if (t.fact == pt.fact)
          pt.facts.insert(pt.facts.begin(), t.fact);
        else
          pt.facts.push_back(t.fact);
      }
    } else if (t.master != kNoToken && index.count(representative(t.master))) {
      origin = std::string(relation_name(t.relation)) + " of token " +
               std::to_string(index[representative(t.master)]);
    }
    if (!origin.empty()) pt.origin += (pt.origin.empty() ? "" : "; ") + origin;
  }
  for (const auto& c : tn.constraints()) {
    if (!c.active) continue;
    auto from = names.find(c.from), to = names.find(c.to);
    if (from == names.end() || to == names.end() || from->second == to->second) continue;
    plan.constraints.push_back({from->second, to->second, c.lb, c.ub});
  }
  return plan;
}

pb::FlexiblePlan to_message(const FlexiblePlan& plan) {
  pb::FlexiblePlan m;
  m.set_horizon(plan.horizon);
  m.set_makespan(plan.makespan);
  m.set_penalty(plan.penalty);
  for (const std::string& g : plan.omitted_goals) m.add_omitted_goals(g);
  for (const PlanTimeline& tl : plan.timelines) {
    pb::PlanTimeline* t = m.add_timelines();
    t->set_name(tl.name);
    for (auto id : tl.tokens) t->add_tokens(id);
  }
  auto bounds = [](pb::Bounds* b, std::int64_t lb, std::int64_t ub) {
    b->set_lb(lb);
    b->set_ub(ub);
  };
  for (const PlanToken& pt : plan.tokens) {
    pb::PlanToken* t = m.add_tokens();
    t->set_id(pt.id);
    t->set_timeline(pt.timeline());
    t->set_predicate(pt.predicate);
    for (const std::string& p : pt.parameters) t->add_parameters(p);
    bounds(t->mutable_start(), pt.start_lb, pt.start_ub);
    bounds(t->mutable_end(), pt.end_lb, pt.end_ub);
    bounds(t->mutable_duration(), pt.duration_lb, pt.duration_ub);
    t->set_origin(pt.origin);
  }
  for (const PlanConstraint& c : plan.constraints) {
    pb::PlanConstraint* x = m.add_constraints();
    x->set_from(c.from);
    x->set_to(c.to);
    x->set_lb(c.lb);
    x->set_ub(c.ub);
  }
  return m;
}

}  // namespace autonomy::planner
