#pragma once
// A shipped job-shop instance (examples/jobshop), or an instance's text, as a model and a
// problem, for the engines' tests; a reading error fails the calling test.
#include <gtest/gtest.h>

#include <optional>
#include <string>

#include "jobshop_instance.hpp"
#include "planner_language.hpp"

namespace autonomy::planner {

struct ShippedShop {
  DomainModel model;
  PlanningProblem problem;
};

// A job-shop instance's text (named `file` in errors) as a model and a problem.
inline std::optional<ShippedShop> jobshop_from_text(const std::string& text,
                                                    const std::string& file) {
  Diagnostics errors;
  auto inst = parse_jobshop(text, file, &errors);
  auto model = inst ? build_domain_model(jobshop_model(*inst), &errors) : std::nullopt;
  auto problem = model ? build_problem(*model, jobshop_problem(*inst), &errors) : std::nullopt;
  if (!problem) {
    ADD_FAILURE() << to_string(errors);
    return std::nullopt;
  }
  return ShippedShop{*model, *problem};
}

inline std::optional<ShippedShop> load_shipped_jobshop(const std::string& name) {
  Diagnostics errors;
  const std::string file = std::string(PLANNER_EXAMPLES_DIR "/jobshop/") + name;
  auto text = read_text_file(file, &errors);
  if (!text) {
    ADD_FAILURE() << to_string(errors);
    return std::nullopt;
  }
  return jobshop_from_text(*text, file);
}

}  // namespace autonomy::planner
