#include "services/behavior/core/constraint_sets.hpp"

#include <algorithm>

namespace autonomy::behavior {

std::string ConstraintSet::name() const {
  std::string out = kObstaclesConstraint;
  for (const std::string& l : layers) out += "+" + l;
  return out;
}

std::optional<ConstraintSet> parse_constraint_set(const std::string& text, std::string* error) {
  ConstraintSet set;
  if (text.empty()) return set;
  std::size_t start = 0;
  for (;;) {
    const std::size_t plus = text.find('+', start);
    const std::string piece = text.substr(start, plus == std::string::npos ? std::string::npos : plus - start);
    if (piece.empty()) {
      if (error) *error = "constraint set '" + text + "' has an empty layer name";
      return std::nullopt;
    }
    if (piece != kObstaclesConstraint &&
        std::find(set.layers.begin(), set.layers.end(), piece) == set.layers.end()) {
      set.layers.push_back(piece);
    }
    if (plus == std::string::npos) break;
    start = plus + 1;
  }
  return set;
}

std::optional<WorldMap> apply_constraints(const WorldMap& map, const ConstraintSet& set,
                                          const ConstraintLayers& known, std::string* error) {
  WorldMap out = map;
  for (const std::string& layer : set.layers) {
    const auto it = known.find(layer);
    if (it == known.end()) {
      if (error) {
        std::string names = kObstaclesConstraint;
        for (const auto& [name, areas] : known) names += ", " + name;
        *error = "unknown constraint set '" + set.name() + "': layer '" + layer + "' is not defined (known layers: " +
                 names + ")";
      }
      return std::nullopt;
    }
    out.obstacles.insert(out.obstacles.end(), it->second.begin(), it->second.end());
  }
  return out;
}

}  // namespace autonomy::behavior
