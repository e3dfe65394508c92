#pragma once
// Where the cells of a behavior grid lie in the world. The grid's origin is the world's origin
// (the world spans [0, width] x [0, height]); cell (col, row) covers
// [col * res, (col + 1) * res) x [row * res, (row + 1) * res). Occupancy and cost-to-go fields
// share one geometry so that a cell means the same place in both.
#include "common/geometry/geometry.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <optional>

namespace autonomy::behavior {

struct GridCell {
  int col = 0;
  int row = 0;

  bool operator==(const GridCell& o) const { return col == o.col && row == o.row; }
  bool operator!=(const GridCell& o) const { return !(*this == o); }
};

class GridGeometry {
 public:
  GridGeometry() = default;
  GridGeometry(int cols, int rows, double resolution_m)
      : cols_(cols), rows_(rows), resolution_m_(resolution_m) {
    assert(cols >= 0 && rows >= 0 && resolution_m > 0.0);
  }

  int cols() const { return cols_; }
  int rows() const { return rows_; }
  double resolution_m() const { return resolution_m_; }
  std::size_t cell_count() const {
    return static_cast<std::size_t>(cols_) * static_cast<std::size_t>(rows_);
  }

  bool contains(GridCell c) const { return c.col >= 0 && c.row >= 0 && c.col < cols_ && c.row < rows_; }

  // Row-major: neighbours along x are adjacent in memory.
  std::size_t index(GridCell c) const {
    assert(contains(c));
    return static_cast<std::size_t>(c.row) * static_cast<std::size_t>(cols_) +
           static_cast<std::size_t>(c.col);
  }
  GridCell cell(std::size_t index) const {
    return {static_cast<int>(index % static_cast<std::size_t>(cols_)),
            static_cast<int>(index / static_cast<std::size_t>(cols_))};
  }

  geometry::Vec2 centre(GridCell c) const {
    return {(c.col + 0.5) * resolution_m_, (c.row + 0.5) * resolution_m_};
  }

  // The cell holding p; nullopt outside the grid or for non-finite p. The far edges belong to the
  // last cells so that a goal on the world's border still has a cell.
  std::optional<GridCell> cell_at(const geometry::Vec2& p) const {
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || cols_ == 0 || rows_ == 0) return std::nullopt;
    const double fx = p.x() / resolution_m_;
    const double fy = p.y() / resolution_m_;
    if (fx < 0.0 || fy < 0.0 || fx > cols_ || fy > rows_) return std::nullopt;
    const int col = std::min(static_cast<int>(fx), cols_ - 1);
    const int row = std::min(static_cast<int>(fy), rows_ - 1);
    return GridCell{col, row};
  }

 private:
  int cols_ = 0;
  int rows_ = 0;
  double resolution_m_ = 1.0;
};

}  // namespace autonomy::behavior
