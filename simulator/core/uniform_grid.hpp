#pragma once
// A uniform grid of cells over a rectangle, each cell holding the values (robot handles) whose
// point lies in it, so "who is near this point" looks at the few cells around it instead of at
// every value: the world's robot-robot collision tests and the robots a range scan can meet use it
// (world.cpp), so their cost grows with the robots nearby, not with all robots.
//
// Points outside the rectangle are kept in the nearest edge cell, so a query never misses a value
// because of where it is; queries by box visit every cell the box touches (a superset: callers
// still test the exact geometry). Values in a cell are in insertion order, which callers must not
// depend on (the world picks the smallest id where an order matters).
#include "common/geometry/geometry.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace autonomy::sim {

template <typename T>
class UniformGrid {
 public:
  UniformGrid() = default;
  // Covers [0, width] x [0, height] with square cells of cell_m (>= 1e-3), at most
  // max_cells_per_side per side (the cells grow to respect that).
  UniformGrid(double width, double height, double cell_m, int max_cells_per_side = 512) {
    const double extent = std::max(width, height);
    cell_ = std::max({cell_m, 1e-3, extent / std::max(1, max_cells_per_side)});
    nx_ = std::max(1, static_cast<int>(std::ceil(width / cell_)));
    ny_ = std::max(1, static_cast<int>(std::ceil(height / cell_)));
    cells_.assign(static_cast<size_t>(nx_) * static_cast<size_t>(ny_), {});
  }

  void insert(const T& value, const geometry::Vec2& p) { cells_[cell_of(p)].push_back(value); }

  // Removes `value` from the cell of `p` (where it was inserted or last moved to); false if absent.
  bool erase(const T& value, const geometry::Vec2& p) {
    std::vector<T>& cell = cells_[cell_of(p)];
    const auto it = std::find(cell.begin(), cell.end(), value);
    if (it == cell.end()) return false;
    *it = cell.back();
    cell.pop_back();
    return true;
  }

  void move(const T& value, const geometry::Vec2& from, const geometry::Vec2& to) {
    if (cell_of(from) == cell_of(to)) return;
    erase(value, from);
    insert(value, to);
  }

  // f(value) for every value in the cells the box [lo, hi] touches.
  template <typename F>
  void for_each_in_box(const geometry::Vec2& lo, const geometry::Vec2& hi, F&& f) const {
    if (cells_.empty()) return;
    const int x0 = column(lo.x()), x1 = column(hi.x());
    const int y0 = row(lo.y()), y1 = row(hi.y());
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        for (const T& v : cells_[static_cast<size_t>(y) * static_cast<size_t>(nx_) + static_cast<size_t>(x)]) f(v);
      }
    }
  }

  double cell_size_m() const { return cell_; }

 private:
  int column(double x) const { return clamp_index(x, nx_); }
  int row(double y) const { return clamp_index(y, ny_); }
  int clamp_index(double v, int n) const {
    const double k = std::floor(v / cell_);
    if (!(k >= 0.0)) return 0;  // also NaN
    return k >= n - 1 ? n - 1 : static_cast<int>(k);
  }
  size_t cell_of(const geometry::Vec2& p) const {
    return static_cast<size_t>(row(p.y())) * static_cast<size_t>(nx_) + static_cast<size_t>(column(p.x()));
  }

  double cell_ = 1.0;
  int nx_ = 0;
  int ny_ = 0;
  std::vector<std::vector<T>> cells_;
};

}  // namespace autonomy::sim
