#pragma once
// The layer-free cost-to-goal search of compute_cost_to_go (internal to common/grid): label
// correcting over 8 x 8 tiles, each relaxed to its local fixed point with row-vector sweeps while
// it sits in L1, tiles scheduled roughly in order of distance. See tile_relaxation.cpp for why the
// result is the textbook float Dijkstra's, bit for bit.
#include "common/grid/occupancy_raster.hpp"

#include <cstddef>
#include <cstdint>

namespace autonomy::grid::detail {

struct TileSearchStats {
  std::size_t tiles = 0;       // tiles covering the raster
  std::size_t tile_runs = 0;   // tiles relaxed (a tile runs again when a neighbour improves it)
  std::size_t passes = 0;      // row sweeps over a tile, all runs together
  std::size_t reachable = 0;   // finite labels at the end
  std::size_t buckets = 0;     // ring of the tile scheduler
  std::size_t work_bytes = 0;  // scheduler and free-bit memory
};

// True when this build and CPU can run tile_search (x86 with AVX2).
bool tile_search_available();

// dist: raster.cell_count() labels, row-major, +inf everywhere except dist[goal] = 0. The moves
// are compute_cost_to_go's (8-connected, no corner cutting), read from the raster's bits tile by
// tile: there is no per-cell move array, so cells no tile run reaches cost nothing but their +inf.
// On return dist holds the fixed point label(v) = min over allowed moves u -> v of
// float(label(u) + step), step = orthogonal or diagonal.
TileSearchStats tile_search(std::size_t goal, const OccupancyRaster& raster, float orthogonal,
                            float diagonal, float* dist);

}  // namespace autonomy::grid::detail
