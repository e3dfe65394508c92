// plan_tool: builds and lists plan resource files (services/behavior/core/plan_resource.hpp).
//
//   plan_tool build (--scenario FILE | --map MAP.yaml) --goal X Y --name N [--constraint SET]
//                   [--layers MISSION_FILE] [--resolution R] [--radius R] [--append] --out plans.bin
//   plan_tool list plans.bin
//
// The grid is the one `behavior` builds for a robot of --radius at --resolution (inflation =
// radius + resolution), over the map the simulator publishes on autonomy/map (a scenario's
// rectangles) or a ROS map's occupied cells, so that behavior --plans finds and uses the plan.
#include "common/grid/map_loader.hpp"
#include "services/behavior/core/constraint_sets.hpp"
#include "services/behavior/core/mission/mission_loader.hpp"
#include "services/behavior/core/plan_resource.hpp"
#include "simulator/scenario/scenario_loader.hpp"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

using namespace autonomy;
using namespace autonomy::behavior;

namespace {

struct NamedMap {
  std::string name;
  WorldMap world;
};

// A ROS map as the world, its lower-left corner at (0, 0) whatever the YAML's origin says (plan
// coordinates are metres from that corner).
NamedMap from_ros_map(const grid::OccupancyMap& m, const std::string& name) {
  const auto& r = m.raster;
  auto placed = std::make_shared<grid::OccupancyRaster>(r.width(), r.height(), r.resolution_m());
  for (int row = 0; row < r.height(); ++row) {
    for (int col = 0; col < r.width(); ++col) {
      if (r.blocked({col, row})) placed->set_blocked({col, row}, true);
    }
  }
  return {name, WorldMap{r.width() * r.resolution_m(), r.height() * r.resolution_m(), {}, {}, {std::move(placed)}}};
}

int build(const std::string& scenario, const std::string& map_yaml, const std::vector<double>& goal,
          const std::string& name, const std::string& constraint, const std::string& layers_file, double resolution,
          double radius, bool append, const std::string& out) {
  NamedMap map;
  if (!scenario.empty()) {
    const auto loaded = sim::load_scenario_file(scenario);
    if (!loaded.ok()) {
      std::cerr << loaded.error_text() << "\n";
      return 1;
    }
    const auto& w = loaded.scenario->world;
    map = {w.name, WorldMap{w.width, w.height, w.obstacles, w.polygons, {}}};
    for (const auto& layer : w.rasters) map.world.rasters.push_back(layer.raster);
  } else {
    const auto loaded = grid::load_ros_map(map_yaml);
    if (!loaded.ok()) {
      std::cerr << loaded.error << "\n";
      return 1;
    }
    map = from_ros_map(*loaded.map, std::filesystem::path(map_yaml).stem().string());
  }
  ConstraintLayers layers;
  if (!layers_file.empty()) {
    const auto loaded = load_mission_file(layers_file);
    if (!loaded.ok()) {
      std::cerr << loaded.error_text() << "\n";
      return 1;
    }
    for (const auto& l : loaded.mission->layers) layers[l.name] = l.areas;
  }
  std::string error;
  const auto set = parse_constraint_set(constraint, &error);
  if (!set) {
    std::cerr << "plan_tool: " << error << "\n";
    return 1;
  }
  const auto world = apply_constraints(map.world, *set, layers, &error);
  if (!world) {
    std::cerr << "plan_tool: " << error << (layers_file.empty() ? " (give the layers with --layers MISSION)" : "")
              << "\n";
    return 1;
  }
  PlanResource resource;
  if (append && std::filesystem::exists(out)) {
    auto existing = load_plan_resource(out);
    if (!existing.ok()) {
      std::cerr << existing.error << "\n";
      return 1;
    }
    resource = std::move(*existing.resource);
    auto& plans = resource.plans;
    plans.erase(std::remove_if(plans.begin(), plans.end(), [&](const StoredPlan& p) { return p.name == name; }),
                plans.end());
  }
  const double inflation = radius + resolution;
  const auto t0 = std::chrono::steady_clock::now();
  std::optional<CostToGoField> field;
  try {
    field.emplace(OccupancyGrid(*world, resolution, inflation), geometry::Vec2(goal[0], goal[1]));
  } catch (const std::exception& e) {
    std::cerr << "plan_tool: " << e.what() << "\n";
    return 1;
  }
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  if (!field->has_route_anywhere()) {
    std::cerr << "plan_tool: goal (" << goal[0] << ", " << goal[1] << ") is blocked or outside the map with '"
              << set->name() << "'\n";
    return 1;
  }
  resource.plans.push_back(
      make_stored_plan(name, set->name(), map.name, world->width_m, world->height_m, inflation, *field));
  if (!save_plan_resource(out, resource, &error)) {
    std::cerr << error << "\n";
    return 1;
  }
  std::printf("%s: plan '%s' (%s) on map '%s', goal (%g, %g), %d x %d cells at %g m, computed in %.1f ms; %zu plan(s)\n",
              out.c_str(), name.c_str(), set->name().c_str(), map.name.c_str(), goal[0], goal[1],
              field->geometry().cols(), field->geometry().rows(), resolution, ms, resource.plans.size());
  return 0;
}

int list(const std::string& file) {
  const auto loaded = load_plan_resource(file);
  if (!loaded.ok()) {
    std::cerr << loaded.error << "\n";
    return 1;
  }
  std::printf("%s: %zu plan(s), format version %u\n", file.c_str(), loaded.resource->plans.size(),
              kPlanResourceVersion);
  for (const StoredPlan& p : loaded.resource->plans) {
    std::size_t reachable = 0;
    float max_cost = 0.0f;
    for (float c : p.costs) {
      if (std::isfinite(c)) {
        ++reachable;
        max_cost = std::max(max_cost, c);
      }
    }
    std::printf("  %-20s %-32s map '%s' %gx%g m  goal (%g, %g)  %u x %u @ %g m  inflation %g m  reachable %zu  max %.1f m\n",
                p.name.c_str(), p.constraint_set.c_str(), p.map_name.c_str(), p.world_width_m, p.world_height_m,
                p.goal.x(), p.goal.y(), p.cols, p.rows, p.resolution_m, p.inflation_radius_m, reachable, max_cost);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Builds and lists plan resource files (internalized plans for behavior --plans)", "plan_tool"};
  app.require_subcommand(1);

  auto* b = app.add_subcommand("build", "Compute one plan and write it into a plan file");
  std::string scenario, map_yaml, name, constraint, layers_file, out;
  std::vector<double> goal;
  double resolution = 0.1, radius = 0.3;
  bool append = false;
  auto* scen = b->add_option("--scenario", scenario, "Scenario file (its world as autonomy/map carries it)");
  auto* map = b->add_option("--map", map_yaml, "ROS map YAML (occupied and unknown cells are obstacles)");
  scen->excludes(map);
  b->add_option("--goal", goal, "Goal X Y in m")->expected(2)->required();
  b->add_option("--name", name, "Plan name (unique in the file)")->required();
  b->add_option("--constraint", constraint, "Constraint set, e.g. comm_attenuation (default: obstacles)");
  b->add_option("--layers", layers_file, "Mission file defining the constraint layers");
  b->add_option("--resolution", resolution, "Grid resolution in m")->check(CLI::Range(0.01, 5.0))->capture_default_str();
  b->add_option("--radius", radius, "Robot radius in m")->check(CLI::NonNegativeNumber)->capture_default_str();
  b->add_flag("--append", append, "Add to (or replace a plan of the same name in) an existing file");
  b->add_option("--out", out, "Plan file to write")->required();

  auto* l = app.add_subcommand("list", "List the plans of a plan file");
  std::string file;
  l->add_option("file", file, "Plan file")->required();

  CLI11_PARSE(app, argc, argv);
  if (b->parsed()) {
    if (scenario.empty() && map_yaml.empty()) {
      std::cerr << "plan_tool build: give --scenario or --map\n";
      return 2;
    }
    return build(scenario, map_yaml, goal, name, constraint, layers_file, resolution, radius, append, out);
  }
  return list(file);
}
