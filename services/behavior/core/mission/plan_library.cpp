#include "services/behavior/core/mission/plan_library.hpp"

#include "services/behavior/core/cost_to_go_field.hpp"
#include "services/behavior/core/occupancy_grid.hpp"

#include <map>
#include <stdexcept>
#include <utility>
#include <vector>

namespace autonomy::behavior {

PlanLibrary build_plan_library(const MissionSpec& mission, const WorldMap& map,
                               double resolution_m, double inflation_radius_m) {
  // Plan sets share work: the obstacles grid (polygons and rasters: the expensive part) is built
  // once, each constraint set's grid once on top of its predecessor, and a field once per
  // (constraint set, goal), e.g. when two plan sets differ only in their selection.
  using Layers = std::vector<std::string>;  // a constraint set: layers[0..k] of a plan set
  std::map<Layers, std::shared_ptr<const OccupancyGrid>> grids;
  std::map<std::pair<Layers, std::pair<double, double>>, std::shared_ptr<const CostToGoField>> fields;
  grids[{kObstaclesLayer}] = std::make_shared<const OccupancyGrid>(map, resolution_m, inflation_radius_m);

  PlanLibrary library;
  for (const PlanSetSpec& spec : mission.plan_sets) {
    if (spec.layers.empty() || spec.layers.front() != kObstaclesLayer) {
      throw std::invalid_argument("plan set " + spec.name + ": the first layer must be obstacles");
    }
    std::string name = kObstaclesLayer;
    Layers layers = {kObstaclesLayer};
    std::vector<Plan> plans;
    for (std::size_t k = 0; k < spec.layers.size(); ++k) {
      if (k > 0) {
        const std::string& layer_name = spec.layers[k];
        const ConstraintLayerSpec* layer = nullptr;
        for (const ConstraintLayerSpec& l : mission.layers) {
          if (l.name == layer_name) layer = &l;
        }
        if (layer == nullptr) {
          throw std::invalid_argument("plan set " + spec.name + ": unknown layer " + layer_name);
        }
        const Layers previous = layers;
        layers.push_back(layer_name);
        name += "+" + layer_name;
        if (grids.count(layers) == 0)
          grids[layers] = std::make_shared<const OccupancyGrid>(grids.at(previous)->with_areas(layer->areas));
      }
      auto& field = fields[{layers, {spec.goal.x(), spec.goal.y()}}];
      if (!field) field = std::make_shared<const CostToGoField>(*grids.at(layers), spec.goal);
      plans.push_back(Plan::from_field(name, field));
    }
    library[spec.name] = std::make_shared<const PlanSet>(spec.name, spec.goal, std::move(plans));
  }
  return library;
}

}  // namespace autonomy::behavior
