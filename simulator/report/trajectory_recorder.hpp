#pragma once
// Keeps each robot's path for pictures and metrics without storing every tick: a point is kept
// when the robot moved at least min_spacing_m from the last kept one, when its connectivity flag
// changed since the last kept one (so a picture shows where links broke and came back), and
// always the first and the latest. A long run of a parked robot costs nothing.
#include "common/geometry/geometry.hpp"

#include <map>
#include <string>
#include <vector>

namespace autonomy::sim {

class TrajectoryRecorder {
 public:
  explicit TrajectoryRecorder(double min_spacing_m = 0.05) : min_spacing_m_(min_spacing_m) {}

  // Without a flag the robot counts as connected.
  void record(const std::string& robot_id, const geometry::Vec2& position);
  void record(const std::string& robot_id, const geometry::Vec2& position, bool connected);
  // Paths by robot id, each ending at the latest recorded position.
  std::map<std::string, std::vector<geometry::Vec2>> paths() const;
  // By robot id, the connectivity flag of every point of paths() (same lengths), for
  // RunPicture::path_connected.
  std::map<std::string, std::vector<bool>> connected_flags() const;

 private:
  struct Point {
    geometry::Vec2 position;
    bool connected = true;
  };
  struct Path {
    std::vector<Point> kept;
    Point latest;
  };
  std::vector<Point> points(const Path& p) const;

  double min_spacing_m_;
  std::map<std::string, Path> paths_;
};

}  // namespace autonomy::sim
