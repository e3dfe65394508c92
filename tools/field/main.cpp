// field_tool: the cost-to-goal field of a ROS map_server map (YAML + PGM) for one goal cell.
//
//   field_tool --map map.yaml --goal COL ROW [--out field.f32] [--resolution-scale]
//
// Cells and the output file use the image's own indexing: COL counts from the left edge, ROW from
// the top edge of the PGM, and the output's first row is the image's top row, so the field lines
// up pixel for pixel with the map image. Output: width * height raw little-endian float32,
// row-major; +inf where no route exists (occupied, unknown and cut-off cells). Costs are in cells
// (steps 1 and sqrt(2)) unless --resolution-scale, which multiplies the steps by the map's
// resolution (metres). The field is common/grid's compute_cost_to_go (bit-identical to a textbook
// float Dijkstra on the same graph; 8-connected, no corner cutting).
//
// Exit status: 0 ok; 2 bad input (map unreadable or invalid, goal outside the map or on a blocked
// cell); 1 the output could not be written; CLI11's codes for bad arguments.
#include "common/grid/cost_to_go.hpp"
#include "common/grid/map_loader.hpp"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <vector>

namespace {

using namespace autonomy::grid;

bool host_is_little_endian() {
  const std::uint32_t one = 1;
  unsigned char first = 0;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

// Rows top first (image order), little-endian float32.
bool write_field(const std::string& path, const CostField& field) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) return false;
  const bool swap = !host_is_little_endian();
  std::vector<char> row(static_cast<std::size_t>(field.width()) * 4);
  for (int y = 0; y < field.height(); ++y) {
    const int raster_row = field.height() - 1 - y;
    const float* src = field.costs().data() + static_cast<std::size_t>(raster_row) *
                                                  static_cast<std::size_t>(field.width());
    std::memcpy(row.data(), src, row.size());
    if (swap) {
      for (std::size_t i = 0; i < row.size(); i += 4) {
        std::swap(row[i], row[i + 3]);
        std::swap(row[i + 1], row[i + 2]);
      }
    }
    out.write(row.data(), static_cast<std::streamsize>(row.size()));
  }
  return static_cast<bool>(out.flush());
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "Computes the cost-to-goal field of a ROS map_server map (YAML + PGM) for one goal cell.\n"
      "Cells are indexed as in the image: COL from the left, ROW from the TOP row of the PGM.\n"
      "Output (--out): width*height raw little-endian float32, row-major, first row = top row of\n"
      "the PGM (lines up with the image); +inf where no route exists. Occupied and unknown cells\n"
      "(between free_thresh and occupied_thresh) are blocked. Costs are in cells (steps 1 and\n"
      "sqrt 2) unless --resolution-scale (metres). Exit 2 on a bad map or goal."};
  std::string map_path;
  std::vector<int> goal;
  std::string out_path;
  bool resolution_scale = false;
  app.add_option("--map", map_path, "map YAML (ROS map_server format)")->required();
  app.add_option("--goal", goal, "goal cell: COL ROW (row 0 = top row of the image)")
      ->required()
      ->expected(2);
  app.add_option("--out", out_path, "output file: raw little-endian float32, row 0 = top row");
  app.add_flag("--resolution-scale", resolution_scale,
               "multiply step costs by the map resolution (costs in metres, not cells)");
  CLI11_PARSE(app, argc, argv);

  auto loaded = load_ros_map(map_path);
  if (!loaded.ok()) {
    std::cerr << "field_tool: " << loaded.error << "\n";
    return 2;
  }
  const auto& map = *loaded.map;
  const int width = map.raster.width();
  const int height = map.raster.height();
  const int col = goal[0];
  const int image_row = goal[1];
  if (col < 0 || image_row < 0 || col >= width || image_row >= height) {
    std::cerr << "field_tool: goal (" << col << ", " << image_row << ") is outside the " << width
              << " x " << height << " map " << map_path << "\n";
    return 2;
  }
  const Cell goal_cell{col, height - 1 - image_row};
  if (map.raster.blocked(goal_cell)) {
    std::cerr << "field_tool: goal (" << col << ", " << image_row
              << ") is on a blocked cell (occupied or unknown) of " << map_path << "\n";
    return 2;
  }

  // Without --resolution-scale the search runs on the same cells with unit resolution.
  const OccupancyRaster raster = resolution_scale ? map.raster : map.raster.with_resolution(1.0);

  const auto t0 = std::chrono::steady_clock::now();
  const auto result = compute_cost_to_go(raster, goal_cell);
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  if (!result.ok()) {  // checked above; kept for safety
    std::cerr << "field_tool: " << result.reason << "\n";
    return 2;
  }

  std::printf("map: %s (%d x %d, resolution %g m, %zu free, %zu occupied, %zu unknown)\n",
              map_path.c_str(), width, height, map.raster.resolution_m(), map.metadata.free_cells,
              map.metadata.occupied_cells, map.metadata.unknown_cells);
  std::printf("goal: col %d, row %d from the top\n", col, image_row);
  std::printf("cells: %zu\nreachable: %zu\nunits: %s\ncompute_ms: %.3f\n", result.stats.cells,
              result.stats.reachable, resolution_scale ? "metres" : "cells", ms);
  if (!out_path.empty()) {
    if (!write_field(out_path, result.field)) {
      std::cerr << "field_tool: cannot write " << out_path << "\n";
      return 1;
    }
    std::printf("wrote: %s (%zu bytes, float32 little-endian, row 0 = top row)\n", out_path.c_str(),
                result.stats.cells * 4);
  }
  return 0;
}
