#include "simulator/radio/attenuator.hpp"

#include "common/geometry/shapes.hpp"  // cross

#include "simulator/radio/radio_parameters.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace autonomy::sim::radio {

using geometry::Rect;
using geometry::cross;
using geometry::Vec2;

namespace {

constexpr double kTol = kBoundaryToleranceM;


double distance_to_segment(const Vec2& p, const Vec2& q0, const Vec2& q1) {
  const Vec2 e = q1 - q0;
  const double len2 = e.squaredNorm();
  const double s = len2 > 0.0 ? std::clamp((p - q0).dot(e) / len2, 0.0, 1.0) : 0.0;
  return (p - (q0 + s * e)).norm();
}

double distance_to_box(const Rect& r, const Vec2& p) { return geometry::distance(r, p); }

// Strictly inside a simple polygon (even-odd rule); within kTol of an edge counts as outside.
bool strictly_inside(const std::vector<Vec2>& v, const Vec2& p) {
  bool inside = false;
  const size_t n = v.size();
  for (size_t i = 0, j = n - 1; i < n; j = i++) {
    const bool near_edge_box = p.x() >= std::min(v[i].x(), v[j].x()) - kTol &&
                               p.x() <= std::max(v[i].x(), v[j].x()) + kTol &&
                               p.y() >= std::min(v[i].y(), v[j].y()) - kTol &&
                               p.y() <= std::max(v[i].y(), v[j].y()) + kTol;
    if (near_edge_box && distance_to_segment(p, v[j], v[i]) <= kTol) return false;
    if ((v[i].y() > p.y()) != (v[j].y() > p.y())) {
      const double x = v[j].x() + (p.y() - v[j].y()) * (v[i].x() - v[j].x()) / (v[i].y() - v[j].y());
      if (p.x() < x) inside = !inside;
    }
  }
  return inside;
}

// Whether segment a-b meets the closed box r (slab test).
bool segment_meets_box(const Rect& r, const Vec2& a, const Vec2& b) {
  const Vec2 d = b - a;
  const double lo[2] = {r.min_x, r.min_y};
  const double hi[2] = {r.max_x, r.max_y};
  double t0 = 0.0;
  double t1 = 1.0;
  for (int k = 0; k < 2; ++k) {
    if (d[k] == 0.0) {
      if (a[k] < lo[k] || a[k] > hi[k]) return false;
      continue;
    }
    const double inv = 1.0 / d[k];
    double ta = (lo[k] - a[k]) * inv;
    double tb = (hi[k] - a[k]) * inv;
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return false;
  }
  return true;
}

// Convex polygon, counter-clockwise: clip the segment to the open half-planes left of every edge
// (Cyrus-Beck), with the same boundary rules as the rectangle.
Traversal traverse_convex(const std::vector<Vec2>& v, const Vec2& a, const Vec2& b) {
  const Vec2 d = b - a;
  const double len = d.norm();
  if (len <= kTol) return {};
  double t0 = 0.0;
  double t1 = 1.0;
  const size_t n = v.size();
  for (size_t i = 0, j = n - 1; i < n; j = i++) {
    const Vec2 e = v[i] - v[j];
    const double side = cross(e, a - v[j]);  // > 0: a is left of (inside) this edge
    const double rate = cross(e, d);
    if (rate == 0.0) {
      if (side <= kTol * e.norm()) return {};
      continue;
    }
    const double t = -side / rate;
    if (rate > 0.0) {
      t0 = std::max(t0, t);
    } else {
      t1 = std::min(t1, t);
    }
    if (t0 >= t1) return {};
  }
  if ((t1 - t0) * len <= kTol) return {};
  const auto clearance = [&](const Vec2& p) {  // signed distance inside (negative: outside)
    double m = std::numeric_limits<double>::infinity();
    for (size_t i = 0, j = n - 1; i < n; j = i++) {
      const Vec2 e = v[i] - v[j];
      m = std::min(m, cross(e, p - v[j]) / e.norm());
    }
    return m;
  };
  if (clearance(a + d * (0.5 * (t0 + t1))) <= kTol) return {};
  Traversal t;
  t.stretches = 1;
  t.inside_m = (t1 - t0) * len;
  t.crossings = (t0 > 0.0 && clearance(a) < -kTol ? 1 : 0) + (t1 < 1.0 && clearance(b) < -kTol ? 1 : 0);
  return t;
}

// Rectangle: clip the segment to the box. As for polygons, the boundary is outside: a segment
// parallel to an edge and within kTol of it, or whose inside piece has its midpoint on the
// boundary, is not inside.
Traversal traverse_rect(const Rect& r, const Vec2& a, const Vec2& b) {
  const Vec2 d = b - a;
  const double len = d.norm();
  const double lo[2] = {r.min_x, r.min_y};
  const double hi[2] = {r.max_x, r.max_y};
  double t0 = 0.0;
  double t1 = 1.0;
  for (int k = 0; k < 2; ++k) {
    if (d[k] == 0.0) {
      if (a[k] <= lo[k] + kTol || a[k] >= hi[k] - kTol) return {};
      continue;
    }
    double ta = (lo[k] - a[k]) / d[k];
    double tb = (hi[k] - a[k]) / d[k];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  if ((t1 - t0) * len <= kTol) return {};
  const Vec2 mid = a + d * (0.5 * (t0 + t1));
  if (mid.x() <= r.min_x + kTol || mid.x() >= r.max_x - kTol || mid.y() <= r.min_y + kTol ||
      mid.y() >= r.max_y - kTol) {
    return {};
  }
  Traversal t;
  t.stretches = 1;
  t.inside_m = (t1 - t0) * len;
  // A crossing where the segment enters or leaves at an interior point; an endpoint inside or on
  // the boundary is not one.
  t.crossings = (t0 > 0.0 && distance_to_box(r, a) > kTol ? 1 : 0) +
                (t1 < 1.0 && distance_to_box(r, b) > kTol ? 1 : 0);
  return t;
}

// Polygon: split the segment at every point where it meets the boundary (edge intersections,
// collinear edge ends), classify each piece, and merge neighbouring pieces with the same status.
// A piece is classified by its midpoint (point in polygon) unless it follows a clean crossing (one
// edge crossed well inside its span, no other split point there), where the status simply flips:
// the common case costs one point-in-polygon test per segment. Touching a vertex splits the
// segment without a clean crossing, so both sides are tested and nothing changes; a piece along an
// edge has its midpoint on the boundary, so it is outside.
Traversal traverse_polygon(const std::vector<Vec2>& v, const Rect& box, const Vec2& a, const Vec2& b) {
  const Vec2 d = b - a;
  const double len2 = d.squaredNorm();
  const double len = std::sqrt(len2);
  if (len <= kTol) return {};
  struct Split {
    double t;
    bool clean;
  };
  const size_t n = v.size();
  // At most two split points per edge, plus both ends; small polygons stay on the stack.
  std::array<Split, 66> stack_splits;
  std::vector<Split> heap_splits;
  Split* ts = stack_splits.data();
  if (2 * n + 2 > stack_splits.size()) {
    heap_splits.resize(2 * n + 2);
    ts = heap_splits.data();
  }
  size_t count = 0;
  ts[count++] = {0.0, false};
  ts[count++] = {1.0, false};
  const auto add = [&](double t, bool clean) {
    if (t > 0.0 && t < 1.0) ts[count++] = {t, clean};
  };
  for (size_t i = 0, j = n - 1; i < n; j = i++) {
    const Vec2& q = v[j];
    const Vec2 e = v[i] - q;
    const Vec2 w = q - a;
    const double elen = e.norm();
    const double denom = cross(d, e);
    if (std::abs(denom) > 1e-12 * len * elen) {
      const double s = cross(w, d) / denom;
      const double s_tol = kTol / elen;
      // Generous on s: a spurious split point is harmless, a missed one is not.
      if (s >= -s_tol && s <= 1.0 + s_tol) {
        const bool clean = s > 1e3 * s_tol && s < 1.0 - 1e3 * s_tol &&
                           std::abs(denom) > 1e-6 * len * elen;
        add(cross(w, e) / denom, clean);
      }
    } else if (std::abs(cross(w, d)) / len <= kTol) {  // collinear: the edge's ends split
      add(w.dot(d) / len2, false);
      add((w + e).dot(d) / len2, false);
    }
  }
  std::sort(ts, ts + count, [](const Split& x, const Split& y) { return x.t < y.t; });

  Traversal t;
  int previous = -1;         // status of the last piece that counted: -1 none, 0 outside, 1 inside
  bool previous_adjacent = false;  // that piece ends at ts[k] (no negligible piece in between)
  for (size_t k = 0; k + 1 < count; ++k) {
    const double piece = (ts[k + 1].t - ts[k].t) * len;
    if (piece <= kTol) {
      previous_adjacent = false;
      continue;
    }
    int status;
    if (k == 0 && distance_to_box(box, a) > kTol) {
      status = 0;
    } else if (previous != -1 && previous_adjacent && ts[k].clean) {
      status = 1 - previous;
    } else {
      status = strictly_inside(v, a + d * (0.5 * (ts[k].t + ts[k + 1].t))) ? 1 : 0;
    }
    if (status == 1) {
      t.inside_m += piece;
      if (previous != 1) ++t.stretches;
    }
    if (previous != -1 && previous != status) ++t.crossings;
    previous = status;
    previous_adjacent = true;
  }
  return t;
}

}  // namespace

namespace detail {
Traversal traverse_any_polygon(const std::vector<Vec2>& vertices, const Vec2& a, const Vec2& b) {
  return traverse_polygon(vertices, geometry::bounds_of(vertices), a, b);
}
Traversal traverse_convex_polygon(const std::vector<Vec2>& ccw_vertices, const Vec2& a,
                                  const Vec2& b) {
  return traverse_convex(ccw_vertices, a, b);
}
}  // namespace detail

Shape Shape::rect(const Rect& r) {
  if (!r.valid() || !std::isfinite(r.min_x) || !std::isfinite(r.min_y) ||
      !std::isfinite(r.max_x) || !std::isfinite(r.max_y)) {
    throw std::invalid_argument("attenuator rectangle must have min < max and finite corners");
  }
  Shape s;
  s.is_rect_ = true;
  s.bounds_ = r;
  s.vertices_ = {{r.min_x, r.min_y}, {r.max_x, r.min_y}, {r.max_x, r.max_y}, {r.min_x, r.max_y}};
  return s;
}

Shape Shape::polygon(std::vector<Vec2> vertices) {
  if (auto why = polygon_problem(vertices)) throw std::invalid_argument("attenuator polygon: " + *why);
  Shape s;
  s.bounds_ = geometry::bounds_of(vertices);
  // Convex when every turn goes the same way (collinear vertices allowed); stored
  // counter-clockwise so that the inside is left of every edge.
  double area2 = 0.0;
  int left = 0, right = 0;
  const size_t n = vertices.size();
  for (size_t i = 0; i < n; ++i) {
    const Vec2& p = vertices[i];
    const Vec2& q = vertices[(i + 1) % n];
    const Vec2& r = vertices[(i + 2) % n];
    area2 += cross(p, q);
    const double turn = cross(q - p, r - q);
    left += turn > 0.0 ? 1 : 0;
    right += turn < 0.0 ? 1 : 0;
  }
  if (area2 < 0.0) std::reverse(vertices.begin(), vertices.end());
  s.convex_ = left == 0 || right == 0;
  s.vertices_ = std::move(vertices);
  return s;
}

Traversal Shape::traverse(const Vec2& a, const Vec2& b) const {
  if (!segment_meets_box(bounds_, a, b)) return {};
  if (is_rect_) return traverse_rect(bounds_, a, b);
  return convex_ ? traverse_convex(vertices_, a, b) : traverse_polygon(vertices_, bounds_, a, b);
}

bool Shape::contains(const Vec2& p) const {
  if (is_rect_) {
    return p.x() > bounds_.min_x + kTol && p.x() < bounds_.max_x - kTol &&
           p.y() > bounds_.min_y + kTol && p.y() < bounds_.max_y - kTol;
  }
  return strictly_inside(vertices_, p);
}

Attenuator Attenuator::obstacle(Shape shape, const RadioParameters& params, std::string name) {
  return {std::move(shape), params.wall_loss_db, 0.0, params.inside_loss_db_per_m, std::move(name)};
}

Attenuator Attenuator::area(Shape shape, double entry_loss_db, double loss_per_metre_db,
                            std::string name) {
  return {std::move(shape), 0.0, entry_loss_db, loss_per_metre_db, std::move(name)};
}

std::optional<std::string> attenuator_problem(const Attenuator& a) {
  for (double v : {a.loss_per_crossing_db, a.loss_per_stretch_db, a.loss_per_metre_db}) {
    if (!std::isfinite(v) || v < 0.0) {
      return "attenuator '" + a.name + "': losses must be finite and >= 0";
    }
  }
  return std::nullopt;
}

std::vector<Attenuator> obstacles_from_rects(const std::vector<Rect>& rects,
                                             const RadioParameters& params) {
  std::vector<Attenuator> out;
  out.reserve(rects.size());
  for (size_t i = 0; i < rects.size(); ++i) {
    out.push_back(Attenuator::obstacle(Shape::rect(rects[i]), params, "obstacle " + std::to_string(i)));
  }
  return out;
}

}  // namespace autonomy::sim::radio
