#pragma once
// A job-shop file (OR-Library format) read into the planner's model and problem for the
// benchmarks; the reader's errors go to standard error.
#include <cstdio>
#include <optional>
#include <string>

#include "domain_model.hpp"
#include "jobshop_instance.hpp"
#include "planner_language.hpp"

namespace autonomy::bench {

struct JobShopFile {
  planner::JobShopInstance instance;
  planner::DomainModel model;
  planner::PlanningProblem problem;
};

inline std::optional<JobShopFile> read_jobshop_file(const std::string& file) {
  using namespace planner;
  Diagnostics errors;
  auto text = read_text_file(file, &errors);
  auto inst = text ? parse_jobshop(*text, file, &errors) : std::nullopt;
  auto model = inst ? build_domain_model(jobshop_model(*inst), &errors) : std::nullopt;
  auto problem = model ? build_problem(*model, jobshop_problem(*inst), &errors) : std::nullopt;
  if (!problem) {
    std::fprintf(stderr, "%s", to_string(errors).c_str());
    return std::nullopt;
  }
  return JobShopFile{*inst, *model, *problem};
}

}  // namespace autonomy::bench
