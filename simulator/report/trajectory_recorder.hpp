#pragma once
// Keeps each robot's path for pictures and metrics without storing every tick: a point is kept
// when the robot moved at least min_spacing_m from the last kept one (and always the first and
// the latest), so a long run of a parked robot costs nothing.
#include "common/geometry/geometry.hpp"

#include <map>
#include <string>
#include <vector>

namespace autonomy::sim {

class TrajectoryRecorder {
 public:
  explicit TrajectoryRecorder(double min_spacing_m = 0.05) : min_spacing_m_(min_spacing_m) {}

  void record(const std::string& robot_id, const geometry::Vec2& position);
  // Paths by robot id, each ending at the latest recorded position.
  std::map<std::string, std::vector<geometry::Vec2>> paths() const;

 private:
  struct Path {
    std::vector<geometry::Vec2> kept;
    geometry::Vec2 latest;
  };
  double min_spacing_m_;
  std::map<std::string, Path> paths_;
};

}  // namespace autonomy::sim
