#include "domain_model.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

namespace autonomy::planner {

std::string Diagnostic::to_string() const {
  std::ostringstream out;
  out << (file.empty() ? "<model>" : file) << ':' << line << ':' << column << ": " << message;
  return out.str();
}

std::string to_string(const Diagnostics& diagnostics) {
  std::string text;
  for (const Diagnostic& d : diagnostics) text += d.to_string() + "\n";
  return text;
}

namespace {

template <typename T>
int index_of(const std::vector<T>& items, const std::string& name) {
  for (std::size_t i = 0; i < items.size(); ++i)
    if (items[i].name() == name) return int(i);
  return -1;
}

class Checker {
 public:
  explicit Checker(Diagnostics* errors) : errors_(errors) {}
  void error(const pb::Location& at, const std::string& message) {
    errors_->push_back({at.file(), at.line(), at.column(), message});
  }
  bool failed() const { return !errors_->empty(); }

 private:
  Diagnostics* errors_;
};

std::string relation_bounds_problem(const pb::Bounds& b) {
  if (b.lb() > b.ub()) {
    return "lower bound " + std::to_string(b.lb()) + " exceeds upper bound " +
           std::to_string(b.ub());
  }
  return {};
}

// A constant argument (number or symbol) as a value of the parameter type, or an error text.
std::optional<double> constant_value(const DomainModel& model, const ParameterType& type,
                                     const pb::Argument& arg, std::string* why) {
  using K = ParameterType::Kind;
  if (arg.has_number()) {
    if (type.kind == K::kEnumeration || type.kind == K::kObject) {
      *why = "a number where a value of " +
             (type.kind == K::kEnumeration ? "enumeration " + model.enums[type.type].name()
                                           : "class " + model.classes[type.type].name) +
             " is expected";
      return std::nullopt;
    }
    double v = arg.number();
    if (type.kind == K::kInteger && v != std::floor(v)) {
      *why = "a real number where an integer is expected";
      return std::nullopt;
    }
    if (v < type.lb || v > type.ub) {
      std::ostringstream out;
      out << v << " is outside the parameter's range [" << type.lb << ", " << type.ub << "]";
      *why = out.str();
      return std::nullopt;
    }
    return v;
  }
  if (arg.has_symbol()) {
    if (type.kind != K::kEnumeration) {
      *why = "'" + arg.symbol() + "' where " +
             (type.kind == K::kObject ? "an object (only in problems)" : "a number") +
             " is expected";
      return std::nullopt;
    }
    const auto& values = model.enums[type.type].values();
    auto it = std::find(values.begin(), values.end(), arg.symbol());
    if (it == values.end()) {
      *why =
          "'" + arg.symbol() + "' is not a value of enumeration " + model.enums[type.type].name();
      return std::nullopt;
    }
    return double(it - values.begin());
  }
  *why = "not a constant";
  return std::nullopt;
}

bool same_type(const ParameterType& a, const ParameterType& b) {
  using K = ParameterType::Kind;
  if (a.kind == K::kEnumeration || a.kind == K::kObject || b.kind == K::kEnumeration ||
      b.kind == K::kObject)
    return a.kind == b.kind && a.type == b.type;
  return true;  // numbers mix
}

}  // namespace

int ClassDef::attribute(const std::string& n) const {
  for (std::size_t i = 0; i < attributes.size(); ++i)
    if (attributes[i].name == n) return int(i);
  return -1;
}
int ClassDef::resource(const std::string& n) const {
  for (std::size_t i = 0; i < resources.size(); ++i)
    if (resources[i].name == n) return int(i);
  return -1;
}
int DomainModel::predicate(const std::string& n) const {
  for (std::size_t i = 0; i < predicates.size(); ++i)
    if (predicates[i].name == n) return int(i);
  return -1;
}
int DomainModel::enumeration(const std::string& n) const {
  return index_of(enums, n);
}
int DomainModel::class_index(const std::string& n) const {
  for (std::size_t i = 0; i < classes.size(); ++i)
    if (classes[i].name == n) return int(i);
  return -1;
}
std::vector<int> DomainModel::schemata_for(const std::string& attribute, int predicate) const {
  std::vector<int> out;
  for (std::size_t i = 0; i < schemata.size(); ++i)
    if (schemata[i].master.attribute == attribute && schemata[i].master.predicate == predicate)
      out.push_back(int(i));
  return out;
}
int PlanningProblem::object(const std::string& n) const {
  for (std::size_t i = 0; i < objects.size(); ++i)
    if (objects[i].name == n) return int(i);
  return -1;
}

std::optional<DomainModel> build_domain_model(const pb::Model& in, Diagnostics* errors) {
  Checker check(errors);
  DomainModel model;
  model.name = in.name();
  std::set<std::string> seen;
  for (const pb::EnumType& e : in.enums()) {
    if (!seen.insert(e.name()).second)
      check.error(e.location(), "'" + e.name() + "' is defined twice");
    if (e.values().empty()) check.error(e.location(), "enumeration " + e.name() + " has no values");
    std::set<std::string> values(e.values().begin(), e.values().end());
    if (values.size() != std::size_t(e.values_size()))
      check.error(e.location(), "enumeration " + e.name() + " lists a value twice");
    model.enums.push_back(e);
  }
  // Class names first: object-typed parameters refer to them.
  for (const pb::ModelClass& c : in.classes()) {
    if (!seen.insert(c.name()).second)
      check.error(c.location(), "'" + c.name() + "' is defined twice");
    model.classes.push_back({c.name(), {}, {}});
  }
  for (const pb::Predicate& p : in.predicates()) {
    PredicateDef def;
    def.name = p.name();
    if (!seen.insert(p.name()).second)
      check.error(p.location(), "'" + p.name() + "' is defined twice");
    std::set<std::string> names;
    for (const pb::Parameter& param : p.parameters()) {
      if (!names.insert(param.name()).second || param.name() == "duration")
        check.error(param.location(), "parameter name '" + param.name() + "' is taken");
      ParameterType t;
      t.lb = param.type().lb();
      t.ub = param.type().ub();
      switch (param.type().kind()) {
        case pb::ParameterType::INTEGER:
        case pb::ParameterType::REAL:
          t.kind = param.type().kind() == pb::ParameterType::INTEGER ? ParameterType::Kind::kInteger
                                                                     : ParameterType::Kind::kReal;
          if (std::isnan(t.lb) || std::isnan(t.ub))
            check.error(param.location(), "parameter " + param.name() + ": a bound is not a number");
          else if (t.kind == ParameterType::Kind::kInteger &&
                   !(std::abs(t.lb) <= double(kNoBound) && std::abs(t.ub) <= double(kNoBound)))
            // Integer values become 64-bit codes (sets, exclusions): a bound beyond 2^52 could
            // not be represented exactly, nor converted without overflow.
            check.error(param.location(),
                        "parameter " + param.name() + ": integer bounds must lie within +-2^52");
          else if (t.lb > t.ub)
            check.error(param.location(), "parameter " + param.name() + ": lb > ub");
          break;
        case pb::ParameterType::ENUMERATION:
        case pb::ParameterType::OBJECT: {
          int e = model.enumeration(param.type().type_name());
          int c = model.class_index(param.type().type_name());
          if (e >= 0) {
            t.kind = ParameterType::Kind::kEnumeration;
            t.type = e;
            t.lb = 0;
            t.ub = model.enums[e].values_size() - 1;
          } else if (c >= 0) {
            t.kind = ParameterType::Kind::kObject;
            t.type = c;
          } else {
            check.error(param.location(), "unknown type '" + param.type().type_name() + "'");
          }
          break;
        }
        default:
          check.error(param.location(), "unknown parameter kind");
      }
      def.parameters.push_back({param.name(), t});
    }
    def.min_duration = p.has_duration() ? p.duration().lb() : 1;
    def.max_duration = p.has_duration() ? p.duration().ub() : kNoBound;
    if (def.min_duration < 0)
      check.error(p.location(), "predicate " + p.name() + ": negative duration");
    if (def.min_duration > def.max_duration)
      check.error(p.location(), "predicate " + p.name() + ": duration lb > ub");
    for (const pb::ParameterConstraint& c : p.constraints()) {
      ParameterConstraintDef cd{c.kind(), {}, int(c.arity())};
      const ParameterType* typed = nullptr;  // the first parameter operand's type, for symbols
      for (const pb::Term& t : c.terms()) {
        if (t.has_parameter()) {
          auto it = std::find_if(def.parameters.begin(), def.parameters.end(),
                                 [&](const ParameterDef& d) { return d.name == t.parameter(); });
          if (t.parameter() == "duration") {
            cd.terms.push_back({TermRef::Kind::kDuration, -1, 0});
          } else if (it == def.parameters.end()) {
            // A bare name may be an enumeration value; resolved below with the type.
            cd.terms.push_back({TermRef::Kind::kConstant, -2, 0});
          } else {
            cd.terms.push_back({TermRef::Kind::kParameter, int(it - def.parameters.begin()), 0});
            if (!typed) typed = &it->type;
          }
        } else {
          cd.terms.push_back({TermRef::Kind::kConstant, -1, t.number()});
          if (!(std::abs(t.number()) <= double(kNoBound)))  // also NaN
            check.error(t.location(), "a constant must lie within +-2^52");
        }
      }
      const bool table = c.kind() == pb::ParameterConstraint::TABLE;
      const int arity = table ? int(c.arity()) : 0;
      for (int i = 0; i < c.terms_size(); ++i) {
        TermRef& r = cd.terms[i];
        const pb::Term& t = c.terms(i);
        if (table) {
          // A table's column is typed by its own variable; its scope names variables only.
          typed = nullptr;
          const int column = arity > 0 ? i % arity : 0;
          if (i < arity) {
            if (r.kind == TermRef::Kind::kConstant)
              check.error(t.location(), "a table's columns are parameters or 'duration'");
            continue;
          }
          if (column < int(cd.terms.size()) && cd.terms[column].kind == TermRef::Kind::kParameter)
            typed = &def.parameters[cd.terms[column].parameter].type;
        }
        if (r.kind == TermRef::Kind::kConstant && (r.parameter == -2 || t.has_symbol())) {
          std::string name = t.has_parameter() ? t.parameter() : t.symbol();
          r.parameter = -1;
          bool found = false;
          if (typed && typed->kind == ParameterType::Kind::kEnumeration) {
            const auto& vals = model.enums[typed->type].values();
            auto it = std::find(vals.begin(), vals.end(), name);
            if (it != vals.end()) {
              r.value = double(it - vals.begin());
              found = true;
            }
          }
          if (!found)
            check.error(t.location(), "'" + name + "' is neither a parameter of " + p.name() +
                                          " nor a value of its type");
        }
      }
      std::size_t need = c.kind() == pb::ParameterConstraint::SUM_PRODUCT ? 4 : 2;
      if (table) {
        if (arity < 1 || c.terms_size() <= arity || c.terms_size() % arity != 0)
          check.error(c.location(), "a table needs its columns and whole tuples");
        else
          for (int i = arity; i < c.terms_size(); ++i) {
            const TermRef& col = cd.terms[i % arity];
            const TermRef& v = cd.terms[i];
            if (col.kind != TermRef::Kind::kParameter || v.kind != TermRef::Kind::kConstant)
              continue;
            const ParameterType& type = def.parameters[col.parameter].type;
            const bool symbolic = type.kind == ParameterType::Kind::kEnumeration ||
                                  type.kind == ParameterType::Kind::kObject;
            if (symbolic && c.terms(i).has_number())
              check.error(c.terms(i).location(), "a number where " +
                                                     def.parameters[col.parameter].name +
                                                     " takes a value of its type");
            else if ((type.kind == ParameterType::Kind::kInteger ||
                      type.kind == ParameterType::Kind::kReal) &&
                     (v.value < type.lb || v.value > type.ub))
              check.error(c.terms(i).location(),
                          "a value outside the type of " + def.parameters[col.parameter].name);
          }
      } else if ((c.kind() == pb::ParameterConstraint::MEMBER && c.terms_size() < 2) ||
                 (c.kind() != pb::ParameterConstraint::MEMBER &&
                  std::size_t(c.terms_size()) != need))
        check.error(c.location(), "constraint has the wrong number of operands");
      else if (cd.terms[0].kind == TermRef::Kind::kConstant &&
               c.kind() == pb::ParameterConstraint::MEMBER)
        check.error(c.location(), "'in' needs a parameter on its left");
      def.constraints.push_back(cd);
    }
    for (const pb::ResourceEffect& e : p.effects())
      def.effects.push_back({-1, e.resource(), e.amount()});
    model.predicates.push_back(std::move(def));
  }
  for (int ci = 0; ci < in.classes_size(); ++ci) {
    const pb::ModelClass& c = in.classes(ci);
    ClassDef& cls = model.classes[ci];
    for (const pb::Resource& r : c.resources()) {
      if (cls.resource(r.name()) >= 0)
        check.error(r.location(), "resource " + r.name() + " defined twice");
      if (r.kind() == pb::Resource::REUSABLE && r.capacity() < 0)
        check.error(r.location(), "negative capacity");
      if (r.kind() == pb::Resource::RESERVOIR &&
          !(r.min_level() <= r.initial_level() && r.initial_level() <= r.max_level()))
        check.error(r.location(), "reservoir " + r.name() + " needs min <= initial <= max");
      cls.resources.push_back(
          {r.name(), r.kind(), r.capacity(), r.min_level(), r.max_level(), r.initial_level()});
    }
    for (const pb::Attribute& a : c.attributes()) {
      if (cls.attribute(a.name()) >= 0 || cls.resource(a.name()) >= 0)
        check.error(a.location(), "'" + a.name() + "' is defined twice in class " + c.name());
      AttributeDef ad{a.name(), {}};
      for (const std::string& v : a.values()) {
        int p = model.predicate(v);
        if (p < 0) {
          check.error(a.location(), "attribute " + a.name() + ": unknown predicate '" + v + "'");
          continue;
        }
        ad.predicates.push_back(p);
        for (const EffectDef& e : model.predicates[p].effects) {
          if (cls.resource(e.resource_name) < 0) {
            const auto& effects = in.predicates(p).effects();
            auto it = std::find_if(
                effects.begin(), effects.end(),
                [&](const pb::ResourceEffect& x) { return x.resource() == e.resource_name; });
            check.error(it->location(), "predicate " + v + " is a value of " + c.name() + "." +
                                            a.name() + " but " + c.name() + " has no resource '" +
                                            e.resource_name + "'");
          }
        }
      }
      if (ad.predicates.empty() && a.values().empty())
        check.error(a.location(), "attribute " + a.name() + " takes no values");
      cls.attributes.push_back(std::move(ad));
    }
  }
  // Configuration constraint schemata.
  for (const pb::ConfigurationConstraint& cc : in.configuration_constraints()) {
    ConfigurationSchema schema;
    schema.where = cc.location().file() + ":" + std::to_string(cc.location().line());
    std::map<std::string, ParameterType> variable_types;
    auto resolve = [&](const pb::ValuePattern& vp, ValuePatternDef* out, bool master) -> bool {
      out->attribute = vp.attribute();
      out->predicate = model.predicate(vp.predicate());
      if (out->predicate < 0) {
        check.error(vp.location(), "unknown predicate '" + vp.predicate() + "'");
        return false;
      }
      const PredicateDef& pd = model.predicates[out->predicate];
      if (vp.arguments_size() != int(pd.parameters.size())) {
        check.error(vp.location(), vp.predicate() + " takes " +
                                       std::to_string(pd.parameters.size()) + " parameters, not " +
                                       std::to_string(vp.arguments_size()));
        return false;
      }
      for (int i = 0; i < vp.arguments_size(); ++i) {
        const pb::Argument& a = vp.arguments(i);
        const ParameterType& type = pd.parameters[i].type;
        PatternArgument pa;
        if (a.has_variable()) {
          auto [it, fresh] = variable_types.emplace(a.variable(), type);
          if (!fresh && !same_type(it->second, type))
            check.error(a.location(), "?" + a.variable() + " is used with two different types");
          auto vit = std::find(schema.variables.begin(), schema.variables.end(), a.variable());
          pa.kind = PatternArgument::Kind::kVariable;
          pa.variable = int(vit - schema.variables.begin());
          if (vit == schema.variables.end()) schema.variables.push_back(a.variable());
        } else if (a.has_any() || a.kind_case() == pb::Argument::KIND_NOT_SET) {
          pa.kind = PatternArgument::Kind::kAny;
        } else {
          std::string why;
          auto v = constant_value(model, type, a, &why);
          if (!v) check.error(a.location(), why);
          pa.kind = PatternArgument::Kind::kConstant;
          pa.value = v.value_or(0);
        }
        out->arguments.push_back(pa);
      }
      (void)master;
      return true;
    };
    if (!resolve(cc.master(), &schema.master, true)) continue;
    // The classes whose attribute can take the master value: the schema applies there.
    std::vector<int> classes;
    for (std::size_t c = 0; c < model.classes.size(); ++c) {
      int a = model.classes[c].attribute(cc.master().attribute());
      if (a < 0) continue;
      const auto& preds = model.classes[c].attributes[a].predicates;
      if (std::find(preds.begin(), preds.end(), schema.master.predicate) != preds.end())
        classes.push_back(int(c));
    }
    if (classes.empty())
      check.error(cc.master().location(), "unreachable schema: no attribute '" +
                                              cc.master().attribute() + "' of any class takes " +
                                              cc.master().predicate());
    for (const pb::Requirement& rq : cc.requirements()) {
      RequirementDef rd;
      rd.relation = rq.relation().kind();
      rd.lb = rq.relation().bounds().lb();
      rd.ub = rq.relation().bounds().ub();
      std::string why = relation_bounds_problem(rq.relation().bounds());
      if (!why.empty()) check.error(rq.location(), why);
      for (const pb::ValuePattern& alt : rq.alternatives()) {
        ValuePatternDef vd;
        if (!resolve(alt, &vd, false)) continue;
        for (int c : classes) {
          int a = model.classes[c].attribute(alt.attribute());
          const auto* preds = a >= 0 ? &model.classes[c].attributes[a].predicates : nullptr;
          if (!preds || std::find(preds->begin(), preds->end(), vd.predicate) == preds->end()) {
            check.error(alt.location(), "class " + model.classes[c].name + " has no attribute '" +
                                            alt.attribute() + "' that can take " + alt.predicate());
            break;
          }
        }
        rd.alternatives.push_back(std::move(vd));
      }
      schema.requirements.push_back(std::move(rd));
    }
    model.schemata.push_back(std::move(schema));
  }
  if (check.failed()) return std::nullopt;
  return model;
}

std::optional<PlanningProblem> build_problem(const DomainModel& model, const pb::Problem& in,
                                             Diagnostics* errors) {
  Checker check(errors);
  PlanningProblem problem;
  problem.name = in.name();
  problem.horizon = in.horizon();
  problem.objective = in.objective();
  if (in.horizon() <= 0 || in.horizon() >= kNoBound)
    check.error(in.location(), "the problem needs a positive, finite horizon");
  for (const pb::ObjectDeclaration& o : in.objects()) {
    int c = model.class_index(o.class_name());
    if (c < 0) check.error(o.location(), "unknown class '" + o.class_name() + "'");
    if (problem.object(o.name()) >= 0)
      check.error(o.location(), "object " + o.name() + " declared twice");
    problem.objects.push_back({o.name(), c});
  }
  std::map<std::string, int> labels;
  auto add_fact = [&](const pb::Fact& f, bool initial) {
    FactDef fd;
    fd.label = f.label();
    fd.initial = initial;
    fd.optional = f.optional();
    fd.penalty = f.penalty();
    fd.where = f.location().file() + ":" + std::to_string(f.location().line());
    fd.object = problem.object(f.object());
    if (fd.object < 0 || problem.objects[fd.object].class_index < 0) {
      check.error(f.location(), "unknown object '" + f.object() + "'");
      return;
    }
    const ClassDef& cls = model.classes[problem.objects[fd.object].class_index];
    fd.attribute = cls.attribute(f.attribute());
    if (fd.attribute < 0) {
      check.error(f.location(), "class " + cls.name + " has no attribute '" + f.attribute() + "'");
      return;
    }
    fd.predicate = model.predicate(f.predicate());
    const auto& preds = cls.attributes[fd.attribute].predicates;
    if (fd.predicate < 0 || std::find(preds.begin(), preds.end(), fd.predicate) == preds.end()) {
      check.error(f.location(),
                  f.object() + "." + f.attribute() + " cannot take '" + f.predicate() + "'");
      return;
    }
    const PredicateDef& pd = model.predicates[fd.predicate];
    if (f.arguments_size() != int(pd.parameters.size())) {
      check.error(f.location(), f.predicate() + " takes " + std::to_string(pd.parameters.size()) +
                                    " parameters, not " + std::to_string(f.arguments_size()));
      return;
    }
    for (int i = 0; i < f.arguments_size(); ++i) {
      const pb::Argument& a = f.arguments(i);
      const ParameterType& type = pd.parameters[i].type;
      PatternArgument pa;
      if (a.has_any() || a.kind_case() == pb::Argument::KIND_NOT_SET) {
        pa.kind = PatternArgument::Kind::kAny;
      } else if (a.has_variable()) {
        check.error(a.location(),
                    "variables (?" + a.variable() + ") belong in schemata, not facts");
      } else if (type.kind == ParameterType::Kind::kObject && a.has_symbol()) {
        int o = problem.object(a.symbol());
        if (o < 0 || problem.objects[o].class_index != type.type)
          check.error(a.location(), "'" + a.symbol() + "' is not an object of class " +
                                        model.classes[type.type].name);
        pa.kind = PatternArgument::Kind::kConstant;
        pa.value = o;
      } else {
        std::string why;
        auto v = constant_value(model, type, a, &why);
        if (!v) check.error(a.location(), why);
        pa.kind = PatternArgument::Kind::kConstant;
        pa.value = v.value_or(0);
      }
      fd.arguments.push_back(pa);
    }
    auto bounds = [&](bool has, const pb::Bounds& b, ModelTime* lb, ModelTime* ub,
                      const char* what) {
      if (!has) return;
      *lb = b.lb();
      *ub = b.ub();
      if (b.lb() > b.ub()) check.error(f.location(), std::string(what) + " bounds: lb > ub");
    };
    bounds(f.has_start(), f.start(), &fd.start_lb, &fd.start_ub, "start");
    bounds(f.has_end(), f.end(), &fd.end_lb, &fd.end_ub, "end");
    bounds(f.has_duration(), f.duration(), &fd.duration_lb, &fd.duration_ub, "duration");
    if (initial) fd.start_lb = fd.start_ub = 0;
    if (!f.label().empty() && !labels.emplace(f.label(), int(problem.facts.size())).second)
      check.error(f.location(), "label " + f.label() + " used twice");
    problem.facts.push_back(std::move(fd));
  };
  for (const pb::Fact& f : in.initial()) add_fact(f, true);
  for (const pb::Fact& f : in.goals()) add_fact(f, false);
  for (const pb::FactRelation& r : in.relations()) {
    auto from = labels.find(r.from()), to = labels.find(r.to());
    if (from == labels.end() || to == labels.end()) {
      check.error(r.location(),
                  "unknown label '" + (from == labels.end() ? r.from() : r.to()) + "'");
      continue;
    }
    std::string why = relation_bounds_problem(r.relation().bounds());
    if (!why.empty()) check.error(r.location(), why);
    problem.relations.push_back({from->second, to->second, r.relation().kind(),
                                 r.relation().bounds().lb(), r.relation().bounds().ub(),
                                 r.location().file() + ":" + std::to_string(r.location().line())});
  }
  if (check.failed()) return std::nullopt;
  return problem;
}

const char* relation_name(pb::TemporalRelation::Kind kind) {
  static const char* names[] = {"before",     "after",       "startsBefore",    "startsAfter",
                                "endsBefore", "endsAfter",   "startsBeforeEnd", "endsAfterStart",
                                "contains",   "containedBy", "parallels",       "paralleledBy"};
  int k = int(kind);
  return k >= 0 && k < 12 ? names[k] : "unknown relation";
}

std::string value_text(const DomainModel& model, const PlanningProblem& problem,
                       const ParameterType& type, double value) {
  switch (type.kind) {
    case ParameterType::Kind::kEnumeration:
      return model.enums[type.type].values(int(value));
    case ParameterType::Kind::kObject:
      return problem.objects[std::size_t(value)].name;
    default: {
      std::ostringstream out;
      out << value;
      return out.str();
    }
  }
}

}  // namespace autonomy::planner
