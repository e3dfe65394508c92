#pragma once
// JSON for scheduling problems and schedules (docs/courier-scheduling.md has the schema): read by
// the courier_schedule tool, written by it and by the node's schedule topic. Every error names the
// JSON path ("/jobs/2/delivery/location: no location 'A-112'") or, for unparsable text, the line
// and column.
#include "services/courier/core/scheduler/job_schedule.hpp"
#include "services/courier/core/scheduler/scheduling_problem.hpp"

#include <nlohmann/json_fwd.hpp>

#include <optional>
#include <string>

namespace autonomy::courier::scheduling {

struct [[nodiscard]] ParsedProblem {
  SchedulingProblem problem;
  std::string error;
  bool ok() const { return error.empty(); }
};

// `base_dir` resolves a relative map YAML path ("map": {"yaml": ...}).
ParsedProblem problem_from_json(const nlohmann::json& document, const std::string& base_dir);
// `name` labels errors ("problem.json:3:14: ...").
ParsedProblem problem_from_json_text(const std::string& text, const std::string& name,
                                     const std::string& base_dir);

// The schedule with names instead of indices, times as seconds and as HH:MM:SS.
nlohmann::json schedule_to_json(const SchedulingProblem& problem, const JobSchedule& schedule);

// "HH:MM" or "HH:MM:SS" (24 h) to seconds of the day; nullopt if malformed.
std::optional<double> parse_time_of_day(const std::string& text);
// Seconds of the day to "HH:MM:SS" (rounded to the second; past midnight "+1d" is appended).
std::string format_time_of_day(double seconds);

}  // namespace autonomy::courier::scheduling
