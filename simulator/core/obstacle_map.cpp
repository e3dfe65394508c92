#include "simulator/core/obstacle_map.hpp"

#include "simulator/core/number_format.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <tuple>

namespace autonomy::sim {

namespace {

// Grid cells: at least 1 m, at most 256 per side of the world.
constexpr double kMinCellM = 1.0;
constexpr double kCellsPerSide = 256.0;
// Shapes are registered in the cells of their box grown by this much, so a ray or disc that only
// grazes a cell boundary still finds them.
constexpr double kRegisterMarginM = 1e-6;

bool cell_blocked(const grid::OccupancyRaster& g, int col, int row) {
  return (g.row_words(row)[static_cast<std::size_t>(col) >> 6] >> (col & 63)) & 1u;
}

}  // namespace

double cast_raster(const grid::OccupancyRaster& g, const geometry::Vec2& origin,
                   const geometry::Vec2& dir, double max_range) {
  if (g.width() == 0 || g.height() == 0) return kNoHit;
  const double res = g.resolution_m();
  // In cell units: t_cells = t_m / res.
  const double px = (origin.x() - g.origin().x) / res;
  const double py = (origin.y() - g.origin().y) / res;
  const double dx = dir.x();
  const double dy = dir.y();
  double t0 = 0.0;
  double t1 = max_range / res;
  const double p[2] = {px, py};
  const double d[2] = {dx, dy};
  const double hi[2] = {static_cast<double>(g.width()), static_cast<double>(g.height())};
  for (int k = 0; k < 2; ++k) {
    if (d[k] == 0.0) {
      if (p[k] < 0.0 || p[k] >= hi[k]) return kNoHit;
      continue;
    }
    double ta = (0.0 - p[k]) / d[k];
    double tb = (hi[k] - p[k]) / d[k];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  if (t0 > t1) return kNoHit;
  int ix = std::clamp(static_cast<int>(std::floor(px + dx * t0)), 0, g.width() - 1);
  int iy = std::clamp(static_cast<int>(std::floor(py + dy * t0)), 0, g.height() - 1);
  const int sx = dx > 0.0 ? 1 : (dx < 0.0 ? -1 : 0);
  const int sy = dy > 0.0 ? 1 : (dy < 0.0 ? -1 : 0);
  const double dtx = sx != 0 ? 1.0 / std::abs(dx) : kNoHit;
  const double dty = sy != 0 ? 1.0 / std::abs(dy) : kNoHit;
  double tmx = sx != 0 ? (ix + (sx > 0 ? 1 : 0) - px) / dx : kNoHit;
  double tmy = sy != 0 ? (iy + (sy > 0 ? 1 : 0) - py) / dy : kNoHit;
  double t_enter = t0;
  while (true) {
    if (cell_blocked(g, ix, iy)) return t_enter * res;
    if (tmx < tmy) {
      t_enter = tmx;
      ix += sx;
      tmx += dtx;
    } else {
      t_enter = tmy;
      iy += sy;
      tmy += dty;
    }
    if (t_enter > t1 || ix < 0 || iy < 0 || ix >= g.width() || iy >= g.height()) return kNoHit;
  }
}

ObstacleMap::ObstacleMap(double width, double height, std::vector<geometry::Rect> rects,
                         std::vector<Polygon> polygons, std::vector<RasterLayer> rasters)
    : width_(width), height_(height), rects_(std::move(rects)), polygons_(std::move(polygons)),
      rasters_(std::move(rasters)) {
  if (!(width_ > 0.0) || !(height_ > 0.0) || !std::isfinite(width_) || !std::isfinite(height_)) {
    throw std::invalid_argument("obstacle map size must be positive");
  }
  for (std::size_t i = 0; i < rects_.size(); ++i) {
    if (!rects_[i].valid()) throw std::invalid_argument("obstacle " + std::to_string(i) + " is invalid");
  }
  for (std::size_t i = 0; i < polygons_.size(); ++i) {
    if (const auto problem = polygon_problem(polygons_[i].vertices)) {
      throw std::invalid_argument("polygon " + std::to_string(i) + " " + *problem);
    }
  }
  for (const RasterLayer& layer : rasters_) {
    if (!layer.raster) throw std::invalid_argument("map '" + layer.name + "' has no raster");
    if (layer.raster->origin().yaw != 0.0) {
      throw std::invalid_argument("map '" + layer.name + "' is rotated; only yaw 0 is supported");
    }
  }

  cell_ = std::max(kMinCellM, std::max(width_, height_) / kCellsPerSide);
  nx_ = std::max(1, static_cast<int>(std::ceil(width_ / cell_)));
  ny_ = std::max(1, static_cast<int>(std::ceil(height_ / cell_)));

  // Edges for rays and areas for overlap, each with the box it is registered under.
  std::vector<std::pair<geometry::Rect, std::uint32_t>> segment_boxes;
  std::vector<std::pair<geometry::Rect, Area>> area_boxes;
  const auto add_segment = [&](const geometry::Vec2& a, const geometry::Vec2& b) {
    segment_boxes.push_back({{std::min(a.x(), b.x()), std::min(a.y(), b.y()), std::max(a.x(), b.x()),
                              std::max(a.y(), b.y())},
                             static_cast<std::uint32_t>(segments_.size())});
    segments_.push_back({a, b});
  };
  for (std::size_t i = 0; i < rects_.size(); ++i) {
    const geometry::Rect& r = rects_[i];
    const geometry::Vec2 c[4] = {{r.min_x, r.min_y}, {r.max_x, r.min_y}, {r.max_x, r.max_y}, {r.min_x, r.max_y}};
    for (int k = 0; k < 4; ++k) add_segment(c[k], c[(k + 1) % 4]);
    area_boxes.push_back({r, {ObstacleRef::Kind::Rect, static_cast<std::uint32_t>(i)}});
  }
  for (std::size_t i = 0; i < polygons_.size(); ++i) {
    const auto& v = polygons_[i].vertices;
    for (std::size_t k = 0; k < v.size(); ++k) add_segment(v[k], v[(k + 1) % v.size()]);
    area_boxes.push_back({polygons_[i].bounds(), {ObstacleRef::Kind::Polygon, static_cast<std::uint32_t>(i)}});
  }

  const std::size_t cells = static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_);
  const auto build = [&](const auto& boxes, std::vector<std::uint32_t>& offsets, auto& ids) {
    offsets.assign(cells + 1, 0);
    for (const auto& [box, id] : boxes) for_cells(box, [&](std::size_t c) { ++offsets[c + 1]; });
    for (std::size_t c = 0; c < cells; ++c) offsets[c + 1] += offsets[c];
    ids.resize(offsets[cells]);
    std::vector<std::uint32_t> fill(offsets.begin(), offsets.end() - 1);
    for (const auto& [box, id] : boxes) for_cells(box, [&](std::size_t c) { ids[fill[c]++] = id; });
  };
  build(segment_boxes, segment_offsets_, segment_ids_);
  build(area_boxes, area_offsets_, areas_);
}

template <typename F>
void ObstacleMap::for_cells(const geometry::Rect& box, F&& f) const {
  const auto col = [&](double x) {
    return std::clamp(static_cast<int>(std::floor(x / cell_)), 0, nx_ - 1);
  };
  const auto row = [&](double y) {
    return std::clamp(static_cast<int>(std::floor(y / cell_)), 0, ny_ - 1);
  };
  const int c0 = col(box.min_x - kRegisterMarginM);
  const int c1 = col(box.max_x + kRegisterMarginM);
  const int r0 = row(box.min_y - kRegisterMarginM);
  const int r1 = row(box.max_y + kRegisterMarginM);
  for (int r = r0; r <= r1; ++r) {
    for (int c = c0; c <= c1; ++c) f(static_cast<std::size_t>(r) * static_cast<std::size_t>(nx_) + c);
  }
}

std::optional<ObstacleRef> ObstacleMap::overlap(const geometry::Vec2& center, double radius) const {
  std::optional<ObstacleRef> found;
  const auto better = [&](ObstacleRef::Kind kind, std::size_t index) {
    return !found || std::make_tuple(kind, index) < std::make_tuple(found->kind, found->index);
  };
  const geometry::Rect box{center.x() - radius, center.y() - radius, center.x() + radius,
                           center.y() + radius};
  for_cells(box, [&](std::size_t c) {
    for (std::uint32_t k = area_offsets_[c]; k < area_offsets_[c + 1]; ++k) {
      const Area& a = areas_[k];
      if (!better(a.kind, a.index)) continue;
      const bool hit = a.kind == ObstacleRef::Kind::Rect
                           ? geometry::circle_overlaps(rects_[a.index], center, radius)
                           : (geometry::circle_overlaps(polygons_[a.index].bounds(), center, radius) &&
                              disc_overlaps_polygon(polygons_[a.index].vertices, center, radius));
      if (hit) found = ObstacleRef{a.kind, a.index, {}};
    }
  });
  if (found) return found;
  for (std::size_t i = 0; i < rasters_.size(); ++i) {
    const grid::OccupancyRaster& g = *rasters_[i].raster;
    const double res = g.resolution_m();
    const double ox = g.origin().x;
    const double oy = g.origin().y;
    const int c0 = std::max(0, static_cast<int>(std::floor((box.min_x - ox) / res)));
    const int c1 = std::min(g.width() - 1, static_cast<int>(std::floor((box.max_x - ox) / res)));
    const int r0 = std::max(0, static_cast<int>(std::floor((box.min_y - oy) / res)));
    const int r1 = std::min(g.height() - 1, static_cast<int>(std::floor((box.max_y - oy) / res)));
    for (int r = r0; r <= r1; ++r) {
      for (int c = c0; c <= c1; ++c) {
        if (!cell_blocked(g, c, r)) continue;
        const geometry::Rect cell{ox + c * res, oy + r * res, ox + (c + 1) * res, oy + (r + 1) * res};
        if (geometry::circle_overlaps(cell, center, radius)) return ObstacleRef{ObstacleRef::Kind::Raster, i, {c, r}};
      }
    }
  }
  return std::nullopt;
}

double ObstacleMap::cast_vector(const geometry::Vec2& o, const geometry::Vec2& d, double limit) const {
  double best = limit;
  int ix = std::clamp(static_cast<int>(std::floor(o.x() / cell_)), 0, nx_ - 1);
  int iy = std::clamp(static_cast<int>(std::floor(o.y() / cell_)), 0, ny_ - 1);
  const int sx = d.x() > 0.0 ? 1 : (d.x() < 0.0 ? -1 : 0);
  const int sy = d.y() > 0.0 ? 1 : (d.y() < 0.0 ? -1 : 0);
  const double dtx = sx != 0 ? cell_ / std::abs(d.x()) : kNoHit;
  const double dty = sy != 0 ? cell_ / std::abs(d.y()) : kNoHit;
  double tmx = sx != 0 ? ((ix + (sx > 0 ? 1 : 0)) * cell_ - o.x()) / d.x() : kNoHit;
  double tmy = sy != 0 ? ((iy + (sy > 0 ? 1 : 0)) * cell_ - o.y()) / d.y() : kNoHit;
  while (true) {
    const std::size_t c = static_cast<std::size_t>(iy) * static_cast<std::size_t>(nx_) + ix;
    for (std::uint32_t k = segment_offsets_[c]; k < segment_offsets_[c + 1]; ++k) {
      const Segment& s = segments_[segment_ids_[k]];
      best = std::min(best, ray_segment(o, d, s.a, s.b));
    }
    const double t_exit = std::min(tmx, tmy);
    if (best <= t_exit) return best;
    if (tmx < tmy) {
      ix += sx;
      tmx += dtx;
    } else {
      iy += sy;
      tmy += dty;
    }
    if (ix < 0 || iy < 0 || ix >= nx_ || iy >= ny_) return best;
  }
}

double ObstacleMap::cast(const geometry::Vec2& o, const geometry::Vec2& d, double max_range) const {
  // The world boundary is a wall.
  double limit = max_range;
  if (d.x() > 0.0) limit = std::min(limit, (width_ - o.x()) / d.x());
  if (d.x() < 0.0) limit = std::min(limit, -o.x() / d.x());
  if (d.y() > 0.0) limit = std::min(limit, (height_ - o.y()) / d.y());
  if (d.y() < 0.0) limit = std::min(limit, -o.y() / d.y());
  limit = std::max(0.0, limit);
  double best = segments_.empty() ? limit : cast_vector(o, d, limit);
  for (const RasterLayer& layer : rasters_) best = std::min(best, cast_raster(*layer.raster, o, d, best));
  return best;
}

bool ObstacleMap::clear(const geometry::Vec2& a, const geometry::Vec2& b) const {
  const double length = (b - a).norm();
  if (length == 0.0) return !overlap(a, 0.0).has_value();
  constexpr double kEndSlackM = 1e-9;
  return cast(a, (b - a) / length, length) >= length - kEndSlackM;
}

std::string ObstacleMap::describe(const ObstacleRef& ref) const {
  switch (ref.kind) {
    case ObstacleRef::Kind::Rect: return "obstacle " + std::to_string(ref.index);
    case ObstacleRef::Kind::Polygon: {
      const std::string& name = polygons_.at(ref.index).name;
      return "polygon " + std::to_string(ref.index) + (name.empty() ? "" : " '" + name + "'");
    }
    case ObstacleRef::Kind::Raster:
      return "map '" + rasters_.at(ref.index).name + "' cell (" + std::to_string(ref.cell.col) + ", " +
             std::to_string(ref.cell.row) + ")";
  }
  return "obstacle";
}

}  // namespace autonomy::sim
