#pragma once
// The planner's output: a flexible plan. Per timeline its tokens in order, each with bounds on
// its start, end and duration (the minimal network's, so any time inside can still be
// completed), its parameters, and the temporal constraints between token timepoints, which an
// executive dispatches as times come (propagating each observed time through them).
#include <cstdint>
#include <string>
#include <vector>

#include "idl/planner_model.pb.h"

namespace autonomy::planner {

class TokenNetwork;

struct PlanToken {
  std::uint32_t id = 0;
  std::string object, attribute, predicate;
  std::vector<std::string> parameters;                      // values, sets or intervals, as text
  std::vector<std::pair<double, double>> parameter_bounds;  // lo, hi (enumeration indices)
  std::int64_t start_lb = 0, start_ub = 0, end_lb = 0, end_ub = 0, duration_lb = 0, duration_ub = 0;
  std::string origin;      // "initial <label>", "goal <label>" or "<relation> of token <id>"
  int fact = -1;           // the problem fact it achieves, or -1
  std::vector<int> facts;  // every fact it achieves (goals merged into one token), fact first
  std::string timeline() const { return object + "." + attribute; }
};

struct PlanTimeline {
  std::string name;
  std::vector<std::uint32_t> tokens;  // indices into FlexiblePlan::tokens, in time order
};

struct PlanConstraint {
  std::string from, to;  // "origin", "<id>.start", "<id>.end"
  std::int64_t lb = 0, ub = 0;
};

struct FlexiblePlan {
  std::int64_t horizon = 0;
  std::vector<PlanTimeline> timelines;
  std::vector<PlanToken> tokens;
  std::vector<PlanConstraint> constraints;
  std::int64_t makespan = 0;  // the earliest completion (every timepoint at its earliest time)
  double penalty = 0;
  std::vector<std::string> omitted_goals;
};

// Reads the plan of a network without flaws (merged tokens appear once, as their target).
FlexiblePlan extract_plan(const TokenNetwork& network);
pb::FlexiblePlan to_message(const FlexiblePlan& plan);

}  // namespace autonomy::planner
