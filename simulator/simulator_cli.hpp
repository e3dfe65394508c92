#pragma once
// The simulator's command line: its flags and the node they describe. The simulator process
// (simulator/main.cpp) and the experiment's trial host (tools/experiments/runner/trial_host.cpp,
// which runs a simulator and its controllers in one process) parse the same flags the same way.
#include "common/service/service.hpp"
#include "simulator/dds/simulator_node.hpp"

#include <CLI/CLI.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace autonomy::sim {

inline constexpr const char* kSimulatorDescription =
    "World and clock simulator: robots, obstacles, lockstep or paced time";

class SimulatorCli {
 public:
  // Registers the simulator's own flags (the shared service flags are added by the caller).
  void add_options(CLI::App& app);
  // Loads the scenario, listens for another world (--world-check) and builds the node. Throws
  // std::runtime_error on a bad scenario or another world on the domain.
  std::unique_ptr<SimulatorNode> make_node(service::Service& service);

 private:
  std::vector<std::string> wait_for_;
  int64_t max_ticks_ = 0;
  std::string trajectory_;
  std::string picture_;
  std::string mode_override_;
  std::string metrics_;
  int radio_period_ = 1;
  bool stop_when_finished_ = false;
  bool without_robots_ = false;
  bool every_tick_ = false;
  double world_check_s_ = 1.0;
  double ack_timeout_s_ = 0;
};

}  // namespace autonomy::sim
