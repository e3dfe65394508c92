// The behavior controller process: drives one robot (--robot ID) to the goals it receives.
#include "services/behavior/dds/behavior_node.hpp"

#include <memory>

using namespace autonomy;

int main(int argc, char** argv) {
  behavior::BehaviorNodeOptions options;
  std::vector<double> start;
  std::vector<double> goal;
  return service::run_service(
      argc, argv, "behavior", "Behavior controller for one robot: goals in, velocity commands out",
      service::InstanceFlag::Robot,
      [&](CLI::App& app) {
        app.add_option("--start", start, "Spawn pose X Y [THETA] (default: the scenario's start for this robot)")
            ->expected(2, 3);
        app.add_option("--goal", goal, "Goal X Y to pursue as soon as the robot is ready")->expected(2);
        app.add_option("--resolution", options.grid_resolution_m, "Planning grid resolution in m")
            ->check(CLI::Range(0.01, 5.0))
            ->capture_default_str();
        app.add_option("--stall-timeout", options.tracker.stall_timeout_s,
                       "Seconds without progress before a goal fails")
            ->check(CLI::PositiveNumber)
            ->capture_default_str();
      },
      [&](service::Service& service) {
        options.robot_id = service.options().instance;
        if (!start.empty()) options.start = geometry::Pose2{start[0], start[1], start.size() > 2 ? start[2] : 0.0};
        if (!goal.empty()) options.initial_goal = msg::NavGoal{options.robot_id, "cli-goal", goal[0], goal[1], 0.0};
        return std::make_unique<behavior::BehaviorNode>(service, options);
      });
}
