#pragma once
// Cost-to-goal fields ("internalized plans", robot-teams paper section 2.1): for every cell of an
// OccupancyRaster, the cost of the cheapest 8-connected path to one goal cell, found by a uniform
// cost search outwards from the goal. A robot reads which way is downhill from its own cell
// (section 2.2) instead of carrying a path.
//
// The graph
//   - Nodes are the free cells; blocked cells (and everything outside the raster) are impassable.
//   - Moves go to the 8 neighbours. A diagonal move needs both orthogonal cells beside it free, so
//     no path clips the corner of an obstacle (and a diagonal gap between two obstacles is closed).
//   - Step cost, computed in float (IEEE single, round to nearest, no fused multiply-add), in this
//     exact order:
//         base  = float(res)                 for E, N, W, S
//               = float(res * sqrt(2.0))     for the diagonals (product in double, rounded once)
//         extra = 0; for each layer i in order: extra = extra + gain_i * layer_i[entered cell]
//         cost(neighbour) candidate = cost(cell) + (base + extra)
//     i.e. the layers price the cell being *entered*. Layer values and gains must be finite and
//     >= 0 (obstacles belong in the raster); the goal's own layer value is never paid.
//
// Exactness contract
//   The field is the shortest-path distance of that graph in the float arithmetic above: it is
//   bit-for-bit the field a textbook Dijkstra (std::priority_queue, float labels, same step
//   function) computes, see reference_dijkstra(). Against the same search in double the difference
//   is float rounding only, accumulated along a path: measured max relative difference 1e-6 on
//   250 x 250, 1e-5 on 1000 x 1000 and up to 7e-5 on 4000 x 4000 maps (field_bench; long maze
//   paths). Unreachable and blocked cells hold +inf in both. The guarantee holds while costs stay
//   below 2^20 * res (a million straight steps); beyond that, float cannot add one step reliably
//   anyway.
//
// Why it is fast (tile_relaxation.cpp and docs/fields.md have the measurements)
//   Without layers, on x86 CPUs with AVX2: label correcting over 8 x 8 tiles. A tile, its one-cell
//   ring and its step costs are loaded into eight-lane row vectors and swept up and down (moves
//   from the row below/above as whole-vector adds and mins, moves along the row repeated until no
//   lane improves) until a sweep changes nothing; then only the neighbouring tiles that a move out
//   of it now improves are queued, in buckets of their smallest improved label. Most tiles run
//   once (measured 0.8-1.05 runs per tile on every map class), each run about two sweeps: about
//   34 instructions per cell against about 250 for a cell queue. A tile's allowed moves are read
//   from the raster's bits when it runs, so nothing is prepared per cell but the output and
//   unreached space costs only its +inf. Any relaxation order reaches the same fixed point (see
//   the .cpp), so the result is the textbook float Dijkstra's, bit for bit. Elsewhere (no AVX2,
//   or with layers): a bucket queue whose buckets are res/4 wide is exactly ordered: a cell popped
//   from bucket k can only push cells into buckets > k, hence every cell is final when its bucket
//   comes up and is expanded exactly once. There the allowed moves of every cell are precomputed
//   into one byte (8 bits, corner rule included), so the inner loops have no bounds or obstacle
//   tests.
//
// Memory: output (4 bytes/cell) + the tile scheduler (a float per tile, 0.06 bytes/cell);
// FieldStats::work_bytes reports the total the computation holds, output included: 4.06-4.3
// bytes/cell. The bucket queue adds the move masks (1 byte/cell) and its ring: 5.1-5.3 bytes/cell.
// Both under the 8-byte budget. The input raster is 1 bit per cell.
//
// Speed (bench/field_bench, see docs/fields.md): 15-42x less CPU time than the textbook Dijkstra
// with double labels on generated building floors, SLAM-like maps, mazes, small clutter and large
// blocks (250^2 .. 4000^2, goals at the centre, a corner or in a passage) and on Nav2's
// warehouse, depot and tb3_sandbox maps; e.g. about 5 ms against 100 ms at 1000^2. On a small
// arena in a large unknown grid (4-5 % reachable) the output's +inf fill dominates: the field
// takes 1.3-1.5 times one plain pass over the output there.
//
// Layers: the same bucket queue, with one candidate and bucket per move; when a layer's largest
// step would need a ring longer than min(4096, cells / 128) buckets (about 1000 resolutions on big
// maps), an exact binary heap over the same masks runs instead.
#include "common/geometry/geometry.hpp"
#include "common/grid/occupancy_raster.hpp"

#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace autonomy::grid {

constexpr float kUnreachable = std::numeric_limits<float>::infinity();

// An extra per-cell cost: `values` row-major as the raster (cell_count() floats), not owned; the
// pointed-to values must outlive the computation only.
struct CostLayer {
  const float* values = nullptr;
  std::size_t size = 0;
  float gain = 1.0f;

  CostLayer() = default;
  CostLayer(const std::vector<float>& v, float g) : values(v.data()), size(v.size()), gain(g) {}
};

// One of the 8 moves, as a cell offset. N is +row (+y).
struct Step {
  int dc = 0;
  int dr = 0;

  bool operator==(const Step& o) const { return dc == o.dc && dr == o.dr; }
};

// Move order: orthogonal first, then diagonals. It is the bit order of the move masks and the
// tie-break order of advice: E, N, W, S, NE, NW, SW, SE.
inline constexpr Step kMoves[8] = {{1, 0}, {0, 1},  {-1, 0},  {0, -1},
                                   {1, 1}, {-1, 1}, {-1, -1}, {1, -1}};

class CostField {
 public:
  CostField() = default;
  CostField(int width, int height, double resolution_m, Cell goal, std::vector<float> costs);

  int width() const { return width_; }
  int height() const { return height_; }
  double resolution_m() const { return resolution_m_; }
  Cell goal() const { return goal_; }

  bool contains(Cell c) const {
    return c.col >= 0 && c.row >= 0 && c.col < width_ && c.row < height_;
  }
  // +inf outside the raster, on blocked cells and where no route exists.
  float cost(Cell c) const {
    return contains(c) ? costs_[static_cast<std::size_t>(c.row) * static_cast<std::size_t>(width_) +
                                static_cast<std::size_t>(c.col)]
                       : kUnreachable;
  }
  bool reachable(Cell c) const { return cost(c) < kUnreachable; }

  // The move from c to its cheapest neighbour, among moves the search allows (a diagonal needs
  // both orthogonal cells beside it reachable: a reachable cell's free neighbours are reachable,
  // so "finite" stands for "free"). Only strictly cheaper neighbours count; ties go to the first
  // move in kMoves order. nullopt at the goal, on unreachable cells and outside the raster.
  std::optional<Step> downhill_step(Cell c) const;
  // downhill_step as a unit vector in the raster's (col, row) axes; zero where there is none.
  geometry::Vec2 advice(Cell c) const;

  // Row-major, index = row * width + col, row 0 = bottom.
  const std::vector<float>& costs() const { return costs_; }
  std::vector<float> release_costs() && { return std::move(costs_); }

 private:
  int width_ = 0;
  int height_ = 0;
  double resolution_m_ = 1.0;
  Cell goal_;
  std::vector<float> costs_;
};

enum class FieldStatus {
  kOk,
  kGoalOutside,  // the goal cell is not in the raster
  kGoalBlocked,  // the goal cell is blocked
  kBadLayer,     // a layer has the wrong size, a negative / non-finite value or gain
  kTooLarge,     // more than 2^32 - 1 cells (the queue stores 32-bit cell indices)
};

const char* to_string(FieldStatus s);

struct FieldStats {
  std::size_t cells = 0;
  std::size_t reachable = 0;
  std::size_t expanded = 0;     // cells popped and expanded (== reachable)
  std::size_t pushes = 0;       // queue insertions (the goal included)
  std::size_t buckets = 0;      // bucket-ring size (0 when the heap fallback ran)
  bool heap_fallback = false;   // layers so expensive that the ring would be too long
  std::size_t tiles = 0;        // without layers: 8 x 8 tiles covering the raster
  std::size_t tile_runs = 0;    // tiles relaxed (a tile runs again when a neighbour improves it)
  std::size_t tile_sweeps = 0;  // row sweeps over tiles, all runs together
  std::size_t work_bytes = 0;   // peak heap bytes held by the computation, output included
};

struct [[nodiscard]] FieldResult {
  FieldStatus status = FieldStatus::kOk;
  std::string reason;  // empty when ok
  CostField field;     // all +inf unless ok
  FieldStats stats;

  bool ok() const { return status == FieldStatus::kOk; }
};

// The field towards `goal` over `raster`, with optional extra cost layers (see the top of file).
FieldResult compute_cost_to_go(const OccupancyRaster& raster, Cell goal,
                               const std::vector<CostLayer>& layers = {});

// Textbook Dijkstra over the same graph and step function: std::priority_queue of (cost, index)
// with lazy deletion, bounds and obstacle tests per move. Real = float reproduces
// compute_cost_to_go bit for bit; Real = double is the "exact" yardstick. The goal must be a free
// cell of the raster and layers valid (it is the baseline for tests and benchmarks, not an API).
template <typename Real>
std::vector<Real> reference_dijkstra(const OccupancyRaster& raster, Cell goal,
                                     const std::vector<CostLayer>& layers = {});

extern template std::vector<float> reference_dijkstra<float>(const OccupancyRaster&, Cell,
                                                             const std::vector<CostLayer>&);
extern template std::vector<double> reference_dijkstra<double>(const OccupancyRaster&, Cell,
                                                               const std::vector<CostLayer>&);

}  // namespace autonomy::grid
