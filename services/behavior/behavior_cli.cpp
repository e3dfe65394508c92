#include "services/behavior/behavior_cli.hpp"

#include "services/behavior/core/mission/mission_loader.hpp"

#include <stdexcept>

namespace autonomy::behavior {

void BehaviorCli::add_options(CLI::App& app) {
  app.add_option("--start", start_, "Spawn pose X Y [THETA] (default: the scenario's start for this robot)")
      ->expected(2, 3);
  app.add_option("--goal", goal_, "Goal X Y to pursue as soon as the robot is ready")->expected(2);
  app.add_option("--constraint", goal_constraints_, "Constraint set of --goal (e.g. comm_attenuation)");
  app.add_option("--resolution", options_.grid_resolution_m, "Planning grid resolution in m")
      ->check(CLI::Range(0.01, 5.0))
      ->capture_default_str();
  app.add_option("--stall-timeout", options_.tracker.stall_timeout_s,
                 "Seconds without progress before a goal is blocked")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--collision-timeout", options_.tracker.collision_timeout_s,
                 "Seconds continuously in collision before a goal is blocked (0: never)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_option("--plans", plans_file_,
                 "Plan resource file (plan_tool build): stored plans used when goal and constraint set match");
  app.add_option("--layers", layers_file_,
                 "Mission file whose constraint layers goals may name in constraint_set");
  app.add_flag("--traffic,!--no-traffic", options_.traffic,
               "Fleet traffic (docs/traffic.md): publish an itinerary, reserve narrow passages, plan around "
               "robots that hold nothing (goal mode; default on)");
  app.add_option("--door-memory", options_.doors.memory_s,
                 "Seconds a door seen closed is planned around without being seen again")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--contact-loss-after", options_.contact.loss_after_s,
                 "Seconds a radio link must stay down before a mission counts the teammate as lost")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_option("--contact-restore-after", options_.contact.restore_after_s,
                 "Seconds a radio link must stay up before a mission counts the teammate as back")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_option("--capability", capabilities_,
                 "Announce this capability in the heartbeat (repeatable), e.g. courier: the courier "
                 "service then takes the robot into its fleet")
      ->check(CLI::Validator(
          [](std::string& s) { return s.empty() || s.size() > 64 ? std::string("1..64 characters") : std::string(); },
          "NAME"));
  app.add_option("--path-planner", path_planner_,
                 "Go-to paths: grid (the cost-to-go field's controller) or ompl (a continuous path "
                 "planned in SE(2), followed by pure pursuit)")
      ->check(CLI::IsMember({"grid", "ompl"}))
      ->capture_default_str();
  app.add_option("--ompl-planner", options_.path.ompl.planner,
                 "OMPL planner by name (RRTConnect, RRT, RRTstar, InformedRRTstar, PRMstar, BITstar, KPIECE1)")
      ->capture_default_str();
  app.add_option("--ompl-space", ompl_space_,
                 "OMPL state space: reeds-shepp (forward and reverse), dubins (forward only), se2 (holonomic)")
      ->check(CLI::IsMember({"reeds-shepp", "dubins", "se2"}))
      ->capture_default_str();
  app.add_option("--ompl-budget-ms", ompl_budget_ms_, "Planning time per go-to path in ms")
      ->check(CLI::Range(1.0, 60000.0))
      ->capture_default_str();
  app.add_option("--turning-radius", options_.path.ompl.turning_radius_m,
                 "Minimum turning radius of reeds-shepp and dubins paths in m")
      ->check(CLI::Range(0.01, 100.0))
      ->capture_default_str();
  app.add_option("--ompl-turn-in-place", turn_in_place_,
                 "Unicycles turn on the spot at the start of a path instead of manoeuvring (true/false)")
      ->capture_default_str();
  app.add_option("--ompl-route-guide", options_.path.ompl.route_guide,
                 "Try the grid route as a guide before sampling (true/false)")
      ->capture_default_str();
  app.add_option("--journal", options_.journal_path,
                 "SQLite journal of the goals (or the mission's progress): started again with the same "
                 "file, the behavior drives on the goal it was pursuing or continues its mission where it was");
  auto* mission = app.add_option("--mission", mission_file_,
                                 "Run this mission (idl/mission.proto text) instead of taking goals");
  // A mission builds its own plans from its plan sets and takes no goals: these would be ignored.
  for (const char* goal_mode_only : {"--goal", "--constraint", "--plans", "--layers", "--path-planner"})
    mission->excludes(app.get_option(goal_mode_only));
}

std::unique_ptr<BehaviorNode> BehaviorCli::make_node(service::Service& service) {
  options_.robot_id = service.options().instance;
  service.set_capabilities(capabilities_);
  options_.path.planner = path_planner_ == "ompl" ? GoToPlanner::Ompl : GoToPlanner::GridField;
  options_.path.ompl.curve = ompl_space_ == "dubins" ? CurveModel::Dubins
                            : ompl_space_ == "se2"  ? CurveModel::Holonomic
                                                   : CurveModel::ReedsShepp;
  options_.path.budget_s = ompl_budget_ms_ * 1e-3;
  options_.path.unicycle_turns_in_place = turn_in_place_;
  if (auto problem = settings_problem(options_.path.ompl)) throw std::runtime_error("--ompl-*: " + *problem);
  if (options_.path.planner == GoToPlanner::Ompl && options_.path.ompl.curve == CurveModel::Dubins)
    spdlog::warn("--ompl-space dubins: OMPL 1.5.2's Dubins space can abort on an internal assertion (dubinsRSR)");
  if (!start_.empty()) options_.start = geometry::Pose2{start_[0], start_[1], start_.size() > 2 ? start_[2] : 0.0};
  if (!goal_.empty())
    options_.initial_goal = msg::NavGoal{options_.robot_id, "cli-goal", goal_[0], goal_[1], 0.0, goal_constraints_};
  if (!plans_file_.empty()) {
    auto loaded = load_plan_resource(plans_file_);
    if (!loaded.ok()) throw std::runtime_error(loaded.error);
    spdlog::info("{}: {} stored plans", plans_file_, loaded.resource->plans.size());
    options_.plans = std::move(loaded.resource);
  }
  if (!layers_file_.empty()) {
    auto loaded = load_mission_file(layers_file_);
    if (!loaded.ok()) throw std::runtime_error(loaded.error_text());
    for (const auto& l : loaded.mission->layers) options_.layers[l.name] = l.areas;
  }
  if (!mission_file_.empty()) {
    auto loaded = load_mission_file(mission_file_);
    if (!loaded.ok()) throw std::runtime_error("mission file has errors:\n" + loaded.error_text());
    if (!loaded.mission->robot.empty() && loaded.mission->robot != options_.robot_id) {
      throw std::runtime_error(mission_file_ + ": the mission is for robot " + loaded.mission->robot +
                               ", not " + options_.robot_id);
    }
    spdlog::info("mission '{}' from {}: {} states, {} plan sets", loaded.mission->name, mission_file_,
                 loaded.mission->states.size(), loaded.mission->plan_sets.size());
    options_.mission = std::move(loaded.mission);
  }
  return std::make_unique<BehaviorNode>(service, options_);
}

}  // namespace autonomy::behavior
