#pragma once
// Loading occupancy maps in the ROS map_server format: a YAML file naming a PGM image.
//
//   image: map.pgm              # relative to the YAML file's directory (or absolute)
//   resolution: 0.05            # metres per pixel, > 0
//   origin: [-10.0, -5.0, 0.0]  # x, y, yaw of the lower-left pixel's outer corner
//   occupied_thresh: 0.65       # required, 0..1
//   free_thresh: 0.196          # required, 0..1, < occupied_thresh
//   negate: 0                   # optional, 0/1 or false/true, default 0
//   mode: trinary               # optional, trinary (default) or scale; raw is refused
//
// A pixel's occupancy probability is p = (maxval - v) / maxval, or v / maxval when negated, as in
// map_server. A cell is *free* when p < free_thresh, *occupied* when p > occupied_thresh and
// *unknown* otherwise. For planning the raster is binary: only free cells are free; occupied and
// unknown cells are blocked (a robot does not plan through space nobody has seen). In scale mode
// map_server turns the in-between values into graded costs; this loader blocks them all the same.
//
// Orientation: the image's first pixel row is the top of the map (highest y), so it becomes raster
// row height - 1; raster row 0 is the image's last row (see occupancy_raster.hpp).
//
// Images: PGM only, binary (P5) or ASCII (P2), maxval 1..65535 (8-bit or 16-bit big-endian
// samples), '#' comments in the header. Errors come back as values: YAML problems as
// "file:line: message", PGM problems as "file: message" (bad header, truncated data, ...).
#include "common/grid/occupancy_raster.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace autonomy::grid {

struct PgmImage {
  int width = 0;
  int height = 0;
  int maxval = 0;
  std::vector<std::uint16_t> pixels;  // row-major, first row = top of the image
};

struct [[nodiscard]] PgmResult {
  std::optional<PgmImage> image;
  std::string error;
  bool ok() const { return image.has_value(); }
};

// `name` only labels error messages.
PgmResult parse_pgm(const std::string& bytes, const std::string& name);
PgmResult load_pgm(const std::string& path);

enum class MapMode { kTrinary, kScale };

struct MapMetadata {
  std::string yaml_path;
  std::string image_path;  // as resolved against the YAML's directory
  double occupied_thresh = 0.65;
  double free_thresh = 0.196;
  bool negate = false;
  MapMode mode = MapMode::kTrinary;
  std::size_t free_cells = 0;
  std::size_t occupied_cells = 0;
  std::size_t unknown_cells = 0;  // blocked in the raster
};

struct OccupancyMap {
  OccupancyRaster raster;
  MapMetadata metadata;
};

struct [[nodiscard]] MapLoadResult {
  std::optional<OccupancyMap> map;
  std::string error;
  bool ok() const { return map.has_value(); }
};

MapLoadResult load_ros_map(const std::string& yaml_path);

// The raster of an image with the given thresholds; the YAML-free part of load_ros_map.
OccupancyMap occupancy_from_image(const PgmImage& image, double resolution_m, RasterOrigin origin,
                                  const MapMetadata& metadata);

}  // namespace autonomy::grid
