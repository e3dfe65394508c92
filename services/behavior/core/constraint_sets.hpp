#pragma once
// Constraint sets: which plan layers a route must honour (NavGoal.constraint_set, plan resource
// files, mission plan sets). A set is written as layer names joined by '+'; "obstacles" (the map's
// own obstacles) is always part of it, so "", "obstacles", "comm_attenuation" and
// "obstacles+comm_attenuation" are all valid spellings. The canonical name starts with
// "obstacles" and keeps the given order, exactly as build_plan_library names its plans.
//
// A layer is a list of rectangles that the route treats as extra obstacles (grown by the same
// inflation radius as the map's), e.g. a mission's communication-attenuating areas.
#include "common/geometry/geometry.hpp"
#include "services/behavior/core/world_map.hpp"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace autonomy::behavior {

using ConstraintLayers = std::map<std::string, std::vector<geometry::Rect>>;

inline constexpr const char* kObstaclesConstraint = "obstacles";

struct ConstraintSet {
  std::vector<std::string> layers;  // the extra layers, "obstacles" excluded, no duplicates
  // "obstacles" or "obstacles+a+b".
  std::string name() const;
};

// Splits and normalises; nullopt with *error set on an empty piece ("a++b", "+a").
std::optional<ConstraintSet> parse_constraint_set(const std::string& text, std::string* error = nullptr);

// The map plus every layer of the set as extra obstacles; nullopt with *error naming the unknown
// layer (and the known ones) when a layer is not in `known`.
std::optional<WorldMap> apply_constraints(const WorldMap& map, const ConstraintSet& set,
                                          const ConstraintLayers& known, std::string* error = nullptr);

}  // namespace autonomy::behavior
