#pragma once
// Builds the internalized plans a mission names, once, before the mission runs (the paper's
// "resource file ... may contain any number of plans based on different sets of constraints").
// Pure computation on values the node already holds: the map from autonomy/map and the mission's
// constraint layers; nothing is read from files here.
//
// Plan k of a plan set avoids layers[0..k]: layers[0] ("obstacles") is the map's own obstacles, each
// further layer adds its areas as extra obstacles. All of them are grown by the same inflation
// radius, so the robot's centre keeps clear of an attenuating area as it does of a wall.
#include "services/behavior/core/mission/mission_spec.hpp"
#include "services/behavior/core/schemas/plan_set.hpp"
#include "services/behavior/core/world_map.hpp"

#include <map>
#include <memory>
#include <string>

namespace autonomy::behavior {

using PlanLibrary = std::map<std::string, std::shared_ptr<const PlanSet>>;

// Plan names join the layers: "obstacles", "obstacles+comm_attenuation", ...
// Throws std::invalid_argument when a plan set names a layer the mission does not define, when
// layers[0] is not "obstacles", or when the grid parameters are invalid (OccupancyGrid).
[[nodiscard]] PlanLibrary build_plan_library(const MissionSpec& mission, const WorldMap& map,
                                             double resolution_m, double inflation_radius_m);

}  // namespace autonomy::behavior
