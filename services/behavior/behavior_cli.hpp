#pragma once
// The behavior controller's command line: its flags and the node they describe. The behavior
// process (services/behavior/main.cpp) and the experiment's trial host
// (tools/experiments/runner/trial_host.cpp, which runs a simulator and its controllers in one
// process) parse the same flags the same way.
#include "common/service/service.hpp"
#include "services/behavior/dds/behavior_node.hpp"

#include <CLI/CLI.hpp>

#include <memory>
#include <string>
#include <vector>

namespace autonomy::behavior {

inline constexpr const char* kBehaviorDescription = "Behavior controller for one robot: goals in, velocity commands out";

class BehaviorCli {
 public:
  // Registers the behavior's own flags (the shared service flags, --robot among them, are added by
  // the caller).
  void add_options(CLI::App& app);
  // Loads the plan, layer and mission files named and builds the node for the service's robot.
  // Throws std::runtime_error on a bad file or setting.
  std::unique_ptr<BehaviorNode> make_node(service::Service& service);

 private:
  BehaviorNodeOptions options_;
  std::vector<double> start_;
  std::vector<double> goal_;
  std::string goal_constraints_;
  std::string plans_file_;
  std::string layers_file_;
  std::string mission_file_;
  std::vector<std::string> capabilities_;
  std::string path_planner_ = "grid";
  std::string ompl_space_ = "reeds-shepp";
  double ompl_budget_ms_ = 50.0;
  bool turn_in_place_ = true;
};

}  // namespace autonomy::behavior
