#include "simulator/radio/raster_attenuator.hpp"

#include "simulator/radio/radio_parameters.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace autonomy::sim::radio {

using geometry::Vec2;

namespace {

constexpr double kRasterTol = kBoundaryToleranceM;
constexpr int kBlockShift = 4;  // 16 x 16 cells per summary block
constexpr int kBlockCells = 1 << kBlockShift;
constexpr int kNoLine = std::numeric_limits<int>::min();
constexpr double kInf = std::numeric_limits<double>::infinity();

// Cell (x, y) is blocked; cells outside the raster are free.
class Bits {
 public:
  explicit Bits(const grid::OccupancyRaster& g)
      : w_(g.width()), h_(g.height()), wpr_(g.words_per_row()),
        words_(g.height() > 0 ? g.row_words(0) : nullptr) {}
  bool operator()(int x, int y) const {
    if (static_cast<unsigned>(x) >= static_cast<unsigned>(w_) ||
        static_cast<unsigned>(y) >= static_cast<unsigned>(h_))
      return false;
    const std::uint64_t word = words_[static_cast<size_t>(y) * wpr_ + (static_cast<unsigned>(x) >> 6)];
    return (word >> (static_cast<unsigned>(x) & 63u)) & 1u;
  }

 private:
  int w_;
  int h_;
  size_t wpr_;
  const std::uint64_t* words_;
};

// Runs of the segment inside the obstacle, in segment parameters t in [0, 1].
struct Runs {
  double tol_t = 0.0;
  int count = 0;
  double inside_t = 0.0;
  bool whole = false;  // one run from end to end

  void close(double start, double end) {
    if (end - start <= tol_t) return;  // touching, not inside
    ++count;
    inside_t += end - start;
    if (start <= tol_t && end >= 1.0 - tol_t) whole = true;
  }
  Traversal traversal(double length_m) const {
    return {count - (whole ? 1 : 0), count, inside_t * length_m};
  }
};

// One axis of the segment in cell units: position p + d t. A flat axis (extent within the
// tolerance) keeps one cell, or lies on grid line `line` (then the cells on both sides count).
struct Axis {
  double p = 0.0;
  double d = 0.0;
  bool flat = false;
  int line = kNoLine;
  int cell = 0;
};

// Sets up an axis; false when the segment lies outside the raster along it (all free).
bool make_axis(double p, double d, int n, double tol_c, Axis& axis) {
  axis.p = p;
  axis.d = d;
  axis.flat = std::abs(d) <= tol_c;
  if (!axis.flat) return true;
  const double c = p + 0.5 * d;
  if (!(c >= -tol_c && c <= n + tol_c)) return false;
  const double m = std::round(c);
  if (std::abs(c - m) <= tol_c) {
    // On a grid line: on the raster's border the outer side is free, so nothing is inside.
    if (m <= 0.0 || m >= n) return false;
    axis.line = static_cast<int>(m);
  } else {
    axis.cell = static_cast<int>(std::floor(c));
  }
  return true;
}

}  // namespace

RasterAttenuator::RasterAttenuator(std::shared_ptr<const grid::OccupancyRaster> raster,
                                   double loss_per_wall_db, double loss_per_metre_db,
                                   std::string name)
    : raster_(std::move(raster)), loss_per_wall_db_(loss_per_wall_db),
      loss_per_metre_db_(loss_per_metre_db), name_(std::move(name)) {
  if (auto why = raster_attenuator_problem(raster_, loss_per_wall_db_, loss_per_metre_db_, name_))
    throw std::invalid_argument(*why);
  const grid::OccupancyRaster& g = *raster_;
  block_cols_ = (g.width() + kBlockCells - 1) >> kBlockShift;
  const int block_rows = (g.height() + kBlockCells - 1) >> kBlockShift;
  free_blocks_.assign(static_cast<size_t>(block_cols_) * static_cast<size_t>(block_rows), 1);
  for (int row = 0; row < g.height(); ++row) {
    const std::uint64_t* words = g.row_words(row);
    for (size_t k = 0; k < g.words_per_row(); ++k) {
      std::uint64_t word = words[k];
      while (word != 0) {
        const int col = static_cast<int>(k * 64) + __builtin_ctzll(word);
        free_blocks_[static_cast<size_t>(row >> kBlockShift) * static_cast<size_t>(block_cols_) +
                     static_cast<size_t>(col >> kBlockShift)] = 0;
        word &= word - 1;
      }
    }
  }
}

RasterAttenuator RasterAttenuator::obstacle(std::shared_ptr<const grid::OccupancyRaster> raster,
                                            const RadioParameters& params, std::string name) {
  return RasterAttenuator(std::move(raster), params.wall_loss_db, params.inside_loss_db_per_m,
                          std::move(name));
}

geometry::Rect RasterAttenuator::bounds() const {
  const grid::OccupancyRaster& g = *raster_;
  const double res = g.resolution_m();
  return {g.origin().x, g.origin().y, g.origin().x + g.width() * res, g.origin().y + g.height() * res};
}

std::optional<std::string> raster_attenuator_problem(
    const std::shared_ptr<const grid::OccupancyRaster>& raster, double loss_per_wall_db,
    double loss_per_metre_db, const std::string& name) {
  if (!raster) return "map '" + name + "' has no raster";
  if (raster->origin().yaw != 0.0) return "map '" + name + "' is rotated; only yaw 0 attenuates radio";
  if (!std::isfinite(raster->origin().x) || !std::isfinite(raster->origin().y) ||
      !(raster->resolution_m() > 0.0) || !std::isfinite(raster->resolution_m()))
    return "map '" + name + "' has a non-finite origin or a non-positive resolution";
  for (double v : {loss_per_wall_db, loss_per_metre_db}) {
    if (!std::isfinite(v) || v < 0.0) return "map '" + name + "': losses must be finite and >= 0";
  }
  return std::nullopt;
}

Traversal RasterAttenuator::traverse(const Vec2& a, const Vec2& b) const {
  const grid::OccupancyRaster& g = *raster_;
  const int n[2] = {g.width(), g.height()};
  const double length_m = (b - a).norm();
  if (n[0] == 0 || n[1] == 0 || !(length_m > kRasterTol)) return {};
  const double res = g.resolution_m();
  const double tol_c = kRasterTol / res;
  const double tol_t = kRasterTol / length_m;

  // Cell units; clip the parameter range to the raster (outside is free).
  Axis ax[2];
  double t0 = 0.0;
  double t1 = 1.0;
  const double p[2] = {(a.x() - g.origin().x) / res, (a.y() - g.origin().y) / res};
  const double d[2] = {(b.x() - a.x()) / res, (b.y() - a.y()) / res};
  for (int k = 0; k < 2; ++k) {
    if (!make_axis(p[k], d[k], n[k], tol_c, ax[k])) return {};
    if (ax[k].flat) continue;
    double ta = -p[k] / d[k];
    double tb = (n[k] - p[k]) / d[k];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  if (t1 - t0 <= tol_t) return {};

  // Start cells, steps, and the parameter of the next grid line ahead on each axis.
  int cell[2];
  int step[2];
  double inv[2];
  double next[2];
  for (int k = 0; k < 2; ++k) {
    if (ax[k].flat) {
      cell[k] = ax[k].cell;
      step[k] = 0;
      inv[k] = 0.0;
      next[k] = kInf;
      continue;
    }
    step[k] = ax[k].d > 0.0 ? 1 : -1;
    inv[k] = 1.0 / ax[k].d;
  }
  // The cell the segment is in just after parameter t along axis k: on (or within the tolerance
  // of) a grid line, the cell beyond it.
  const auto cell_after = [&](int k, double t) {
    const double c = ax[k].p + ax[k].d * t;
    int i = static_cast<int>(std::floor(c));
    if (step[k] > 0 && (i + 1) - c <= tol_c) ++i;
    if (step[k] < 0 && c - i <= tol_c) --i;
    return i;
  };
  const auto line_at = [&](int k, int i) { return ((i + (step[k] > 0 ? 1 : 0)) - ax[k].p) * inv[k]; };
  for (int k = 0; k < 2; ++k) {
    if (ax[k].flat) continue;
    cell[k] = std::clamp(cell_after(k, t0), 0, n[k] - 1);
    next[k] = line_at(k, cell[k]);
  }

  const Bits bit(g);
  const int line_x = ax[0].line;
  const int line_y = ax[1].line;
  const auto occupied = [&](int x, int y) {
    if (line_x != kNoLine) return bit(line_x - 1, y) && bit(line_x, y);
    if (line_y != kNoLine) return bit(x, line_y - 1) && bit(x, line_y);
    return bit(x, y);
  };
  const bool can_skip = line_x == kNoLine && line_y == kNoLine;

  Runs runs;
  runs.tol_t = tol_t;
  int x = cell[0];
  int y = cell[1];
  bool in_run = occupied(x, y);
  double run_start = t0;
  // Every step enters a new cell or block; more than n0 + n1 + 4 of them would be a bug.
  for (int guard = n[0] + n[1] + 4; guard > 0; --guard) {
    if (can_skip && !in_run && block_free(x >> kBlockShift, y >> kBlockShift)) {
      // Nothing blocked in this block: jump to where the segment leaves it.
      double leave[2];
      for (int k = 0; k < 2; ++k) {
        const int i = k == 0 ? x : y;
        const int edge = step[k] > 0 ? ((i >> kBlockShift) + 1) << kBlockShift : (i >> kBlockShift) << kBlockShift;
        leave[k] = step[k] == 0 ? kInf : (edge - ax[k].p) * inv[k];
      }
      const double t = std::min(leave[0], leave[1]);
      if (t >= t1) break;
      int to[2] = {x, y};
      for (int k = 0; k < 2; ++k) {
        const int i = to[k];
        const int lo = (i >> kBlockShift) << kBlockShift;
        if (step[k] != 0 && leave[k] <= t + tol_t) {
          to[k] = step[k] > 0 ? lo + kBlockCells : lo - 1;  // crossed this axis' block edge
        } else if (step[k] != 0) {
          to[k] = std::clamp(cell_after(k, t), lo, lo + kBlockCells - 1);
        }
      }
      x = to[0];
      y = to[1];
      if (x < 0 || x >= n[0] || y < 0 || y >= n[1]) break;  // left the raster: the rest is free
      next[0] = step[0] == 0 ? kInf : line_at(0, x);
      next[1] = step[1] == 0 ? kInf : line_at(1, y);
      if (occupied(x, y)) {
        in_run = true;
        run_start = t;
      }
      continue;
    }
    const double t = std::min(next[0], next[1]);
    if (t >= t1) break;
    // Through a lattice point (both lines at once, within the tolerance): a diagonal step that
    // touches the two side cells only at the corner.
    const bool corner = std::abs(next[0] - next[1]) <= tol_t;
    const bool step_x = corner || next[0] < next[1];
    const bool step_y = corner || !step_x;
    const int nx = step_x ? x + step[0] : x;
    const int ny = step_y ? y + step[1] : y;
    const bool next_occupied = occupied(nx, ny);
    if (in_run) {
      const bool joined = next_occupied && (!corner || (occupied(nx, y) && occupied(x, ny)));
      if (!joined) {
        runs.close(run_start, t);
        in_run = false;
        if (next_occupied) {  // leaves one wall at a corner and enters another
          in_run = true;
          run_start = t;
        }
      }
    } else if (next_occupied) {
      in_run = true;
      run_start = t;
    }
    x = nx;
    y = ny;
    // Both computed, one kept: selects instead of branches the CPU cannot predict on slanted paths.
    const double next_x = line_at(0, x);
    const double next_y = line_at(1, y);
    next[0] = step_x ? next_x : next[0];
    next[1] = step_y ? next_y : next[1];
    if (!in_run && (x < 0 || x >= n[0] || y < 0 || y >= n[1])) break;
  }
  if (in_run) runs.close(run_start, t1);
  return runs.traversal(length_m);
}

Traversal traverse_raster_reference(const grid::OccupancyRaster& g, const Vec2& a, const Vec2& b) {
  const double length_m = (b - a).norm();
  if (g.width() == 0 || g.height() == 0 || !(length_m > kRasterTol)) return {};
  const double res = g.resolution_m();
  const double tol_c = kRasterTol / res;
  const double tol_t = kRasterTol / length_m;
  const Vec2 p((a.x() - g.origin().x) / res, (a.y() - g.origin().y) / res);
  const Vec2 d((b.x() - a.x()) / res, (b.y() - a.y()) / res);
  const Bits bit(g);

  // A point is inside when every cell whose closed square holds it (within the tolerance) is
  // blocked: the interior of the union of blocked cells.
  const auto inside = [&](double t) {
    const Vec2 q = p + d * t;
    const int x0 = static_cast<int>(std::floor(q.x() - tol_c));
    const int x1 = static_cast<int>(std::floor(q.x() + tol_c));
    const int y0 = static_cast<int>(std::floor(q.y() - tol_c));
    const int y1 = static_cast<int>(std::floor(q.y() + tol_c));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x)
        if (!bit(x, y)) return false;
    return true;
  };

  std::vector<double> cuts = {0.0, 1.0};
  for (int k = 0; k < 2; ++k) {
    if (std::abs(d[k]) <= tol_c) continue;  // runs along the axis: no line crossed
    const double lo = std::min(p[k], p[k] + d[k]);
    const double hi = std::max(p[k], p[k] + d[k]);
    const int first = std::max(static_cast<int>(std::ceil(lo)), -1);
    const int last = std::min(static_cast<int>(std::floor(hi)), (k == 0 ? g.width() : g.height()) + 1);
    for (int m = first; m <= last; ++m) {
      const double t = (m - p[k]) / d[k];
      if (t > 0.0 && t < 1.0) cuts.push_back(t);
    }
  }
  std::sort(cuts.begin(), cuts.end());
  // Merge cuts closer than the tolerance (a lattice point, or a line at an end).
  std::vector<double> points;
  for (double t : cuts) {
    if (!points.empty() && t - points.back() <= tol_t) continue;
    points.push_back(t);
  }
  if (points.back() < 1.0) points.back() = 1.0;

  Runs runs;
  runs.tol_t = tol_t;
  bool in_run = false;
  double run_start = 0.0;
  for (size_t i = 0; i + 1 < points.size(); ++i) {
    const bool piece = inside(0.5 * (points[i] + points[i + 1]));
    // The cut at points[i] joins two inside pieces only if the point itself is inside.
    if (in_run && !(piece && inside(points[i]))) {
      runs.close(run_start, points[i]);
      in_run = false;
    }
    if (piece && !in_run) {
      in_run = true;
      run_start = points[i];
    }
  }
  if (in_run) runs.close(run_start, 1.0);
  return runs.traversal(length_m);
}

}  // namespace autonomy::sim::radio
