#include "services/behavior/core/mission/plan_library.hpp"

#include "services/behavior/core/cost_to_go_field.hpp"
#include "services/behavior/core/occupancy_grid.hpp"

#include <stdexcept>
#include <utility>
#include <vector>

namespace autonomy::behavior {

PlanLibrary build_plan_library(const MissionSpec& mission, const WorldMap& map,
                               double resolution_m, double inflation_radius_m) {
  PlanLibrary library;
  for (const PlanSetSpec& spec : mission.plan_sets) {
    if (spec.layers.empty() || spec.layers.front() != kObstaclesLayer) {
      throw std::invalid_argument("plan set " + spec.name + ": the first layer must be obstacles");
    }
    WorldMap world = map;
    std::string name = kObstaclesLayer;
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
        world.obstacles.insert(world.obstacles.end(), layer->areas.begin(), layer->areas.end());
        name += "+" + layer_name;
      }
      auto field = std::make_shared<const CostToGoField>(
          OccupancyGrid(world, resolution_m, inflation_radius_m), spec.goal);
      plans.push_back(Plan::from_field(name, std::move(field)));
    }
    library[spec.name] = std::make_shared<const PlanSet>(spec.name, spec.goal, std::move(plans));
  }
  return library;
}

}  // namespace autonomy::behavior
