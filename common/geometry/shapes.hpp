#pragma once
// Polygons and the few exact plane tests the world needs beyond rectangles: where a ray first
// meets a segment or a disc, how far a point is from a segment, whether a disc overlaps a polygon.
// Touching is not overlapping (distance == radius is free). Shared by the simulator (ground truth)
// and the behavior controller (planning grids), so both read a polygon the same way.
#include "common/geometry/geometry.hpp"

#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace autonomy::geometry {

inline constexpr double kNoHit = std::numeric_limits<double>::infinity();
// Points closer than this (1 nm) are one point: polygon checks, the radio's boundary tests.
inline constexpr double kSamePointM = 1e-9;

// The smallest axis-aligned rectangle holding every point; {+inf, +inf, -inf, -inf} for none.
Rect bounds_of(const std::vector<Vec2>& points);

// A simple polygon (closed implicitly, no self-intersections, either orientation, convex or not).
struct Polygon {
  std::string name;  // for error messages and reports; may be empty
  std::vector<Vec2> vertices;

  Rect bounds() const { return bounds_of(vertices); }
};

// Why `vertices` is not a usable simple polygon (fewer than 3 vertices, a non-finite coordinate,
// (near) zero area, a repeated vertex, two edges that cross, touch or overlap, within
// kSamePointM), or nothing when it is usable. The one check for every polygon: scenario files,
// maps from DDS, radio attenuators.
std::optional<std::string> polygon_problem(const std::vector<Vec2>& vertices);

// Even-odd rule; points on the boundary may count either way.
bool polygon_contains(const std::vector<Vec2>& vertices, const Vec2& p);

double segment_distance(const Vec2& p, const Vec2& a, const Vec2& b);

// The disc overlaps the polygon: its centre is inside or an edge is closer than `radius`.
bool disc_overlaps_polygon(const std::vector<Vec2>& vertices, const Vec2& center,
                           double radius);

// Ray origin + t * dir (dir a unit vector), t >= 0: the smallest t at which it meets the segment
// a-b, or kNoHit. A ray running along the segment meets it at its first point.
double ray_segment(const Vec2& origin, const Vec2& dir, const Vec2& a,
                   const Vec2& b);

// The smallest t >= 0 at which the ray meets the disc's boundary, 0 when the origin is inside,
// kNoHit when it misses.
double ray_circle(const Vec2& origin, const Vec2& dir,
                  const Vec2& center, double radius);

// Segments a-b and c-d share a point.
bool segments_intersect(const Vec2& a, const Vec2& b, const Vec2& c,
                        const Vec2& d);

// 2D cross product (z of the 3D one).
inline double cross(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

}  // namespace autonomy::geometry
