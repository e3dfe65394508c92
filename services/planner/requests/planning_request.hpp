#pragma once
// A planning request from the wire, checked and run: the pure part of the planner service (no
// DDS, no threads, no clock; the node passes in when to stop and how much time has passed).
//
//   check_request  - field lengths (common/msg/text_limits.hpp), ids, exactly one model and one
//                    problem, a known engine, a sane budget: a rejection before any parsing
//   prepare_run    - parses the model and problem (text: file:line:column diagnostics; or the
//                    serialized protobuf), folds the executive's state into the initial values,
//                    and checks them with the model manager
//   run_planning   - make_plan with a termination built from the node's predicates, each better
//                    plan reported as progress, the reply with statistics, the plan, the
//                    validator's findings and, when infeasible, the conflicting statements
#include <functional>
#include <optional>
#include <string>
#include <variant>

#include "common/msg/planner.hpp"
#include "domain_model.hpp"
#include "planner.hpp"

namespace autonomy::planner {

struct RequestLimits {
  std::int64_t max_budget_ms = 600000;  // a longer budget is rejected (bad_budget)
};

// A rejected reply (status Rejected) echoing the request's id, clipped to its limit.
msg::PlanningReply rejected_reply(const msg::PlanningRequest& request, const std::string& reason,
                                  const std::string& detail);

// The rejection of a request that cannot be planned as it stands, or nothing.
std::optional<msg::PlanningReply> check_request(const msg::PlanningRequest& request,
                                                const RequestLimits& limits = {});

// A checked model and problem, ready to plan.
struct PreparedRun {
  DomainModel model;
  PlanningProblem problem;
};

// Parses and checks; a rejected reply (parse_error, invalid_protobuf, invalid_model,
// invalid_problem, invalid_state) with every diagnostic otherwise.
std::variant<PreparedRun, msg::PlanningReply> prepare_run(const msg::PlanningRequest& request);

struct RunControl {
  std::function<bool()> cancelled;    // a PlanningCancel arrived (or the service stops)
  std::function<bool()> out_of_time;  // the request's budget has passed
  std::function<double()> elapsed_ms;
  std::function<void(const msg::PlanningProgress&)> on_progress;
};

msg::PlanningReply run_planning(const msg::PlanningRequest& request, const PreparedRun& run,
                                const RunControl& control);

// "temporal conflict between: a; b; c" (or "search exhausted: no plan achieves together: a;
// b") -> {a, b, c}; any other explanation as one statement.
std::vector<std::string> conflicting_statements(const std::string& explanation);

}  // namespace autonomy::planner
