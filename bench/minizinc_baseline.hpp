#pragma once
// The job-shop baseline of the planner benchmarks: MiniZinc with Gecode on the standard
// disjunctive model (bench/jobshop.mzn; bench/install-minizinc.sh installs them).
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "jobshop_instance.hpp"

namespace autonomy::bench {

// A shell command's standard output; nullopt when it could not run or exited non-zero.
std::optional<std::string> run_command(const std::string& command);

// True when `minizinc --solvers` lists Gecode.
bool minizinc_with_gecode();

struct Baseline {
  bool ran = false, proved = false;
  long makespan = -1;
  double seconds = 0;         // the whole minizinc run (flattening included)
  double solve_seconds = -1;  // Gecode's own solve time, when it reports it
  // Every improving solution: (seconds since minizinc started, flattening included; makespan).
  std::vector<std::pair<double, long>> curve;
};

// One instance through `minizinc --solver gecode` with the data written from the parsed
// instance, stopped after `seconds`.
Baseline run_minizinc(const std::string& model, const planner::JobShopInstance& inst,
                      const std::string& name, int seconds);

}  // namespace autonomy::bench
