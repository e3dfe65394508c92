#pragma once
// C++ value types of idl/planner.idl: planning requests, replies, progress, cancellation and the
// latest plan. services/planner/messages converts the plan to and from the planner's own
// FlexiblePlan.
#include <cstdint>
#include <string>
#include <vector>

namespace autonomy::msg {

struct PlannerTimelineValue {
  std::string timeline;
  std::string predicate;
  std::vector<std::string> parameters;
};

struct PlanningRequest {
  std::string request_id;
  std::string requester;
  std::string model_file;
  std::string model_text;
  std::vector<uint8_t> model_protobuf;
  std::string problem_file;
  std::string problem_text;
  std::vector<uint8_t> problem_protobuf;
  std::vector<PlannerTimelineValue> state;
  int64_t plan_origin = 0;
  std::string engine;
  uint32_t seed = 0;
  int64_t budget_ms = 0;
  int64_t max_decisions = 0;
};

enum class PlanningStatus { Optimal, PlanFound, Infeasible, OutOfTime, Cancelled, Rejected };

struct PlannerDiagnostic {
  std::string file;
  uint32_t line = 0;
  uint32_t column = 0;
  std::string message;
};

struct PlanningStatistics {
  uint64_t decisions = 0;
  uint64_t backtracks = 0;
  uint64_t dead_ends = 0;
  uint64_t temporal_propagations = 0;
  uint64_t procedure_calls = 0;
  uint32_t improvements = 0;
  double elapsed_ms = 0.0;
};

struct PlanToken {
  uint32_t id = 0;
  std::string object;
  std::string attribute;
  std::string predicate;
  std::vector<std::string> parameters;
  std::vector<double> parameter_lo;
  std::vector<double> parameter_hi;
  int64_t start_lb = 0;
  int64_t start_ub = 0;
  int64_t end_lb = 0;
  int64_t end_ub = 0;
  int64_t duration_lb = 0;
  int64_t duration_ub = 0;
  std::string origin;
  int32_t fact = -1;
};

struct PlanTimeline {
  std::string name;
  std::vector<uint32_t> tokens;
};

struct PlanConstraint {
  std::string from;
  std::string to;
  int64_t lb = 0;
  int64_t ub = 0;
};

struct FlexiblePlan {
  int64_t horizon = 0;
  int64_t makespan = 0;
  double penalty = 0.0;
  std::vector<std::string> omitted_goals;
  std::vector<PlanTimeline> timelines;
  std::vector<PlanToken> tokens;
  std::vector<PlanConstraint> constraints;
};

struct PlanningReply {
  std::string request_id;
  std::string requester;
  PlanningStatus status = PlanningStatus::Rejected;
  std::string reason;
  std::string detail;
  std::vector<PlannerDiagnostic> diagnostics;
  std::vector<std::string> conflicts;
  std::string engine;
  bool has_plan = false;
  FlexiblePlan plan;
  std::vector<std::string> violations;
  PlanningStatistics statistics;
  int64_t plan_origin = 0;
};

struct PlanningProgress {
  std::string request_id;
  uint32_t improvement = 0;
  int64_t makespan = 0;
  double penalty = 0.0;
  uint32_t tokens = 0;
  double elapsed_ms = 0.0;
};

struct PlanningCancel {
  std::string request_id;
  std::string requester;
};

struct LatestPlan {
  std::string requester;
  std::string request_id;
  PlanningStatus status = PlanningStatus::PlanFound;
  std::string engine;
  int64_t plan_origin = 0;
  FlexiblePlan plan;
};

const char* to_string(PlanningStatus s);

}  // namespace autonomy::msg
