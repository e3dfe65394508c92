// The behavior controller process: drives one robot (--robot ID) to the goals it receives, or
// runs a mission for it (--mission FILE).
#include "services/behavior/core/mission/mission_loader.hpp"
#include "services/behavior/dds/behavior_node.hpp"

#include <memory>
#include <stdexcept>

using namespace autonomy;

int main(int argc, char** argv) {
  behavior::BehaviorNodeOptions options;
  std::vector<double> start;
  std::vector<double> goal;
  std::string goal_constraints;
  std::string plans_file;
  std::string layers_file;
  std::string mission_file;
  std::vector<std::string> capabilities;
  std::string path_planner = "grid";
  std::string ompl_space = "reeds-shepp";
  double ompl_budget_ms = 50.0;
  bool turn_in_place = true;
  return service::run_service(
      argc, argv, "behavior", "Behavior controller for one robot: goals in, velocity commands out",
      service::InstanceFlag::Robot,
      [&](CLI::App& app) {
        app.add_option("--start", start, "Spawn pose X Y [THETA] (default: the scenario's start for this robot)")
            ->expected(2, 3);
        app.add_option("--goal", goal, "Goal X Y to pursue as soon as the robot is ready")->expected(2);
        app.add_option("--constraint", goal_constraints, "Constraint set of --goal (e.g. comm_attenuation)");
        app.add_option("--resolution", options.grid_resolution_m, "Planning grid resolution in m")
            ->check(CLI::Range(0.01, 5.0))
            ->capture_default_str();
        app.add_option("--stall-timeout", options.tracker.stall_timeout_s,
                       "Seconds without progress before a goal is blocked")
            ->check(CLI::PositiveNumber)
            ->capture_default_str();
        app.add_option("--collision-timeout", options.tracker.collision_timeout_s,
                       "Seconds continuously in collision before a goal is blocked (0: never)")
            ->check(CLI::NonNegativeNumber)
            ->capture_default_str();
        app.add_option("--plans", plans_file,
                       "Plan resource file (plan_tool build): stored plans used when goal and constraint set match");
        app.add_option("--layers", layers_file,
                       "Mission file whose constraint layers goals may name in constraint_set");
        app.add_flag("--traffic,!--no-traffic", options.traffic,
                     "Fleet traffic (docs/traffic.md): publish an itinerary, reserve narrow passages, plan around "
                     "robots that hold nothing (goal mode; default on)");
        app.add_option("--door-memory", options.doors.memory_s,
                       "Seconds a door seen closed is planned around without being seen again")
            ->check(CLI::PositiveNumber)
            ->capture_default_str();
        app.add_option("--contact-loss-after", options.contact.loss_after_s,
                       "Seconds a radio link must stay down before a mission counts the teammate as lost")
            ->check(CLI::NonNegativeNumber)
            ->capture_default_str();
        app.add_option("--contact-restore-after", options.contact.restore_after_s,
                       "Seconds a radio link must stay up before a mission counts the teammate as back")
            ->check(CLI::NonNegativeNumber)
            ->capture_default_str();
        app.add_option("--capability", capabilities,
                       "Announce this capability in the heartbeat (repeatable), e.g. courier: the courier "
                       "service then takes the robot into its fleet")
            ->check(CLI::Validator(
                [](std::string& s) { return s.empty() || s.size() > 64 ? std::string("1..64 characters") : std::string(); },
                "NAME"));
        app.add_option("--path-planner", path_planner,
                       "Go-to paths: grid (the cost-to-go field's controller) or ompl (a continuous path "
                       "planned in SE(2), followed by pure pursuit)")
            ->check(CLI::IsMember({"grid", "ompl"}))
            ->capture_default_str();
        app.add_option("--ompl-planner", options.path.ompl.planner,
                       "OMPL planner by name (RRTConnect, RRT, RRTstar, InformedRRTstar, PRMstar, BITstar, KPIECE1)")
            ->capture_default_str();
        app.add_option("--ompl-space", ompl_space,
                       "OMPL state space: reeds-shepp (forward and reverse), dubins (forward only), se2 (holonomic)")
            ->check(CLI::IsMember({"reeds-shepp", "dubins", "se2"}))
            ->capture_default_str();
        app.add_option("--ompl-budget-ms", ompl_budget_ms, "Planning time per go-to path in ms")
            ->check(CLI::Range(1.0, 60000.0))
            ->capture_default_str();
        app.add_option("--turning-radius", options.path.ompl.turning_radius_m,
                       "Minimum turning radius of reeds-shepp and dubins paths in m")
            ->check(CLI::Range(0.01, 100.0))
            ->capture_default_str();
        app.add_option("--ompl-turn-in-place", turn_in_place,
                       "Unicycles turn on the spot at the start of a path instead of manoeuvring (true/false)")
            ->capture_default_str();
        app.add_option("--ompl-route-guide", options.path.ompl.route_guide,
                       "Try the grid route as a guide before sampling (true/false)")
            ->capture_default_str();
        app.add_option("--journal", options.journal_path,
                       "SQLite journal of the goals (or the mission's progress): started again with the same "
                       "file, the behavior drives on the goal it was pursuing or continues its mission where it was");
        auto* mission = app.add_option("--mission", mission_file,
                                       "Run this mission (idl/mission.proto text) instead of taking goals");
        // A mission builds its own plans from its plan sets and takes no goals: these would be ignored.
        for (const char* goal_mode_only : {"--goal", "--constraint", "--plans", "--layers", "--path-planner"})
          mission->excludes(app.get_option(goal_mode_only));
      },
      [&](service::Service& service) {
        options.robot_id = service.options().instance;
        service.set_capabilities(capabilities);
        options.path.planner = path_planner == "ompl" ? behavior::GoToPlanner::Ompl : behavior::GoToPlanner::GridField;
        options.path.ompl.curve = ompl_space == "dubins" ? behavior::CurveModel::Dubins
                                  : ompl_space == "se2"  ? behavior::CurveModel::Holonomic
                                                         : behavior::CurveModel::ReedsShepp;
        options.path.budget_s = ompl_budget_ms * 1e-3;
        options.path.unicycle_turns_in_place = turn_in_place;
        if (auto problem = behavior::settings_problem(options.path.ompl)) throw std::runtime_error("--ompl-*: " + *problem);
        if (options.path.planner == behavior::GoToPlanner::Ompl && options.path.ompl.curve == behavior::CurveModel::Dubins)
          spdlog::warn("--ompl-space dubins: OMPL 1.5.2's Dubins space can abort on an internal assertion (dubinsRSR)");
        if (!start.empty()) options.start = geometry::Pose2{start[0], start[1], start.size() > 2 ? start[2] : 0.0};
        if (!goal.empty())
          options.initial_goal = msg::NavGoal{options.robot_id, "cli-goal", goal[0], goal[1], 0.0, goal_constraints};
        if (!plans_file.empty()) {
          auto loaded = behavior::load_plan_resource(plans_file);
          if (!loaded.ok()) throw std::runtime_error(loaded.error);
          spdlog::info("{}: {} stored plans", plans_file, loaded.resource->plans.size());
          options.plans = std::move(loaded.resource);
        }
        if (!layers_file.empty()) {
          auto loaded = behavior::load_mission_file(layers_file);
          if (!loaded.ok()) throw std::runtime_error(loaded.error_text());
          for (const auto& l : loaded.mission->layers) options.layers[l.name] = l.areas;
        }
        if (!mission_file.empty()) {
          auto loaded = behavior::load_mission_file(mission_file);
          if (!loaded.ok()) throw std::runtime_error("mission file has errors:\n" + loaded.error_text());
          if (!loaded.mission->robot.empty() && loaded.mission->robot != options.robot_id) {
            throw std::runtime_error(mission_file + ": the mission is for robot " + loaded.mission->robot +
                                     ", not " + options.robot_id);
          }
          spdlog::info("mission '{}' from {}: {} states, {} plan sets", loaded.mission->name, mission_file,
                       loaded.mission->states.size(), loaded.mission->plan_sets.size());
          options.mission = std::move(loaded.mission);
        }
        return std::make_unique<behavior::BehaviorNode>(service, options);
      });
}
