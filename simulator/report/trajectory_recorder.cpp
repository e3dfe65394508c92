#include "simulator/report/trajectory_recorder.hpp"

namespace autonomy::sim {

void TrajectoryRecorder::record(const std::string& robot_id, const geometry::Vec2& position) {
  record(robot_id, position, true);
}

void TrajectoryRecorder::record(const std::string& robot_id, const geometry::Vec2& position, bool connected) {
  Path& p = paths_[robot_id];
  if (p.kept.empty() || (position - p.kept.back().position).norm() >= min_spacing_m_ ||
      connected != p.kept.back().connected)
    p.kept.push_back({position, connected});
  p.latest = {position, connected};
}

std::vector<TrajectoryRecorder::Point> TrajectoryRecorder::points(const Path& p) const {
  std::vector<Point> out = p.kept;
  // A flag change is always kept, so the latest point differs from the last kept one only in
  // position, never in flag alone.
  if (out.empty() || out.back().position != p.latest.position) out.push_back(p.latest);
  return out;
}

std::map<std::string, std::vector<geometry::Vec2>> TrajectoryRecorder::paths() const {
  std::map<std::string, std::vector<geometry::Vec2>> out;
  for (const auto& [id, p] : paths_) {
    auto& path = out[id];
    for (const Point& point : points(p)) path.push_back(point.position);
  }
  return out;
}

std::map<std::string, std::vector<bool>> TrajectoryRecorder::connected_flags() const {
  std::map<std::string, std::vector<bool>> out;
  for (const auto& [id, p] : paths_) {
    auto& flags = out[id];
    for (const Point& point : points(p)) flags.push_back(point.connected);
  }
  return out;
}

}  // namespace autonomy::sim
