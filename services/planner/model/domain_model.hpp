#pragma once
// The model manager (paper, section 4): the checked domain model and problem, with names
// resolved to indices, built from the protobuf message (its single input interface). Answers
// the questions the token network asks: which predicates an attribute takes, which
// configuration constraint schemata apply to a value.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "diagnostic.hpp"
#include "idl/planner_model.pb.h"

namespace autonomy::planner {

using ModelTime = std::int64_t;
inline constexpr ModelTime kNoBound = ModelTime{1} << 52;  // same as the temporal network's

struct ParameterType {
  enum class Kind { kInteger, kReal, kEnumeration, kObject } kind = Kind::kInteger;
  double lb = 0, ub = 0;
  int type = -1;  // enumeration index or class index
};

struct ParameterDef {
  std::string name;
  ParameterType type;
};

// A resolved operand: parameter index, the duration, or a constant (enumeration values are
// their index in the enumeration).
struct TermRef {
  enum class Kind { kParameter, kDuration, kConstant } kind = Kind::kConstant;
  int parameter = -1;
  double value = 0;
};

struct ParameterConstraintDef {
  pb::ParameterConstraint::Kind kind;
  std::vector<TermRef> terms;
  int arity = 0;  // TABLE: the first `arity` terms are the columns, then the tuples' values
};

struct EffectDef {
  int resource = -1;  // index in the class's resources (resolved per class, see ClassDef)
  std::string resource_name;
  double amount = 0;
};

struct PredicateDef {
  std::string name;
  std::vector<ParameterDef> parameters;
  ModelTime min_duration = 0, max_duration = kNoBound;
  std::vector<ParameterConstraintDef> constraints;
  std::vector<EffectDef> effects;
};

struct AttributeDef {
  std::string name;
  std::vector<int> predicates;
};

struct ResourceDef {
  std::string name;
  pb::Resource::Kind kind;
  double capacity = 0, min_level = 0, max_level = 0, initial_level = 0;
};

struct ClassDef {
  std::string name;
  std::vector<AttributeDef> attributes;
  std::vector<ResourceDef> resources;
  int attribute(const std::string& name) const;
  int resource(const std::string& name) const;
};

// Pattern argument: a schema variable, a constant (number or enumeration index), or any.
struct PatternArgument {
  enum class Kind { kVariable, kConstant, kAny } kind = Kind::kAny;
  int variable = -1;
  double value = 0;
};

struct ValuePatternDef {
  std::string attribute;
  int predicate = -1;
  std::vector<PatternArgument> arguments;
};

struct RequirementDef {
  pb::TemporalRelation::Kind relation;
  ModelTime lb = 0, ub = kNoBound;
  std::vector<ValuePatternDef> alternatives;
};

struct ConfigurationSchema {
  ValuePatternDef master;
  std::vector<RequirementDef> requirements;
  std::vector<std::string> variables;  // ?names, in order of first use
  std::string where;                   // "file:line" of the schema, for explanations
};

struct DomainModel {
  std::string name;
  std::vector<pb::EnumType> enums;
  std::vector<PredicateDef> predicates;
  std::vector<ClassDef> classes;
  std::vector<ConfigurationSchema> schemata;

  int predicate(const std::string& name) const;
  int enumeration(const std::string& name) const;
  int class_index(const std::string& name) const;
  // Schemata whose master pattern is on this attribute name and predicate.
  std::vector<int> schemata_for(const std::string& attribute, int predicate) const;
};

struct FactDef {
  std::string label;
  int object = -1, attribute = -1, predicate = -1;
  std::vector<PatternArgument> arguments;  // constants or any
  ModelTime start_lb = 0, start_ub = kNoBound, end_lb = 0, end_ub = kNoBound;
  ModelTime duration_lb = 0, duration_ub = kNoBound;
  bool initial = false, optional = false;
  double penalty = 0;
  std::string where;  // "file:line" of the statement, for explanations
};

struct FactRelationDef {
  int from = -1, to = -1;  // indices in PlanningProblem::facts
  pb::TemporalRelation::Kind relation;
  ModelTime lb = 0, ub = kNoBound;
  std::string where;
};

struct ObjectDef {
  std::string name;
  int class_index = -1;
};

struct PlanningProblem {
  std::string name;
  ModelTime horizon = 0;
  std::vector<ObjectDef> objects;
  std::vector<FactDef> facts;  // initial values first, then goals
  std::vector<FactRelationDef> relations;
  pb::Problem::Objective objective = pb::Problem::NONE;
  int object(const std::string& name) const;
};

// Checks the model; every mistake with its location. Empty optional when there is any.
std::optional<DomainModel> build_domain_model(const pb::Model& model, Diagnostics* errors);
std::optional<PlanningProblem> build_problem(const DomainModel& model, const pb::Problem& problem,
                                             Diagnostics* errors);

// The language's name of a temporal relation ("containedBy").
const char* relation_name(pb::TemporalRelation::Kind kind);

// Text of a parameter value for plans and messages (enumeration name, object name, number).
std::string value_text(const DomainModel& model, const PlanningProblem& problem,
                       const ParameterType& type, double value);

}  // namespace autonomy::planner
