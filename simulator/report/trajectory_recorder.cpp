#include "simulator/report/trajectory_recorder.hpp"

namespace autonomy::sim {

void TrajectoryRecorder::record(const std::string& robot_id, const geometry::Vec2& position) {
  Path& p = paths_[robot_id];
  if (p.kept.empty() || (position - p.kept.back()).norm() >= min_spacing_m_) p.kept.push_back(position);
  p.latest = position;
}

std::map<std::string, std::vector<geometry::Vec2>> TrajectoryRecorder::paths() const {
  std::map<std::string, std::vector<geometry::Vec2>> out;
  for (const auto& [id, p] : paths_) {
    auto& path = out[id];
    path = p.kept;
    if (path.empty() || path.back() != p.latest) path.push_back(p.latest);
  }
  return out;
}

}  // namespace autonomy::sim
