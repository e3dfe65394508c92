#pragma once
// What takes signal away besides distance: obstacles (walls, buildings: rectangles or simple
// polygons) and attenuating areas declared in a scenario (alleys, parked cars, trees, ...).
//
// A Shape answers one question: where does the straight segment a-b run inside me? The answer,
// a Traversal, is what the losses are computed from:
//   crossings  how many times the segment passes between outside and inside (walls crossed);
//   stretches  how many separate pieces of the segment lie inside (entries into an area);
//   inside_m   the total length of those pieces.
//
// Boundary convention (all shapes, both directions of the segment, so a-b and b-a agree):
// - The boundary itself is outside. A segment that only touches a vertex or an edge, or runs
//   along an edge, is not inside there: no crossing, no length.
// - Crossings are counted only at interior points of the segment. An endpoint (a radio) inside a
//   shape, or on its boundary, pays for the walls the segment passes on its way out, not for one
//   it stands in: a radio inside a building to a radio outside crosses 1 wall.
// - Geometric tolerance kBoundaryToleranceM (1 nm): points that close to the boundary are on it.
//   Polygons are closed implicitly, are simple (no self-intersection), of any orientation,
//   convex or not.
#include "common/geometry/geometry.hpp"
#include "common/geometry/shapes.hpp"

#include <optional>
#include <string>
#include <vector>

namespace autonomy::sim::radio {

struct RadioParameters;

inline constexpr double kBoundaryToleranceM = geometry::kSamePointM;

struct Traversal {
  int crossings = 0;
  int stretches = 0;
  double inside_m = 0.0;
};

class Shape {
 public:
  // Throws std::invalid_argument for an invalid rectangle (see Rect::valid).
  static Shape rect(const geometry::Rect& r);
  // Throws std::invalid_argument when polygon_problem() finds one.
  static Shape polygon(std::vector<geometry::Vec2> vertices);

  bool is_rect() const { return is_rect_; }
  bool is_convex() const { return is_rect_ || convex_; }
  const geometry::Rect& bounds() const { return bounds_; }
  // The corners, counter-clockwise (a rectangle's four from its min corner; a polygon given
  // clockwise is stored reversed).
  const std::vector<geometry::Vec2>& vertices() const { return vertices_; }

  Traversal traverse(const geometry::Vec2& a, const geometry::Vec2& b) const;
  // Strictly inside (the boundary is outside).
  bool contains(const geometry::Vec2& p) const;

 private:
  Shape() = default;
  bool is_rect_ = false;
  bool convex_ = false;  // polygons: clipped directly instead of split and classified
  geometry::Rect bounds_;
  std::vector<geometry::Vec2> vertices_;
};

using geometry::polygon_problem;  // the shared check (common/geometry/shapes.hpp)

// A shape and what it costs a signal path: loss = crossings * loss_per_crossing_db
// + stretches * loss_per_stretch_db + inside_m * loss_per_metre_db.
struct Attenuator {
  Shape shape;
  double loss_per_crossing_db = 0.0;
  double loss_per_stretch_db = 0.0;
  double loss_per_metre_db = 0.0;
  std::string name;  // for reports and error messages; may be empty

  // A wall or building: params.wall_loss_db per boundary crossed, params.inside_loss_db_per_m.
  static Attenuator obstacle(Shape shape, const RadioParameters& params, std::string name = {});
  // A declared attenuating area: entry_loss_db once per piece of path inside (whichever way the
  // signal goes), loss_per_metre_db inside.
  static Attenuator area(Shape shape, double entry_loss_db, double loss_per_metre_db,
                         std::string name = {});

  double loss_db(const Traversal& t) const {
    return t.crossings * loss_per_crossing_db + t.stretches * loss_per_stretch_db +
           t.inside_m * loss_per_metre_db;
  }
};

// Why `a` cannot be used (negative or non-finite losses), or nothing.
std::optional<std::string> attenuator_problem(const Attenuator& a);

namespace detail {
// The general (any simple polygon) and convex (counter-clockwise) routines behind
// Shape::traverse, exposed so tests can check them against each other on the same shapes.
Traversal traverse_any_polygon(const std::vector<geometry::Vec2>& vertices,
                               const geometry::Vec2& a, const geometry::Vec2& b);
Traversal traverse_convex_polygon(const std::vector<geometry::Vec2>& ccw_vertices,
                                  const geometry::Vec2& a, const geometry::Vec2& b);
}  // namespace detail

// Obstacles for the simulator's rectangular world obstacles, with the parameters' wall losses.
std::vector<Attenuator> obstacles_from_rects(const std::vector<geometry::Rect>& rects,
                                             const RadioParameters& params);

}  // namespace autonomy::sim::radio
