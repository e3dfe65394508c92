#pragma once
// The static obstacles of a world in one queryable structure: axis-aligned rectangles, polygons
// and occupancy rasters (ROS map_server maps), with the world boundary as a wall.
//
// Two questions, both exact for the geometry as given (no rasterising of vector shapes):
//   overlap(c, r)       which obstacle, if any, a disc overlaps (touching is free, as in
//                       free_space.hpp); raster cells are squares, blocked cells are obstacles;
//   cast(o, dir, max)   how far a ray travels before it meets an obstacle or the boundary.
//
// Why it is fast. Rectangles and polygons are registered in a uniform grid of cells (about 1 to
// 4 m): areas by bounding box (for overlap), edges by bounding box (for rays). A ray walks that
// grid cell by cell (Amanatides & Woo 1987), testing only the edges registered where it is, and
// stops at the first cell whose exit lies beyond the nearest hit found. A raster is walked the
// same way in its own cells, reading one bit per cell. A ray therefore costs about
// (length / cell size) cell visits whatever the number of obstacles.
//
// Rasters must be axis-aligned (origin yaw 0); cells outside a raster are free (a map covers a
// part of the world). Built once; queries are const and may run on several threads.
#include "common/geometry/geometry.hpp"
#include "common/grid/occupancy_raster.hpp"
#include "simulator/core/shapes.hpp"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace autonomy::sim {

// An occupancy raster placed in the world by its own origin (map frame == world frame).
struct RasterLayer {
  std::string name;  // e.g. the YAML file it came from, for messages
  std::shared_ptr<const grid::OccupancyRaster> raster;
};

struct ObstacleRef {
  enum class Kind { Rect, Polygon, Raster };
  Kind kind = Kind::Rect;
  std::size_t index = 0;  // into the rects, polygons or rasters the map was built from
  grid::Cell cell;        // Raster only: the blocked cell
};

class ObstacleMap {
 public:
  ObstacleMap() = default;
  // Throws std::invalid_argument for a non-positive size, an invalid rectangle, a polygon with a
  // polygon_problem, or a raster that is null or rotated.
  ObstacleMap(double width, double height, std::vector<geometry::Rect> rects,
              std::vector<Polygon> polygons, std::vector<RasterLayer> rasters);

  // The first obstacle (rectangles, then polygons, then rasters) the disc overlaps.
  std::optional<ObstacleRef> overlap(const geometry::Vec2& center, double radius) const;
  // Distance along origin + t * dir (dir a unit vector) to the first obstacle or world boundary,
  // capped at max_range: max_range means nothing within range. 0 when the origin is inside one.
  double cast(const geometry::Vec2& origin, const geometry::Vec2& dir, double max_range) const;
  // No obstacle between a and b (an obstacle touched exactly at b does not count).
  bool clear(const geometry::Vec2& a, const geometry::Vec2& b) const;

  // "obstacle 3", "polygon 2 'hall wall'", "map 'floor.yaml' cell (12, 40)".
  std::string describe(const ObstacleRef& ref) const;

  double width() const { return width_; }
  double height() const { return height_; }
  double cell_size_m() const { return cell_; }

 private:
  struct Segment {
    geometry::Vec2 a;
    geometry::Vec2 b;
  };
  struct Area {
    ObstacleRef::Kind kind;
    std::uint32_t index;
  };

  template <typename F>
  void for_cells(const geometry::Rect& box, F&& f) const;
  double cast_vector(const geometry::Vec2& origin, const geometry::Vec2& dir, double max_range) const;

  double width_ = 0.0;
  double height_ = 0.0;
  std::vector<geometry::Rect> rects_;
  std::vector<Polygon> polygons_;
  std::vector<RasterLayer> rasters_;

  double cell_ = 1.0;
  int nx_ = 0;
  int ny_ = 0;
  std::vector<Segment> segments_;
  // CSR per cell: segments (for rays) and areas (for overlap).
  std::vector<std::uint32_t> segment_offsets_;
  std::vector<std::uint32_t> segment_ids_;
  std::vector<std::uint32_t> area_offsets_;
  std::vector<Area> areas_;
};

// Where the ray origin + t * dir, 0 <= t <= max_range, first enters a blocked cell of `raster`
// (kNoHit when it does not). Cells outside the raster are free. Exposed for tests and benches.
double cast_raster(const grid::OccupancyRaster& raster, const geometry::Vec2& origin,
                   const geometry::Vec2& dir, double max_range);

}  // namespace autonomy::sim
