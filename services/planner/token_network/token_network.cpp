#include "token_network.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "not_first_last.hpp"
#include "procedures.hpp"

namespace autonomy::planner {

namespace {
Time to_time(ModelTime t) {
  return t >= kNoBound ? kInfinity : (t <= -kNoBound ? -kInfinity : t);
}

Domain type_domain(const ParameterType& t, const PlanningProblem& problem) {
  switch (t.kind) {
    case ParameterType::Kind::kInteger:
      return Domain::integer(t.lb, t.ub);
    case ParameterType::Kind::kReal:
      return Domain::real(t.lb, t.ub);
    case ParameterType::Kind::kEnumeration: {
      std::vector<std::int64_t> v;
      for (int i = 0; i <= int(t.ub); ++i) v.push_back(i);
      return Domain::values(v);
    }
    case ParameterType::Kind::kObject: {
      std::vector<std::int64_t> v;
      for (std::size_t o = 0; o < problem.objects.size(); ++o)
        if (problem.objects[o].class_index == t.type) v.push_back(std::int64_t(o));
      return Domain::values(v);
    }
  }
  return Domain::real(0, 0);
}
}  // namespace

std::string Decision::describe() const {
  std::ostringstream out;
  switch (kind) {
    case Kind::kInsert:
      out << "insert token " << token << " at position " << index;
      break;
    case Kind::kMerge:
      out << "merge token " << token << " into token " << index;
      break;
    case Kind::kOmit:
      out << "omit token " << token;
      break;
    case Kind::kRestrict:
      out << "restrict variable " << variable << " to " << domain.to_string();
      break;
    case Kind::kOrder:
      out << "token " << token << " ends before token " << index
          << (requirement ? " ends" : " starts");
      break;
    case Kind::kChoose:
      out << "instance " << instance << " requirement " << requirement << ": alternative " << index;
      break;
  }
  return out.str();
}

TokenNetwork::TokenNetwork(const DomainModel& model, const PlanningProblem& problem)
    : model_(model), problem_(problem), tn_(to_time(problem.horizon)) {}

TokenNetwork::Mark TokenNetwork::mark() const {
  return {tn_.mark(), cn_.mark(), trail_.size(), tokens_.size(), instances_.size()};
}

void TokenNetwork::undo_to(const Mark& m) {
  while (trail_.size() > m.trail) {
    trail_.back()();
    trail_.pop_back();
  }
  tokens_.resize(m.tokens);
  instantiated_.resize(m.tokens);
  instances_.resize(m.instances);
  tn_.undo_to(m.tn);
  cn_.undo_to(m.cn);
  temporal_reasons_.resize(tn_.constraints().size());
}

bool TokenNetwork::add_temporal(TimepointId from, TimepointId to, Time lb, Time ub,
                                const std::string& why) {
  TemporalResult r = tn_.add_constraint(from, to, lb, ub);
  temporal_reasons_.resize(tn_.constraints().size());
  temporal_reasons_.back() = why;
  if (r) return true;
  // Every caller gives up on a failure, so this cycle is why the current apply() fails.
  cycle_ = r.conflict;
  cycle_valid_ = explain_;
  // Name the statements of the cycle, each once, the closing one first.
  std::vector<std::string> reasons;
  for (TemporalConstraintId c : r.conflict) {
    const std::string s = c == TemporalNetwork::kHorizonConstraint
                              ? "the horizon " + std::to_string(tn_.horizon())
                              : (c < temporal_reasons_.size() ? temporal_reasons_[c] : why);
    if (!s.empty() && std::find(reasons.begin(), reasons.end(), s) == reasons.end())
      reasons.push_back(s);
  }
  conflict_ = "temporal conflict between: ";
  for (std::size_t i = 0; i < reasons.size(); ++i) conflict_ += (i ? "; " : "") + reasons[i];
  return false;
}

bool TokenNetwork::relate(TokenId master, TokenId slave, pb::TemporalRelation::Kind kind, Time lb,
                          Time ub, const std::string& why) {
  const Token &i = tokens_[master], &j = tokens_[slave];
  using R = pb::TemporalRelation;
  auto add = [&](TimepointId a, TimepointId b) { return add_temporal(a, b, lb, ub, why); };
  switch (kind) {
    case R::BEFORE:
      return add(i.end, j.start);
    case R::AFTER:
      return add(j.end, i.start);
    case R::STARTS_BEFORE:
      return add(i.start, j.start);
    case R::STARTS_AFTER:
      return add(j.start, i.start);
    case R::ENDS_BEFORE:
      return add(i.end, j.end);
    case R::ENDS_AFTER:
      return add(j.end, i.end);
    case R::STARTS_BEFORE_END:
      return add(i.start, j.end);
    case R::ENDS_AFTER_START:
      return add(j.start, i.end);
    case R::CONTAINS:
      return add(i.start, j.start) && add(j.end, i.end);
    case R::CONTAINED_BY:
      return add(j.start, i.start) && add(i.end, j.end);
    case R::PARALLELS:
      return add(i.start, j.start) && add(i.end, j.end);
    case R::PARALLELED_BY:
      return add(j.start, i.start) && add(j.end, i.end);
    default:
      return false;
  }
}

TokenId TokenNetwork::new_token(std::size_t timeline, int predicate) {
  const PredicateDef& pd = model_.predicates[predicate];
  Token t;
  t.predicate = predicate;
  t.timeline = timeline;
  t.start = tn_.add_timepoint();
  t.end = tn_.add_timepoint();
  t.min_duration = std::max<Time>(0, pd.min_duration);
  for (const ParameterDef& p : pd.parameters)
    t.parameters.push_back(cn_.add_variable(type_domain(p.type, problem_), p.name));
  tokens_.push_back(std::move(t));
  instantiated_.emplace_back();
  return tokens_.size() - 1;
}

// The predicate's duration range, the end before the makespan, and the parameter constraints.
bool TokenNetwork::setup_token(TokenId id, const std::string& why) {
  const PredicateDef& pd = model_.predicates[tokens_[id].predicate];
  if (!add_temporal(
          tokens_[id].start, tokens_[id].end, pd.min_duration, to_time(pd.max_duration),
          "duration of " + model_.predicates[tokens_[id].predicate].name + " for " + why) ||
      !add_temporal(tokens_[id].end, makespan_, 0, kInfinity, ""))
    return false;
  for (const ParameterConstraintDef& c : pd.constraints) {
    std::vector<VariableId> vars;
    std::vector<std::int64_t> constants;
    const bool table = c.kind == pb::ParameterConstraint::TABLE;
    for (std::size_t k = 0; k < (table ? std::size_t(c.arity) : c.terms.size()); ++k) {
      const TermRef& term = c.terms[k];
      switch (term.kind) {
        case TermRef::Kind::kParameter:
          vars.push_back(tokens_[id].parameters[term.parameter]);
          break;
        case TermRef::Kind::kDuration:
          if (tokens_[id].duration == static_cast<VariableId>(-1)) {
            tokens_[id].duration = cn_.add_variable(
                Domain::integer(double(pd.min_duration),
                                double(std::min(to_time(pd.max_duration), tn_.horizon()))),
                "duration");
          }
          vars.push_back(tokens_[id].duration);
          break;
        case TermRef::Kind::kConstant:
          constants.push_back(std::int64_t(term.value));
          vars.push_back(cn_.add_variable(Domain::real(term.value, term.value), "constant"));
          break;
      }
    }
    using K = pb::ParameterConstraint;
    switch (c.kind) {
      case K::EQUAL:
        cn_.add_constraint(make_equal(vars[0], vars[1]));
        break;
      case K::NOT_EQUAL:
        cn_.add_constraint(make_not_equal(vars[0], vars[1]));
        break;
      case K::LESS_EQUAL:
        cn_.add_constraint(make_less_equal(vars[0], vars[1], 0));
        break;
      case K::LESS:
        cn_.add_constraint(
            make_less_equal(vars[0], vars[1], cn_.domain(vars[0]).is_integer() ? 1 : 1e-6));
        break;
      case K::SUM_PRODUCT:
        cn_.add_constraint(make_sum_product(vars[0], vars[1], vars[2], vars[3]));
        break;
      case K::TABLE: {
        std::vector<std::vector<double>> tuples;
        for (std::size_t i = std::size_t(c.arity); i + std::size_t(c.arity) <= c.terms.size();
             i += std::size_t(c.arity)) {
          tuples.emplace_back();
          for (int k = 0; k < c.arity; ++k) tuples.back().push_back(c.terms[i + k].value);
        }
        cn_.add_constraint(make_table(vars, std::move(tuples)));
        break;
      }
      case K::MEMBER: {
        std::vector<std::int64_t> values;
        for (std::size_t i = 1; i < c.terms.size(); ++i)
          values.push_back(std::int64_t(c.terms[i].value));
        cn_.add_constraint(make_member(vars[0], values));
        break;
      }
      default:
        break;
    }
  }
  return true;
}

bool TokenNetwork::initialize() {
  // Conflicts found here are the problem's own: name every statement of the cycle.
  tn_.set_explain_conflicts(true);
  struct Off {
    TemporalNetwork& tn;
    bool restore;
    ~Off() { tn.set_explain_conflicts(restore); }
  } off{tn_, explain_};
  makespan_ = tn_.add_timepoint();
  for (std::size_t o = 0; o < problem_.objects.size(); ++o) {
    const ClassDef& cls = model_.classes[problem_.objects[o].class_index];
    for (std::size_t a = 0; a < cls.attributes.size(); ++a)
      timelines_.push_back(
          {problem_.objects[o].name + "." + cls.attributes[a].name, int(o), int(a), {}});
  }
  auto timeline_of = [&](int object, int attribute) {
    for (std::size_t i = 0; i < timelines_.size(); ++i)
      if (timelines_[i].object == object && timelines_[i].attribute == attribute) return i;
    return std::size_t(0);
  };
  std::vector<TokenId> of_fact;
  for (std::size_t f = 0; f < problem_.facts.size(); ++f) {
    const FactDef& fact = problem_.facts[f];
    const std::string why = (fact.initial ? "initial value " : "goal ") +
                            (fact.label.empty() ? std::to_string(f) : fact.label) + " (" +
                            fact.where + ")";
    TokenId t = new_token(timeline_of(fact.object, fact.attribute), fact.predicate);
    of_fact.push_back(t);
    tokens_[t].fact = int(f);
    tokens_[t].optional = fact.optional;
    tokens_[t].penalty = fact.penalty;
    tokens_[t].min_duration = std::max<Time>(tokens_[t].min_duration, fact.duration_lb);
    for (std::size_t i = 0; i < fact.arguments.size(); ++i) {
      if (fact.arguments[i].kind != PatternArgument::Kind::kConstant) continue;
      if (!cn_.narrow_bounds(tokens_[t].parameters[i], fact.arguments[i].value,
                             fact.arguments[i].value)) {
        conflict_ = "parameter " + std::to_string(i) + " of " + why + " is outside its domain";
        return false;
      }
    }
    if (!add_temporal(TemporalNetwork::origin(), tokens_[t].start, to_time(fact.start_lb),
                      to_time(fact.start_ub), why + " start") ||
        !add_temporal(TemporalNetwork::origin(), tokens_[t].end, to_time(fact.end_lb),
                      to_time(fact.end_ub), why + " end") ||
        !add_temporal(tokens_[t].start, tokens_[t].end, to_time(fact.duration_lb),
                      to_time(fact.duration_ub), why + " duration"))
      return false;
    if (!setup_token(t, why)) return false;
  }
  for (const FactRelationDef& r : problem_.relations) {
    std::string why = std::string(relation_name(r.relation)) + " between " +
                      problem_.facts[r.from].label + " and " + problem_.facts[r.to].label + " (" +
                      r.where + ")";
    if (!relate(of_fact[r.from], of_fact[r.to], r.relation, to_time(r.lb), to_time(r.ub), why))
      return false;
  }
  return propagate_constraints("the problem's parameters") && exclusion_propagation() && settle();
}

// Constraint propagation, with the duration variables tied to the temporal network both ways
// (the temporal side gives the window-implied bounds, the constraint side tightens the
// start->end distance), until neither side changes.
bool TokenNetwork::propagate_constraints(const std::string& why) {
  for (int round = 0; round < 20; ++round) {
    PropagationResult r = cn_.propagate();
    if (!r && r.interrupted) {
      interrupted_ = true;
      conflict_ = "stopped during parameter propagation (" + why + ")";
      return false;
    }
    if (!r) {
      conflict_ = "parameter constraints cannot hold (" + why + ")";
      if (!r.cycle.empty()) {
        // Name the relations of the cycle (parameter names): "a + 1 <= b, b + 1 <= a".
        conflict_ += ": no values satisfy ";
        std::vector<DifferenceEdge> edges;
        for (ConstraintId c : r.cycle) cn_.constraint(c).differences(&edges);
        for (std::size_t i = 0; i < edges.size(); ++i) {
          std::ostringstream text;
          text << (i ? ", " : "") << cn_.name(edges[i].a);
          if (edges[i].offset != 0) text << " + " << edges[i].offset;
          text << " <= " << cn_.name(edges[i].b);
          conflict_ += text.str();
        }
      } else if (!r.failed_on_restrict) {
        conflict_ += ": " + cn_.constraint(r.failed).name();
      }
      return false;
    }
    bool changed = false;
    for (TokenId id = 0; id < tokens_.size(); ++id) {
      Token& t = tokens_[id];
      if (t.duration == static_cast<VariableId>(-1)) continue;
      TimeBounds w = tn_.window_distance(t.start, t.end);
      Domain before = cn_.domain(t.duration);
      if (!cn_.narrow_bounds(t.duration, double(std::max<Time>(w.earliest, 0)), double(w.latest))) {
        conflict_ = "duration of token " + std::to_string(id) + " cannot fit (" + why + ")";
        return false;
      }
      changed |= !(before == cn_.domain(t.duration));
      Time lo = Time(std::ceil(cn_.domain(t.duration).lo() - 1e-9));
      Time hi = Time(std::floor(cn_.domain(t.duration).hi() + 1e-9));
      if (lo > t.pushed_min || hi < t.pushed_max) {
        Time old_min = t.pushed_min, old_max = t.pushed_max;
        on_undo([this, id, old_min, old_max] {
          if (id < tokens_.size()) {
            tokens_[id].pushed_min = old_min;
            tokens_[id].pushed_max = old_max;
          }
        });
        t.pushed_min = std::max(lo, t.pushed_min);
        t.pushed_max = std::min(hi, t.pushed_max);
        if (!add_temporal(t.start, t.end, t.pushed_min, t.pushed_max,
                          "duration constraint (" + why + ")"))
          return false;
        changed = true;
      }
    }
    if (!changed) return true;
  }
  return true;
}

bool TokenNetwork::apply(const Decision& d) {
  ++decisions_;
  cycle_valid_ = false;
  bool ok = false;
  switch (d.kind) {
    case Decision::Kind::kInsert:
      ok = insert(d.token, d.index);
      break;
    case Decision::Kind::kMerge:
      ok = merge(d.token, d.index);
      break;
    case Decision::Kind::kOmit: {
      Token& t = tokens_[d.token];
      if (!t.optional || t.state != Token::State::kFree) return false;
      TokenId id = d.token;
      on_undo([this, id] { tokens_[id].state = Token::State::kFree; });
      t.state = Token::State::kOmitted;
      ok = true;
      break;
    }
    case Decision::Kind::kRestrict:
      ok = cn_.narrow(d.variable, d.domain) && propagate_constraints("a parameter choice");
      break;
    case Decision::Kind::kChoose:
      ok = choose(d.instance, d.requirement, d.index);
      break;
    case Decision::Kind::kOrder:
      ok = add_temporal(tokens_[d.token].end,
                        d.requirement == 1 ? tokens_[d.index].end : tokens_[d.index].start, 0,
                        kInfinity, "resource order");
      break;
  }
  return ok && exclusion_propagation() && settle();
}

bool TokenNetwork::insert(TokenId id, std::size_t position) {
  Token& t = tokens_[id];
  Timeline& tl = timelines_[t.timeline];
  if (t.state != Token::State::kFree || position > tl.sequence.size()) return false;
  const std::string why = "order on " + tl.name;
  if (position > 0 &&
      !add_temporal(tokens_[tl.sequence[position - 1]].end, t.start, 0, kInfinity, why))
    return false;
  if (position < tl.sequence.size() &&
      !add_temporal(t.end, tokens_[tl.sequence[position]].start, 0, kInfinity, why))
    return false;
  tl.sequence.insert(tl.sequence.begin() + long(position), id);
  t.state = Token::State::kPlaced;
  const std::size_t timeline = t.timeline;
  on_undo([this, id, timeline, position] {
    auto& seq = timelines_[timeline].sequence;
    seq.erase(seq.begin() + long(position));
    tokens_[id].state = Token::State::kFree;
  });
  return true;
}

bool TokenNetwork::merge(TokenId id, TokenId target) {
  Token& t = tokens_[id];
  const Token& u = tokens_[target];
  if (t.state != Token::State::kFree || u.state != Token::State::kPlaced ||
      t.timeline != u.timeline || t.predicate != u.predicate)
    return false;
  const std::string why = "merging on " + timelines_[t.timeline].name;
  if (!add_temporal(u.start, t.start, 0, 0, why) || !add_temporal(u.end, t.end, 0, 0, why))
    return false;
  for (std::size_t i = 0; i < t.parameters.size(); ++i)
    if (t.parameters[i] != u.parameters[i])
      cn_.add_constraint(make_equal(t.parameters[i], u.parameters[i]));
  t.state = Token::State::kMerged;
  t.merged_into = target;
  on_undo([this, id] {
    tokens_[id].state = Token::State::kFree;
    tokens_[id].merged_into = kNoToken;
  });
  return propagate_constraints(why);
}

bool TokenNetwork::choose(std::size_t inst, std::size_t requirement, std::size_t alternative) {
  SchemaInstance& si = instances_[inst];
  const ConfigurationSchema& schema = model_.schemata[si.schema];
  const RequirementDef& rq = schema.requirements[requirement];
  if (si.chosen[requirement] >= 0 || alternative >= rq.alternatives.size()) return false;
  const ValuePatternDef& alt = rq.alternatives[alternative];
  const TokenId master = si.token;
  const Timeline& mtl = timelines_[tokens_[master].timeline];
  const ClassDef& cls = model_.classes[problem_.objects[mtl.object].class_index];
  const int attribute = cls.attribute(alt.attribute);
  std::size_t timeline = 0;
  for (std::size_t i = 0; i < timelines_.size(); ++i)
    if (timelines_[i].object == mtl.object && timelines_[i].attribute == attribute) timeline = i;
  const std::string why = std::string(relation_name(rq.relation)) + " of the schema at " +
                          schema.where + " for " + token_text(master);
  TokenId slave = new_token(timeline, alt.predicate);
  Token& s = tokens_[slave];
  s.master = master;
  s.relation = rq.relation;
  for (std::size_t i = 0; i < alt.arguments.size(); ++i) {
    const PatternArgument& a = alt.arguments[i];
    if (a.kind == PatternArgument::Kind::kVariable) {
      s.parameters[i] = instances_[inst].bindings[a.variable];
    } else if (a.kind == PatternArgument::Kind::kConstant) {
      if (!cn_.narrow_bounds(s.parameters[i], a.value, a.value)) {
        conflict_ = why + ": a constant outside its parameter's domain";
        return false;
      }
    }
  }
  on_undo([this, inst, requirement] {
    if (inst < instances_.size()) instances_[inst].chosen[requirement] = -1;
  });
  instances_[inst].chosen[requirement] = int(alternative);
  return setup_token(slave, why) &&
         relate(master, slave, rq.relation, to_time(rq.lb), to_time(rq.ub), why) &&
         propagate_constraints(why);
}

TokenNetwork::Applies TokenNetwork::applies(TokenId t, const ValuePatternDef& master,
                                            VariableId* undecided) const {
  Applies result = Applies::kYes;
  for (std::size_t i = 0; i < master.arguments.size(); ++i) {
    if (master.arguments[i].kind != PatternArgument::Kind::kConstant) continue;
    const Domain& d = cn_.domain(tokens_[t].parameters[i]);
    if (!d.contains(master.arguments[i].value)) return Applies::kNo;
    if (!d.is_singleton()) {
      result = Applies::kUndecided;
      *undecided = tokens_[t].parameters[i];
    }
  }
  return result;
}

bool TokenNetwork::settle() {
  for (TokenId id = 0; id < tokens_.size(); ++id) {
    if (tokens_[id].state != Token::State::kPlaced || is_initial(id)) continue;
    const Timeline& tl = timelines_[tokens_[id].timeline];
    const ClassDef& cls = model_.classes[problem_.objects[tl.object].class_index];
    for (int s : model_.schemata_for(cls.attributes[tl.attribute].name, tokens_[id].predicate)) {
      auto& done = instantiated_[id];
      if (std::find(done.begin(), done.end(), s) != done.end()) continue;
      VariableId undecided = 0;
      Applies a = applies(id, model_.schemata[s].master, &undecided);
      if (a == Applies::kUndecided) continue;
      done.push_back(s);
      on_undo([this, id] {
        if (id < instantiated_.size() && !instantiated_[id].empty()) instantiated_[id].pop_back();
      });
      if (a == Applies::kNo) continue;
      const ConfigurationSchema& schema = model_.schemata[s];
      SchemaInstance si{id, s, {}, std::vector<int>(schema.requirements.size(), -1)};
      for (std::size_t v = 0; v < schema.variables.size(); ++v) {
        VariableId var = static_cast<VariableId>(-1);
        for (std::size_t i = 0; i < schema.master.arguments.size(); ++i)
          if (schema.master.arguments[i].kind == PatternArgument::Kind::kVariable &&
              schema.master.arguments[i].variable == int(v))
            var = tokens_[id].parameters[i];
        if (var == static_cast<VariableId>(-1)) {
          // Not in the master: a fresh variable typed by its first use in a requirement.
          for (const RequirementDef& rq : schema.requirements)
            for (const ValuePatternDef& alt : rq.alternatives)
              for (std::size_t i = 0;
                   i < alt.arguments.size() && var == static_cast<VariableId>(-1); ++i)
                if (alt.arguments[i].kind == PatternArgument::Kind::kVariable &&
                    alt.arguments[i].variable == int(v))
                  var = cn_.add_variable(
                      type_domain(model_.predicates[alt.predicate].parameters[i].type, problem_),
                      schema.variables[v]);
        }
        si.bindings.push_back(var);
      }
      instances_.push_back(std::move(si));
    }
  }
  // Requirements with a single allowed value need no decision.
  for (std::size_t inst = 0; inst < instances_.size(); ++inst) {
    const ConfigurationSchema& schema = model_.schemata[instances_[inst].schema];
    for (std::size_t r = 0; r < schema.requirements.size(); ++r) {
      if (instances_[inst].chosen[r] < 0 && schema.requirements[r].alternatives.size() == 1 &&
          !choose(inst, r, 0))
        return false;
    }
  }
  return true;
}

// Tokens on one timeline that can never share a slot (all parameters decided, values
// different, positive duration) exclude each other in time. Two checks on them, repeated to a
// fixed point:
//  - overload: every window [a, b] must hold the durations of the tokens entirely within it;
//  - detectable precedence: when B cannot end before A's latest start, A precedes B, which is
//    added to the temporal network (as the search would find out only by trying every slot);
//  - edge finding on task intervals (Caseau and Laburthe 1995; Nuijten 1994): for the tokens
//    Omega inside a window [est(a), lct(b)] and a token i outside it, when Omega and i cannot
//    all fit before lct(b), i ends last, so every token of Omega precedes i; when they cannot
//    all fit after est(a), i precedes them all. Each is added as precedences too.
// Optional goals still free are left out: leaving them out must stay possible.
bool TokenNetwork::exclusion_propagation() {
  for (int round = 0; round < 8; ++round) {
    std::vector<std::vector<TokenId>> by_timeline(timelines_.size());
    for (TokenId id = 0; id < tokens_.size(); ++id) {
      const Token& t = tokens_[id];
      if (t.state != Token::State::kFree && t.state != Token::State::kPlaced) continue;
      if (t.min_duration <= 0 || (t.optional && t.state == Token::State::kFree)) continue;
      bool decided = true;
      for (VariableId v : t.parameters) decided &= cn_.domain(v).is_singleton();
      if (decided) by_timeline[t.timeline].push_back(id);
    }
    bool added = false;
    for (auto& ids : by_timeline) {
      if (ids.size() < 2) continue;
      // Identical values could still be merged: keep one token per value.
      std::map<std::vector<double>, TokenId> unique;
      for (TokenId id : ids) {
        std::vector<double> key{double(tokens_[id].predicate)};
        for (VariableId v : tokens_[id].parameters) key.push_back(cn_.domain(v).lo());
        unique.emplace(key, id);
      }
      if (unique.size() < 2) continue;
      using Window = UnaryWindow;
      std::vector<Window> w;
      std::vector<TokenId> members;
      for (auto& [key, id] : unique) {
        w.push_back({tn_.earliest(tokens_[id].start), tn_.latest(tokens_[id].end),
                     tokens_[id].min_duration});
        members.push_back(id);
      }
      std::vector<std::size_t> by_lct(w.size());
      for (std::size_t k = 0; k < w.size(); ++k) by_lct[k] = k;
      std::sort(by_lct.begin(), by_lct.end(),
                [&](std::size_t a, std::size_t b) { return w[a].lct < w[b].lct; });
      for (std::size_t f : by_lct) {
        const Window& from = w[f];
        Time load = 0;
        std::vector<std::size_t> within;  // the tokens that must fit in [from.est, x.lct]
        for (std::size_t k : by_lct) {
          const Window& x = w[k];
          if (x.est < from.est) continue;
          load += x.duration;
          within.push_back(k);
          if (from.est + load > x.lct) {
            // Name the tokens that cannot all fit, each with its statement (issue 29).
            conflict_ = "overload on " + timelines_[&ids - &by_timeline[0]].name + " in [" +
                        std::to_string(from.est) + ", " + std::to_string(x.lct) +
                        "]: the durations of ";
            for (std::size_t i = 0; i < within.size(); ++i) {
              const Token& t = tokens_[members[within[i]]];
              conflict_ += (i ? "; " : "") + token_text(members[within[i]]);
              if (t.fact >= 0) {
                const FactDef& fact = problem_.facts[std::size_t(t.fact)];
                conflict_ += " (" + (fact.initial ? std::string("initial value") : "goal " + fact.label) +
                             ", " + fact.where + ")";
              }
            }
            conflict_ += " add up to " + std::to_string(load) + ", more than the window holds";
            return false;
          }
        }
      }
      // i before j, once (a known pair is not added twice; both placed: their slots order
      // them; bounds already apart: nothing to add).
      auto precede = [&](std::size_t i, std::size_t j, const char* rule) {
        const Token &a = tokens_[members[i]], &b = tokens_[members[j]];
        if (a.state == Token::State::kPlaced && b.state == Token::State::kPlaced) return true;
        if (tn_.latest(a.end) <= tn_.earliest(b.start)) return true;
        auto key = std::make_pair(members[i], members[j]);
        if (!precedences_.insert(key).second) return true;
        on_undo([this, key] { precedences_.erase(key); });
        added = true;
        return add_temporal(a.end, b.start, 0, kInfinity,
                            std::string(rule) + " on " + timelines_[a.timeline].name);
      };
      constexpr std::size_t kEdgeFindingLimit = 32;  // task intervals cost n^3 per timeline
      if (members.size() <= kEdgeFindingLimit) {
        const std::size_t n = members.size();
        // Per token: the tokens that must end before it starts, and those it must precede.
        std::vector<std::uint32_t> after(n, 0), before(n, 0);
        // Omega grows as the est threshold goes down (tokens by est, latest first); a token i
        // is pushed only when d(i) exceeds the slack lct(b) - est(a) - p(Omega), so windows
        // with more slack than the longest token are skipped.
        std::vector<std::size_t> by_est(n);
        for (std::size_t k = 0; k < n; ++k) by_est[k] = k;
        std::sort(by_est.begin(), by_est.end(),
                  [&](std::size_t x, std::size_t y) { return w[x].est > w[y].est; });
        Time longest = 0;
        for (const Window& x : w) longest = std::max(longest, x.duration);
        for (std::size_t b = 0; b < n; ++b) {
          std::uint32_t omega = 0;
          Time p = 0;
          for (std::size_t r = 0; r < n; ++r) {
            const std::size_t k = by_est[r];
            if (w[k].lct <= w[b].lct) {
              omega |= std::uint32_t{1} << k;
              p += w[k].duration;
            }
            if (r + 1 < n && w[by_est[r + 1]].est == w[k].est) continue;  // ties: all of them
            const Time est = w[k].est;
            if (omega == 0 || est >= w[b].lct || w[b].lct - est - p >= longest) continue;
            for (std::size_t i = 0; i < n; ++i) {
              if (omega & (std::uint32_t{1} << i)) continue;
              if (std::min(w[i].est, est) + p + w[i].duration > w[b].lct) after[i] |= omega;
              if (std::max(w[i].lct, w[b].lct) - p - w[i].duration < est) before[i] |= omega;
            }
          }
        }
        for (std::size_t i = 0; i < n; ++i)
          for (std::size_t k = 0; k < n; ++k) {
            if ((after[i] >> k) & 1u && !precede(k, i, "edge finding")) return false;
            if ((before[i] >> k) & 1u && !precede(i, k, "edge finding")) return false;
          }
        // Not-first/not-last (not_first_last.hpp) narrows the windows themselves.
        const std::vector<UnaryWindow> narrowed =
            not_first_not_last_ ? not_first_not_last(w) : std::vector<UnaryWindow>{};
        const std::string& line = timelines_[tokens_[members[0]].timeline].name;
        for (std::size_t i = 0; i < narrowed.size(); ++i) {
          const Token& t = tokens_[members[i]];
          if (narrowed[i].est > tn_.earliest(t.start)) {
            added = true;
            if (!add_temporal(TemporalNetwork::origin(), t.start, narrowed[i].est, kInfinity,
                              "not-first on " + line))
              return false;
          }
          if (narrowed[i].lct < tn_.latest(t.end)) {
            added = true;
            if (!add_temporal(TemporalNetwork::origin(), t.end, 0, narrowed[i].lct,
                              "not-last on " + line))
              return false;
          }
        }
      }
      for (std::size_t i = 0; i < members.size(); ++i) {
        for (std::size_t j = 0; j < members.size(); ++j) {
          if (i == j) continue;
          const Token &a = tokens_[members[i]], &b = tokens_[members[j]];
          if (a.state == Token::State::kPlaced && b.state == Token::State::kPlaced) continue;
          // B before A would need est(B) + d(B) <= lst(A) = latest(A.start).
          if (tn_.earliest(b.start) + b.min_duration <= tn_.latest(a.start)) continue;
          if (tn_.earliest(b.start) >= tn_.earliest(a.end) &&
              tn_.latest(a.end) <= tn_.earliest(b.start))
            continue;  // already apart
          auto key = std::make_pair(members[i], members[j]);
          if (precedences_.count(key)) continue;
          precedences_.insert(key);
          on_undo([this, key] { precedences_.erase(key); });
          if (!add_temporal(a.end, b.start, 0, kInfinity,
                            "exclusion on " + timelines_[a.timeline].name))
            return false;
          added = true;
        }
      }
    }
    if (!added) return true;
  }
  return true;
}

bool TokenNetwork::is_initial(TokenId id) const {
  return tokens_[id].fact >= 0 && problem_.facts[tokens_[id].fact].initial;
}

bool TokenNetwork::bound_makespan(Time ub) {
  return add_temporal(TemporalNetwork::origin(), makespan_, 0, ub, "the makespan bound");
}

double TokenNetwork::omitted_penalty() const {
  double p = 0;
  for (const Token& t : tokens_)
    if (t.state == Token::State::kOmitted) p += t.penalty;
  return p;
}

bool TokenNetwork::may_merge(TokenId a, TokenId b) const {
  const Token &t = tokens_[a], &u = tokens_[b];
  if (t.timeline != u.timeline || t.predicate != u.predicate) return false;
  for (std::size_t i = 0; i < t.parameters.size(); ++i) {
    Domain d = cn_.domain(t.parameters[i]);
    d.intersect(cn_.domain(u.parameters[i]));
    if (d.empty()) return false;
  }
  auto overlap = [&](TimepointId x, TimepointId y) {
    return tn_.earliest(x) <= tn_.latest(y) && tn_.earliest(y) <= tn_.latest(x);
  };
  return overlap(t.start, u.start) && overlap(t.end, u.end);
}

std::vector<Flaw> TokenNetwork::flaws() const {
  std::vector<Flaw> out;
  for (TokenId id = 0; id < tokens_.size(); ++id) {
    const Token& t = tokens_[id];
    if (t.state == Token::State::kFree) {
      out.push_back({Flaw::Kind::kFreeToken, id});
      continue;
    }
    if (t.state != Token::State::kPlaced) continue;
    const Timeline& tl = timelines_[t.timeline];
    const ClassDef& cls = model_.classes[problem_.objects[tl.object].class_index];
    std::vector<int> schemata;
    if (!is_initial(id))
      schemata = model_.schemata_for(cls.attributes[tl.attribute].name, t.predicate);
    for (int s : schemata) {
      const auto& done = instantiated_[id];
      if (std::find(done.begin(), done.end(), s) != done.end()) continue;
      VariableId undecided = 0;
      if (applies(id, model_.schemata[s].master, &undecided) == Applies::kUndecided) {
        Flaw f{Flaw::Kind::kUnboundParameter, id};
        f.variable = undecided;
        f.blocks_schema = true;
        out.push_back(f);
      }
    }
    for (VariableId v : t.parameters) {
      const Domain& d = cn_.domain(v);
      if (d.is_integer() && !d.is_singleton()) {
        Flaw f{Flaw::Kind::kUnboundParameter, id};
        f.variable = v;
        out.push_back(f);
      }
    }
  }
  for (std::size_t inst = 0; inst < instances_.size(); ++inst)
    for (std::size_t r = 0; r < instances_[inst].chosen.size(); ++r)
      if (instances_[inst].chosen[r] < 0) {
        Flaw f{Flaw::Kind::kOpenRequirement, instances_[inst].token};
        f.instance = inst;
        f.requirement = r;
        out.push_back(f);
      }
  for (Flaw& f : resource_flaws()) out.push_back(std::move(f));
  return out;
}

std::vector<Flaw> TokenNetwork::resource_flaws() const {
  std::vector<Flaw> out;
  for (std::size_t o = 0; o < problem_.objects.size(); ++o) {
    const ClassDef& cls = model_.classes[problem_.objects[o].class_index];
    for (const ResourceDef& res : cls.resources) {
      struct Use {
        TokenId id;
        double amount;
      };
      std::vector<Use> uses;
      for (TokenId id = 0; id < tokens_.size(); ++id) {
        const Token& t = tokens_[id];
        if (t.state != Token::State::kPlaced || timelines_[t.timeline].object != int(o)) continue;
        for (const EffectDef& e : model_.predicates[t.predicate].effects)
          if (e.resource_name == res.name) uses.push_back({id, e.amount});
      }
      if (uses.empty()) continue;
      auto start = [&](TokenId id) { return tn_.earliest(tokens_[id].start); };
      auto end = [&](TokenId id) { return tn_.earliest(tokens_[id].end); };
      if (res.kind == pb::Resource::REUSABLE) {
        // Pairs first: exact under every dispatch of the flexible plan. Tokens of one
        // timeline are ordered already; bounds settle most other pairs; the rest take a
        // shortest-path search that stops beyond distance 0.
        auto distance = [&](TimepointId from, TimepointId to) {
          return tn_.shortest_distance(from, to, 0);
        };
        for (std::size_t i = 0; i < uses.size(); ++i)
          for (std::size_t j = i + 1; j < uses.size(); ++j) {
            if (uses[i].amount + uses[j].amount <= res.capacity + 1e-9) continue;
            const Token &a = tokens_[uses[i].id], &b = tokens_[uses[j].id];
            if (a.timeline == b.timeline) continue;
            if (tn_.latest(a.end) <= tn_.earliest(b.start) ||
                tn_.latest(b.end) <= tn_.earliest(a.start))
              continue;
            const bool apart = distance(b.start, a.end) <= 0 || distance(a.start, b.end) <= 0;
            if (apart) continue;
            Flaw f{Flaw::Kind::kResourceConflict, uses[i].id};
            f.involved = {uses[i].id, uses[j].id};
            out.push_back(f);
            return out;
          }
        // Larger sets: peaks at the earliest times.
        for (const Use& at : uses) {
          double load = 0;
          std::vector<TokenId> active;
          for (const Use& u : uses)
            if (start(u.id) <= start(at.id) && start(at.id) < end(u.id)) {
              load += u.amount;
              active.push_back(u.id);
            }
          if (load > res.capacity + 1e-9) {
            Flaw f{Flaw::Kind::kResourceConflict, at.id};
            f.involved = active;
            out.push_back(f);
            return out;
          }
        }
      } else {
        std::sort(uses.begin(), uses.end(),
                  [&](const Use& a, const Use& b) { return end(a.id) < end(b.id); });
        double level = res.initial_level;
        for (std::size_t i = 0; i < uses.size();) {
          std::size_t j = i;
          for (; j < uses.size() && end(uses[j].id) == end(uses[i].id); ++j)
            level += uses[j].amount;
          const bool low = level<res.min_level - 1e-9, high = level> res.max_level + 1e-9;
          if (low || high) {
            Flaw f{Flaw::Kind::kResourceConflict, uses[i].id};
            f.reservoir = true;
            f.reservoir_low = low;
            // Candidates to move before it: later producers (low) or later consumers (high).
            for (std::size_t k = j; k < uses.size(); ++k)
              if ((low && uses[k].amount > 0) || (high && uses[k].amount < 0))
                f.involved.push_back(uses[k].id);
            out.push_back(f);
            return out;
          }
          i = j;
        }
      }
    }
  }
  return out;
}

std::vector<Decision> TokenNetwork::options(const Flaw& f) const {
  std::vector<Decision> out;
  switch (f.kind) {
    case Flaw::Kind::kFreeToken: {
      const Token& t = tokens_[f.token];
      const Timeline& tl = timelines_[t.timeline];
      for (TokenId other : tl.sequence)
        if (may_merge(f.token, other)) {
          Decision d{Decision::Kind::kMerge, f.token, other};
          out.push_back(d);
        }
      // Slots whose neighbours leave room, the earliest-starting first (later slots on ties).
      std::vector<std::pair<Time, std::size_t>> slots;
      for (std::size_t p = 0; p <= tl.sequence.size(); ++p) {
        Time after = p > 0 ? tn_.earliest(tokens_[tl.sequence[p - 1]].end) : 0;
        Time before =
            p < tl.sequence.size() ? tn_.latest(tokens_[tl.sequence[p]].start) : kInfinity;
        if (after > tn_.latest(t.start) || tn_.earliest(t.end) > before) continue;
        slots.push_back({std::max(after, tn_.earliest(t.start)), p});
      }
      std::sort(slots.begin(), slots.end(), [](auto& a, auto& b) {
        return a.first != b.first ? a.first < b.first : a.second > b.second;
      });
      for (auto& [start, p] : slots) out.push_back({Decision::Kind::kInsert, f.token, p});
      if (t.optional) out.push_back({Decision::Kind::kOmit, f.token});
      break;
    }
    case Flaw::Kind::kOpenRequirement: {
      const auto& rq = model_.schemata[instances_[f.instance].schema].requirements[f.requirement];
      for (std::size_t a = 0; a < rq.alternatives.size(); ++a) {
        Decision d{Decision::Kind::kChoose, f.token, a, f.instance, f.requirement};
        out.push_back(d);
      }
      break;
    }
    case Flaw::Kind::kResourceConflict: {
      auto order = [&](TokenId a, TokenId b, std::size_t to_end) {
        Decision d{Decision::Kind::kOrder, a, b};
        d.requirement = to_end;
        out.push_back(d);
      };
      if (f.reservoir) {
        // Level out of bounds where f.token ends: one of the candidates ends no later.
        for (TokenId k : f.involved) order(k, f.token, 1);
      } else {
        // Most slack first: a before b where b's latest start leaves the most room.
        std::vector<std::pair<Time, std::pair<TokenId, TokenId>>> pairs;
        for (TokenId a : f.involved)
          for (TokenId b : f.involved)
            if (a != b && tn_.earliest(tokens_[a].end) <= tn_.latest(tokens_[b].start))
              pairs.push_back(
                  {tn_.latest(tokens_[b].start) - tn_.earliest(tokens_[a].end), {a, b}});
        std::sort(pairs.begin(), pairs.end(), [](auto& x, auto& y) { return x.first > y.first; });
        for (auto& [slack, ab] : pairs) order(ab.first, ab.second, 0);
      }
      break;
    }
    case Flaw::Kind::kUnboundParameter: {
      const Domain& d = cn_.domain(f.variable);
      auto restrict_to = [&](Domain dom) {
        Decision dec{Decision::Kind::kRestrict, f.token};
        dec.variable = f.variable;
        dec.domain = std::move(dom);
        out.push_back(dec);
      };
      if (d.is_set()) {
        for (std::int64_t v : d.set_values()) restrict_to(Domain::singleton(v));
      } else if (d.size() <= 16) {
        for (double v = d.lo(); v <= d.hi(); v += 1) restrict_to(Domain::integer(v, v));
      } else {
        double mid = std::floor((d.lo() + d.hi()) / 2);
        restrict_to(Domain::integer(d.lo(), mid));
        restrict_to(Domain::integer(mid + 1, d.hi()));
      }
      break;
    }
  }
  return out;
}

std::string TokenNetwork::parameter_text(TokenId id, std::size_t i) const {
  const Token& t = tokens_[id];
  const Domain& d = cn_.domain(t.parameters[i]);
  const ParameterType& type = model_.predicates[t.predicate].parameters[i].type;
  if (d.is_singleton()) return value_text(model_, problem_, type, d.lo());
  if (d.is_set()) {
    std::string s = "{";
    for (std::size_t k = 0; k < d.set_values().size(); ++k)
      s += (k ? ", " : "") + value_text(model_, problem_, type, double(d.set_values()[k]));
    return s + "}";
  }
  std::ostringstream out;
  out << '[' << d.lo() << ", " << d.hi() << ']';
  return out.str();
}

std::string TokenNetwork::token_text(TokenId id) const {
  const Token& t = tokens_[id];
  std::string s = timelines_[t.timeline].name + " == " + model_.predicates[t.predicate].name;
  if (!t.parameters.empty()) {
    s += "(";
    for (std::size_t i = 0; i < t.parameters.size(); ++i)
      s += (i ? ", " : "") + parameter_text(id, i);
    s += ")";
  }
  return s;
}

}  // namespace autonomy::planner
