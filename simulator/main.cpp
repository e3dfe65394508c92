// The simulator process: owns the world's ground truth and its clock.
#include "simulator/simulator_cli.hpp"

using namespace autonomy;

int main(int argc, char** argv) {
  sim::SimulatorCli cli;
  return service::run_service(
      argc, argv, "simulator", sim::kSimulatorDescription, service::InstanceFlag::Instance,
      [&](CLI::App& app) { cli.add_options(app); }, [&](service::Service& service) { return cli.make_node(service); });
}
