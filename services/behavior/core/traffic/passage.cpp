#include "services/behavior/core/traffic/passage.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace autonomy::behavior::traffic {

double Passage::distance(const geometry::Vec2& p) const {
  const geometry::Vec2 d = p - centre;
  const double c = std::cos(heading), s = std::sin(heading);
  const double along = std::abs(d.x() * c + d.y() * s) - half_along;
  const double across = std::abs(-d.x() * s + d.y() * c) - half_across;
  const double ox = std::max(along, 0.0), oy = std::max(across, 0.0);
  return std::hypot(ox, oy);
}

std::vector<Passage> narrow_passages(const WorldMap& map, const PassageSettings& settings) {
  if (!std::isfinite(settings.robot_radius_m) || settings.robot_radius_m <= 0.0 || !std::isfinite(settings.margin_m) ||
      settings.margin_m < 0.0 || !std::isfinite(settings.wall_half_thickness_m) || settings.wall_half_thickness_m < 0.0)
    throw std::invalid_argument("passage settings: robot radius must be positive, margin and wall thickness >= 0, all finite");
  const double r = settings.robot_radius_m;
  const double two_abreast = 4.0 * r + settings.margin_m;
  std::vector<Passage> out;
  for (const Doorway& d : map.doors) {
    if (!(d.width_m < two_abreast)) continue;
    Passage p;
    p.id = d.id;
    p.name = "doorway " + d.id;
    p.centre = d.centre;
    p.heading = d.heading;
    p.half_along = 0.5 * d.width_m + r;
    p.half_across = settings.wall_half_thickness_m + 2.0 * r;
    out.push_back(std::move(p));
  }
  std::sort(out.begin(), out.end(), [](const Passage& a, const Passage& b) { return a.id < b.id; });
  return out;
}

}  // namespace autonomy::behavior::traffic
