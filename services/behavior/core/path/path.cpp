#include "services/behavior/core/path/path.hpp"

#include <algorithm>
#include <cmath>

namespace autonomy::behavior {

const char* to_string(PathStatus s) {
  switch (s) {
    case PathStatus::Found:
      return "found";
    case PathStatus::InvalidRequest:
      return "invalid request";
    case PathStatus::StartBlocked:
      return "start blocked";
    case PathStatus::GoalBlocked:
      return "goal blocked";
    case PathStatus::Unreachable:
      return "unreachable";
    case PathStatus::NotFound:
      return "not found within budget";
  }
  return "unknown";
}

double path_length(const std::vector<geometry::Pose2>& poses) {
  double sum = 0.0;
  for (std::size_t i = 1; i < poses.size(); ++i)
    sum += (poses[i].position() - poses[i - 1].position()).norm();
  return sum;
}

double path_smoothness(const std::vector<geometry::Pose2>& poses) {
  constexpr double kMinSegment = 1e-3;
  // Drop near-duplicate vertices first: their direction is noise.
  std::vector<geometry::Vec2> pts;
  for (const auto& p : poses) {
    if (pts.empty() || (p.position() - pts.back()).norm() >= kMinSegment)
      pts.push_back(p.position());
  }
  double sum = 0.0;
  for (std::size_t i = 1; i + 1 < pts.size(); ++i) {
    const geometry::Vec2 a = pts[i] - pts[i - 1];
    const geometry::Vec2 b = pts[i + 1] - pts[i];
    const double turn = std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
    sum += turn * turn / (a.norm() + b.norm());
  }
  return sum;
}

std::optional<std::size_t> first_collision(const OccupancyGrid& grid,
                                           const std::vector<geometry::Pose2>& poses,
                                           double step_m) {
  const auto blocked_at = [&](const geometry::Vec2& p) {
    const auto c = grid.geometry().cell_at(p);
    return !c || grid.blocked(*c);
  };
  if (poses.empty()) return std::nullopt;
  if (blocked_at(poses.front().position())) return std::size_t{0};
  const double step = step_m > 0.0 ? step_m : 0.05;
  for (std::size_t i = 1; i < poses.size(); ++i) {
    const geometry::Vec2 a = poses[i - 1].position();
    const geometry::Vec2 b = poses[i].position();
    const int n = std::max(1, static_cast<int>(std::ceil((b - a).norm() / step)));
    for (int k = 1; k <= n; ++k) {
      if (blocked_at(a + (b - a) * (static_cast<double>(k) / n))) return i - 1;
    }
  }
  return std::nullopt;
}

}  // namespace autonomy::behavior
