#pragma once
// Job-shop scheduling as timelines: reads an OR-Library instance ("jobs machines", then one
// line per job of (machine, duration) pairs; '#' comments) into a model (one Machine class
// whose attribute `busy` takes op(job, index)) and a problem (one object per machine, one goal
// per operation with its fixed duration, precedence before[0, +inf] inside each job, minimise
// the makespan).
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "diagnostic.hpp"
#include "idl/planner_model.pb.h"

namespace autonomy::planner {

struct JobShopInstance {
  int jobs = 0, machines = 0;
  // operations[j] = (machine, duration) in job order
  std::vector<std::vector<std::pair<int, long>>> operations;
  // Where each job's line is, so conflicts name it: the file and one line number per job.
  std::string file;
  std::vector<unsigned> job_lines;
  unsigned header_line = 1;
};

// Errors carry file:line:column of the field at fault. A UTF-8 byte-order mark is skipped;
// numbers that overflow and durations that add up to 2^52 ticks or more (the horizon's limit)
// are errors.
std::optional<JobShopInstance> parse_jobshop(std::string_view text, const std::string& file,
                                             Diagnostics* errors);
pb::Model jobshop_model(const JobShopInstance& instance);
pb::Problem jobshop_problem(const JobShopInstance& instance);
// Goal label of operation k of job j, as in the problem and the plan ("j2_o3").
std::string jobshop_label(int job, int operation);

}  // namespace autonomy::planner
