// The behavior controller process: drives one robot (--robot ID) to the goals it receives, or
// runs a mission for it (--mission FILE).
#include "services/behavior/behavior_cli.hpp"

using namespace autonomy;

int main(int argc, char** argv) {
  behavior::BehaviorCli cli;
  return service::run_service(
      argc, argv, "behavior", behavior::kBehaviorDescription, service::InstanceFlag::Robot,
      [&](CLI::App& app) { cli.add_options(app); }, [&](service::Service& service) { return cli.make_node(service); });
}
