#include "services/behavior/dds/map_conversion.hpp"

#include <spdlog/spdlog.h>

#include <cmath>
#include <memory>

namespace autonomy::behavior {

// The map sample as the planner's world. Shapes another process got wrong (a crossing polygon,
// a raster whose cells do not add up) are left out with a warning rather than stopping the robot.
WorldMap world_of(const msg::WorldMap& m) {
  WorldMap w{m.width, m.height, {}, {}, {}, {}};
  for (const auto& r : m.obstacles) {
    if (r.valid() && std::isfinite(r.min_x) && std::isfinite(r.min_y) && std::isfinite(r.max_x) &&
        std::isfinite(r.max_y)) {
      w.obstacles.push_back(r);
    } else {
      spdlog::warn("map '{}': obstacle rectangle ({}, {})-({}, {}) is not valid; ignored", m.name, r.min_x, r.min_y,
                   r.max_x, r.max_y);
    }
  }
  for (const auto& p : m.polygons) {
    geometry::Polygon polygon{p.name, {}};
    for (const auto& v : p.vertices) polygon.vertices.emplace_back(v.x, v.y);
    if (const auto problem = geometry::polygon_problem(polygon.vertices)) {
      spdlog::warn("map '{}': polygon '{}' ignored: {}", m.name, p.name, *problem);
      continue;
    }
    w.polygons.push_back(std::move(polygon));
  }
  for (const auto& r : m.rasters) {
    const std::size_t cells = static_cast<std::size_t>(r.cols) * r.rows;
    if (cells == 0 || r.blocked.size() != cells || !std::isfinite(r.resolution) || r.resolution <= 0.0 ||
        !std::isfinite(r.origin_x) || !std::isfinite(r.origin_y)) {
      spdlog::warn("map '{}': raster '{}' ignored: {} x {} cells at {} m, {} cell values", m.name, r.name, r.cols,
                   r.rows, r.resolution, r.blocked.size());
      continue;
    }
    auto raster = std::make_shared<grid::OccupancyRaster>(static_cast<int>(r.cols), static_cast<int>(r.rows),
                                                          r.resolution, grid::RasterOrigin{r.origin_x, r.origin_y, 0.0});
    for (int row = 0; row < raster->height(); ++row) {
      for (int col = 0; col < raster->width(); ++col) {
        if (r.blocked[raster->index({col, row})] != 0) raster->set_blocked({col, row}, true);
      }
    }
    w.rasters.push_back(std::move(raster));
  }
  for (const auto& d : m.doors) {
    if (d.id.empty() || !std::isfinite(d.x) || !std::isfinite(d.y) || !std::isfinite(d.width) || d.width <= 0.0 ||
        !std::isfinite(d.heading) || !std::isfinite(d.open_angle) || std::fabs(d.open_angle) > M_PI) {
      spdlog::warn("map '{}': door '{}' ignored: doorway ({}, {}) width {} heading {} open angle {}", m.name, d.id, d.x,
                   d.y, d.width, d.heading, d.open_angle);
      continue;
    }
    w.doors.push_back({d.id, geometry::Vec2(d.x, d.y), d.width, d.heading, d.open_angle});
  }
  return w;
}

}  // namespace autonomy::behavior
