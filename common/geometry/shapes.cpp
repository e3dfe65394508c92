#include "common/geometry/shapes.hpp"

#include <algorithm>
#include <cmath>

namespace autonomy::geometry {

namespace {

// Orientation of c relative to a-b with a relative tolerance: +1 left, -1 right, 0 collinear.
int orientation(const Vec2& a, const Vec2& b, const Vec2& c) {
  const double v = cross(b - a, c - a);
  const double scale = (b - a).norm() * (c - a).norm();
  if (std::abs(v) <= 1e-12 * scale) return 0;
  return v > 0.0 ? 1 : -1;
}

bool on_segment(const Vec2& a, const Vec2& b, const Vec2& p) {
  return std::min(a.x(), b.x()) <= p.x() && p.x() <= std::max(a.x(), b.x()) &&
         std::min(a.y(), b.y()) <= p.y() && p.y() <= std::max(a.y(), b.y());
}

}  // namespace

Rect bounds_of(const std::vector<Vec2>& points) {
  Rect r{kNoHit, kNoHit, -kNoHit, -kNoHit};
  for (const Vec2& v : points) {
    r.min_x = std::min(r.min_x, v.x());
    r.min_y = std::min(r.min_y, v.y());
    r.max_x = std::max(r.max_x, v.x());
    r.max_y = std::max(r.max_y, v.y());
  }
  return r;
}

bool segments_intersect(const Vec2& a, const Vec2& b, const Vec2& c,
                        const Vec2& d) {
  const int o1 = orientation(a, b, c);
  const int o2 = orientation(a, b, d);
  const int o3 = orientation(c, d, a);
  const int o4 = orientation(c, d, b);
  if (o1 != o2 && o3 != o4) return true;
  return (o1 == 0 && on_segment(a, b, c)) || (o2 == 0 && on_segment(a, b, d)) ||
         (o3 == 0 && on_segment(c, d, a)) || (o4 == 0 && on_segment(c, d, b));
}

std::optional<std::string> polygon_problem(const std::vector<Vec2>& v) {
  const std::size_t n = v.size();
  if (n < 3) return "has " + std::to_string(n) + " vertices; a polygon needs at least 3";
  for (const Vec2& p : v) {
    if (!std::isfinite(p.x()) || !std::isfinite(p.y())) return std::string("has a vertex that is not finite");
  }
  double twice_area = 0.0;
  for (std::size_t i = 0; i < n; ++i) twice_area += cross(v[i], v[(i + 1) % n]);
  if (std::abs(twice_area) < 1e-12) return std::string("has zero area");
  for (std::size_t i = 0; i < n; ++i) {
    if ((v[i] - v[(i + 1) % n]).norm() <= kSamePointM) return "repeats vertex " + std::to_string(i);
  }
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& a = v[i];
    const Vec2& b = v[(i + 1) % n];
    for (std::size_t j = i + 1; j < n; ++j) {
      const bool adjacent = j == i + 1 || (i == 0 && j == n - 1);
      const Vec2& c = v[j];
      const Vec2& d = v[(j + 1) % n];
      if (adjacent) {
        // Neighbours share a vertex; they must not fold back onto each other.
        const Vec2& shared = j == i + 1 ? b : a;
        const Vec2& p = j == i + 1 ? a : b;
        const Vec2& q = j == i + 1 ? d : c;
        if (orientation(p, shared, q) == 0 && (p - shared).dot(q - shared) > 0.0) {
          return "edges " + std::to_string(i) + " and " + std::to_string(j) + " overlap";
        }
        continue;
      }
      // Edges that pass within kSamePointM of each other touch: a path between them would be
      // a nanometre wide, which no traversal or containment test can resolve.
      const bool touch = segment_distance(c, a, b) <= kSamePointM || segment_distance(d, a, b) <= kSamePointM ||
                         segment_distance(a, c, d) <= kSamePointM || segment_distance(b, c, d) <= kSamePointM;
      if (touch || segments_intersect(a, b, c, d)) {
        return "edges " + std::to_string(i) + " and " + std::to_string(j) + " cross";
      }
    }
  }
  return std::nullopt;
}

bool polygon_contains(const std::vector<Vec2>& v, const Vec2& p) {
  bool inside = false;
  for (std::size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) {
    if ((v[i].y() > p.y()) != (v[j].y() > p.y()) &&
        p.x() < (v[j].x() - v[i].x()) * (p.y() - v[i].y()) / (v[j].y() - v[i].y()) + v[i].x()) {
      inside = !inside;
    }
  }
  return inside;
}

double segment_distance(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (p - (a + t * ab)).norm();
}

bool disc_overlaps_polygon(const std::vector<Vec2>& v, const Vec2& center,
                           double radius) {
  for (std::size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) {
    if (segment_distance(center, v[j], v[i]) < radius) return true;
  }
  return polygon_contains(v, center);
}

double ray_segment(const Vec2& o, const Vec2& dir, const Vec2& a,
                   const Vec2& b) {
  const Vec2 e = b - a;
  const Vec2 w = a - o;
  const double denom = cross(dir, e);
  if (denom == 0.0) {
    // Parallel: a hit only when collinear, at the nearer endpoint ahead of the origin.
    if (cross(w, dir) != 0.0) return kNoHit;
    const double ta = w.dot(dir);
    const double tb = (b - o).dot(dir);
    if (ta < 0.0 && tb < 0.0) return kNoHit;
    if (ta <= 0.0 || tb <= 0.0) return 0.0;  // the origin lies on the segment
    return std::min(ta, tb);
  }
  const double t = cross(w, e) / denom;
  const double s = cross(w, dir) / denom;
  if (t < 0.0 || s < 0.0 || s > 1.0) return kNoHit;
  return t;
}

double ray_circle(const Vec2& o, const Vec2& dir, const Vec2& center,
                  double radius) {
  const Vec2 m = o - center;
  const double c = m.squaredNorm() - radius * radius;
  if (c <= 0.0) return 0.0;
  const double b = m.dot(dir);
  if (b > 0.0) return kNoHit;  // outside and pointing away
  const double disc = b * b - c;
  if (disc < 0.0) return kNoHit;
  return -b - std::sqrt(disc);
}

}  // namespace autonomy::geometry
