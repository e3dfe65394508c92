#include "plan_validator.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

namespace autonomy::planner {

namespace {

struct Interval {
  std::int64_t start, end;
};

// Each distance the relation constrains, with the master I and the slave J at fixed times.
bool relation_holds(pb::TemporalRelation::Kind kind, Interval i, Interval j, std::int64_t lb,
                    std::int64_t ub) {
  auto in = [&](std::int64_t from, std::int64_t to) { return to - from >= lb && to - from <= ub; };
  using R = pb::TemporalRelation;
  switch (kind) {
    case R::BEFORE:
      return in(i.end, j.start);
    case R::AFTER:
      return in(j.end, i.start);
    case R::STARTS_BEFORE:
      return in(i.start, j.start);
    case R::STARTS_AFTER:
      return in(j.start, i.start);
    case R::ENDS_BEFORE:
      return in(i.end, j.end);
    case R::ENDS_AFTER:
      return in(j.end, i.end);
    case R::STARTS_BEFORE_END:
      return in(i.start, j.end);
    case R::ENDS_AFTER_START:
      return in(j.start, i.end);
    case R::CONTAINS:
      return in(i.start, j.start) && in(j.end, i.end);
    case R::CONTAINED_BY:
      return in(j.start, i.start) && in(i.end, j.end);
    case R::PARALLELS:
      return in(i.start, j.start) && in(i.end, j.end);
    case R::PARALLELED_BY:
      return in(j.start, i.start) && in(j.end, i.end);
    default:
      return false;
  }
}

bool ground(const PlanToken& t, std::size_t i) {
  return std::abs(t.parameter_bounds[i].first - t.parameter_bounds[i].second) < 1e-9;
}
double value(const PlanToken& t, std::size_t i) {
  return t.parameter_bounds[i].first;
}

std::string describe(const PlanToken& t) {
  std::string s = "token " + std::to_string(t.id) + " (" + t.timeline() + " == " + t.predicate;
  if (!t.parameters.empty()) {
    s += "(";
    for (std::size_t i = 0; i < t.parameters.size(); ++i) s += (i ? ", " : "") + t.parameters[i];
    s += ")";
  }
  return s + ")";
}

}  // namespace

std::vector<std::string> validate_plan(const DomainModel& model, const PlanningProblem& problem,
                                       const FlexiblePlan& plan) {
  std::vector<std::string> errors;
  auto fail = [&](const std::string& s) { errors.push_back(s); };
  const std::int64_t big = std::int64_t(1) << 52;
  std::vector<int> predicate_of(plan.tokens.size(), -1);
  std::int64_t makespan = 0;
  // Tokens: values their attribute can take, durations, parameter constraints.
  for (const PlanToken& t : plan.tokens) {
    const Interval at{t.start_lb, t.end_lb};
    makespan = std::max(makespan, at.end);
    int o = problem.object(t.object);
    int p = model.predicate(t.predicate);
    if (o < 0 || p < 0) {
      fail(describe(t) + ": unknown object or predicate");
      continue;
    }
    const ClassDef& cls = model.classes[problem.objects[o].class_index];
    int a = cls.attribute(t.attribute);
    if (a < 0 || std::find(cls.attributes[a].predicates.begin(), cls.attributes[a].predicates.end(),
                           p) == cls.attributes[a].predicates.end()) {
      fail(describe(t) + ": not a value of " + t.timeline());
      continue;
    }
    predicate_of[t.id] = p;
    const PredicateDef& pd = model.predicates[p];
    const std::int64_t d = at.end - at.start;
    if (at.start < 0 || at.end > plan.horizon) fail(describe(t) + ": outside [0, horizon]");
    if (d < pd.min_duration || (pd.max_duration < big && d > pd.max_duration))
      fail(describe(t) + ": duration " + std::to_string(d) + " outside the predicate's range");
    if (t.parameter_bounds.size() != pd.parameters.size()) {
      fail(describe(t) + ": wrong number of parameters");
      continue;
    }
    for (const ParameterConstraintDef& c : pd.constraints) {
      std::vector<double> x;
      bool all_ground = true;
      for (const TermRef& term : c.terms) {
        if (term.kind == TermRef::Kind::kParameter) {
          all_ground &= ground(t, term.parameter);
          x.push_back(value(t, term.parameter));
        } else if (term.kind == TermRef::Kind::kDuration) {
          x.push_back(double(d));
        } else {
          x.push_back(term.value);
        }
      }
      if (!all_ground) continue;  // real intervals: left to the executive
      using K = pb::ParameterConstraint;
      bool ok = true;
      switch (c.kind) {
        case K::EQUAL:
          ok = std::abs(x[0] - x[1]) < 1e-6;
          break;
        case K::NOT_EQUAL:
          ok = std::abs(x[0] - x[1]) >= 1e-6;
          break;
        case K::LESS_EQUAL:
          ok = x[0] <= x[1] + 1e-6;
          break;
        case K::LESS:
          ok = x[0] < x[1];
          break;
        case K::SUM_PRODUCT:
          ok = std::abs(x[0] + x[1] * x[2] - x[3]) < 1e-6;
          break;
        case K::MEMBER:
          ok = std::find(x.begin() + 1, x.end(), x[0]) != x.end();
          break;
        case K::TABLE: {
          const std::size_t k = std::size_t(std::max(c.arity, 1));
          ok = false;
          for (std::size_t i = k; i + k <= x.size() && !ok; i += k) {
            bool row = true;
            for (std::size_t j = 0; j < k; ++j) row &= std::abs(x[i + j] - x[j]) < 1e-6;
            ok = row;
          }
          break;
        }
        default:
          break;
      }
      if (!ok) fail(describe(t) + ": a parameter constraint does not hold");
    }
  }
  if (makespan != plan.makespan)
    fail("makespan " + std::to_string(plan.makespan) + " reported, " + std::to_string(makespan) +
         " at the earliest times");
  // Timelines: tokens in order, none overlapping the next.
  for (const PlanTimeline& tl : plan.timelines) {
    for (std::size_t k = 1; k < tl.tokens.size(); ++k) {
      const PlanToken &a = plan.tokens[tl.tokens[k - 1]], &b = plan.tokens[tl.tokens[k]];
      if (a.timeline() != tl.name || b.timeline() != tl.name)
        fail(tl.name + ": a token of another timeline");
      if (a.end_lb > b.start_lb) fail(describe(a) + " overlaps " + describe(b) + " on " + tl.name);
    }
  }
  // Configuration constraints: every requirement of every applicable schema met by some token.
  for (const PlanToken& t : plan.tokens) {
    if (predicate_of[t.id] < 0) continue;
    // Initial values are the given state (checked against their facts below).
    if (t.fact >= 0 && std::size_t(t.fact) < problem.facts.size() && problem.facts[t.fact].initial)
      continue;
    for (int s : model.schemata_for(t.attribute, predicate_of[t.id])) {
      const ConfigurationSchema& schema = model.schemata[s];
      std::vector<std::optional<double>> bound(schema.variables.size());
      bool applies = true;
      for (std::size_t i = 0; i < schema.master.arguments.size(); ++i) {
        const PatternArgument& a = schema.master.arguments[i];
        if (a.kind == PatternArgument::Kind::kConstant && !(ground(t, i) && value(t, i) == a.value))
          applies = false;
        if (a.kind == PatternArgument::Kind::kVariable && ground(t, i))
          bound[a.variable] = value(t, i);
      }
      if (!applies) continue;
      for (const RequirementDef& rq : schema.requirements) {
        bool met = false;
        for (const ValuePatternDef& alt : rq.alternatives) {
          for (const PlanToken& u : plan.tokens) {
            if (met) break;
            if (u.object != t.object || u.attribute != alt.attribute ||
                predicate_of[u.id] != alt.predicate)
              continue;
            bool match = true;
            for (std::size_t i = 0; i < alt.arguments.size() && match; ++i) {
              const PatternArgument& a = alt.arguments[i];
              if (a.kind == PatternArgument::Kind::kConstant)
                match = ground(u, i) && value(u, i) == a.value;
              if (a.kind == PatternArgument::Kind::kVariable && bound[a.variable])
                match = ground(u, i) && value(u, i) == *bound[a.variable];
            }
            met = match && relation_holds(rq.relation, {t.start_lb, t.end_lb},
                                          {u.start_lb, u.end_lb}, rq.lb, rq.ub);
          }
        }
        if (!met)
          fail(describe(t) + " lacks " + relation_name(rq.relation) + "(" +
               rq.alternatives[0].attribute +
               " == " + model.predicates[rq.alternatives[0].predicate].name +
               "...) required by the schema at " + schema.where);
      }
    }
  }
  // Goals and initial values: the token claiming each, its values and bounds; then relations.
  std::map<int, const PlanToken*> achiever;
  for (const PlanToken& t : plan.tokens) {
    if (t.fact >= 0) achiever[t.fact] = &t;
    for (int f : t.facts) achiever.emplace(f, &t);  // goals merged into one token
  }
  for (std::size_t f = 0; f < problem.facts.size(); ++f) {
    const FactDef& fact = problem.facts[f];
    const std::string name =
        (fact.initial ? "initial value " : "goal ") + fact.label + " (" + fact.where + ")";
    auto it = achiever.find(int(f));
    if (it == achiever.end()) {
      bool omitted = std::find(plan.omitted_goals.begin(), plan.omitted_goals.end(), fact.label) !=
                     plan.omitted_goals.end();
      if (!(fact.optional && omitted)) fail(name + " is not in the plan");
      continue;
    }
    const PlanToken& t = *it->second;
    const ClassDef& cls = model.classes[problem.objects[fact.object].class_index];
    if (t.object != problem.objects[fact.object].name ||
        t.attribute != cls.attributes[fact.attribute].name || predicate_of[t.id] != fact.predicate)
      fail(name + ": achieved by " + describe(t) + ", a different value");
    for (std::size_t i = 0; i < fact.arguments.size() && i < t.parameter_bounds.size(); ++i)
      if (fact.arguments[i].kind == PatternArgument::Kind::kConstant &&
          !(ground(t, i) && value(t, i) == fact.arguments[i].value))
        fail(name + ": parameter " + std::to_string(i) + " differs in " + describe(t));
    auto within = [](std::int64_t v, std::int64_t lb, std::int64_t ub) {
      return v >= lb && v <= ub;
    };
    if (!within(t.start_lb, fact.start_lb, fact.start_ub) ||
        !within(t.end_lb, fact.end_lb, fact.end_ub) ||
        !within(t.end_lb - t.start_lb, fact.duration_lb, fact.duration_ub))
      fail(name + ": " + describe(t) + " misses the goal's time bounds");
  }
  for (const FactRelationDef& r : problem.relations) {
    auto a = achiever.find(r.from), b = achiever.find(r.to);
    if (a == achiever.end() || b == achiever.end()) continue;  // omitted: nothing to relate
    if (!relation_holds(r.relation, {a->second->start_lb, a->second->end_lb},
                        {b->second->start_lb, b->second->end_lb}, r.lb, r.ub))
      fail(std::string("relation ") + relation_name(r.relation) + " (" + r.where +
           ") does not hold between " + describe(*a->second) + " and " + describe(*b->second));
  }
  // Resources, per object: concurrent uses within capacity, reservoir levels within bounds.
  for (const ObjectDef& object : problem.objects) {
    const ClassDef& cls = model.classes[object.class_index];
    for (const ResourceDef& res : cls.resources) {
      struct Use {
        std::int64_t start, end;
        double amount;
      };
      std::vector<Use> uses;
      for (const PlanToken& t : plan.tokens) {
        if (t.object != object.name || predicate_of[t.id] < 0) continue;
        for (const EffectDef& e : model.predicates[predicate_of[t.id]].effects)
          if (e.resource_name == res.name) uses.push_back({t.start_lb, t.end_lb, e.amount});
      }
      if (res.kind == pb::Resource::REUSABLE) {
        for (const Use& at : uses) {
          double load = 0;
          for (const Use& u : uses)
            if (u.start <= at.start && at.start < u.end) load += u.amount;
          if (load > res.capacity + 1e-9) {
            std::ostringstream out;
            out << object.name << "." << res.name << ": " << load << " in use at " << at.start
                << ", capacity " << res.capacity;
            fail(out.str());
            break;
          }
        }
      } else {
        std::sort(uses.begin(), uses.end(),
                  [](const Use& a, const Use& b) { return a.end < b.end; });
        // Changes at the same time happen together (a charge ending as a drive ends).
        double level = res.initial_level;
        for (std::size_t i = 0; i < uses.size();) {
          const std::int64_t at = uses[i].end;
          for (; i < uses.size() && uses[i].end == at; ++i) level += uses[i].amount;
          if (level < res.min_level - 1e-9 || level > res.max_level + 1e-9) {
            std::ostringstream out;
            out << object.name << "." << res.name << ": level " << level << " at " << at
                << " outside [" << res.min_level << ", " << res.max_level << "]";
            fail(out.str());
            break;
          }
        }
      }
    }
  }
  return errors;
}

}  // namespace autonomy::planner
