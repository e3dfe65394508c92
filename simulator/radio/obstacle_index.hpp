#pragma once
// A uniform grid over the attenuators' bounding boxes, so a signal path only looks at the
// attenuators in the cells it passes through (Amanatides-Woo grid walk) instead of at all of them.
// Built once per set of attenuators; queries are const and thread safe.
//
// Contract of visit(a, b, f): f(id) is called at least once for every attenuator whose bounding
// box the segment a-b meets with positive length, and possibly for others near the path and
// more than once for the same id (callers deduplicate, see RadioModel). Boxes are registered
// slightly inflated, so a path grazing a cell corner still finds them.
#include "common/geometry/geometry.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace autonomy::sim::radio {

class ObstacleIndex {
 public:
  ObstacleIndex() = default;
  // cell_size_m <= 0 picks one: the larger of the mean box side and sqrt(area / count), so that
  // a cell holds about one attenuator; capped at 1024 cells per side.
  explicit ObstacleIndex(const std::vector<geometry::Rect>& boxes, double cell_size_m = 0.0);

  template <typename F>
  void visit(const geometry::Vec2& a, const geometry::Vec2& b, F&& f) const {
    visit_while(a, b, [&f](uint32_t id) {
      f(id);
      return true;
    });
  }
  // The same walk, from a towards b, stopping as soon as f(id) returns false.
  template <typename F>
  void visit_while(const geometry::Vec2& a, const geometry::Vec2& b, F&& f) const;

  size_t size() const { return count_; }
  double cell_size_m() const { return cell_; }
  int columns() const { return nx_; }
  int rows() const { return ny_; }

 private:
  size_t count_ = 0;
  double x0_ = 0.0;
  double y0_ = 0.0;
  double cell_ = 1.0;
  int nx_ = 0;
  int ny_ = 0;
  std::vector<uint32_t> offsets_;  // CSR: cell c holds ids_[offsets_[c] .. offsets_[c + 1])
  std::vector<uint32_t> ids_;
};

template <typename F>
void ObstacleIndex::visit_while(const geometry::Vec2& a, const geometry::Vec2& b, F&& f) const {
  if (nx_ == 0) return;
  // Clip the segment to the grid (closed box): parameters t0..t1 along a + t (b - a).
  const geometry::Vec2 d = b - a;
  const double lo[2] = {x0_, y0_};
  const double hi[2] = {x0_ + nx_ * cell_, y0_ + ny_ * cell_};
  double t0 = 0.0;
  double t1 = 1.0;
  for (int k = 0; k < 2; ++k) {
    if (d[k] == 0.0) {
      if (a[k] < lo[k] || a[k] > hi[k]) return;
      continue;
    }
    double ta = (lo[k] - a[k]) / d[k];
    double tb = (hi[k] - a[k]) / d[k];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  if (t0 > t1) return;
  const geometry::Vec2 p = a + d * t0;
  const geometry::Vec2 q = a + d * t1;
  const auto cell_of = [this](double v, double origin, int n) {
    return std::clamp(static_cast<int>(std::floor((v - origin) / cell_)), 0, n - 1);
  };
  int ix = cell_of(p.x(), x0_, nx_);
  int iy = cell_of(p.y(), y0_, ny_);
  const int jx = cell_of(q.x(), x0_, nx_);
  const int jy = cell_of(q.y(), y0_, ny_);
  const int sx = d.x() > 0.0 ? 1 : (d.x() < 0.0 ? -1 : 0);
  const int sy = d.y() > 0.0 ? 1 : (d.y() < 0.0 ? -1 : 0);
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const double dtx = sx != 0 ? cell_ / std::abs(d.x()) : kInf;
  const double dty = sy != 0 ? cell_ / std::abs(d.y()) : kInf;
  double tmx = sx != 0 ? (x0_ + (ix + (sx > 0 ? 1 : 0)) * cell_ - a.x()) / d.x() : kInf;
  double tmy = sy != 0 ? (y0_ + (iy + (sy > 0 ? 1 : 0)) * cell_ - a.y()) / d.y() : kInf;
  const auto visit_cell = [&](int x, int y) {
    const size_t c = static_cast<size_t>(y) * static_cast<size_t>(nx_) + static_cast<size_t>(x);
    for (uint32_t k = offsets_[c]; k < offsets_[c + 1]; ++k) {
      if (!f(ids_[k])) return false;
    }
    return true;
  };
  for (int steps = nx_ + ny_ + 2; steps > 0; --steps) {
    if (!visit_cell(ix, iy)) return;
    if (ix == jx && iy == jy) return;
    if (std::min(tmx, tmy) > t1) break;
    if (tmx < tmy) {
      ix += sx;
      tmx += dtx;
    } else {
      iy += sy;
      tmy += dty;
    }
    if (ix < 0 || ix >= nx_ || iy < 0 || iy >= ny_) break;
  }
  // Rounding at a cell corner can walk past the end cell; make sure it is seen.
  (void)visit_cell(jx, jy);
}

}  // namespace autonomy::sim::radio
