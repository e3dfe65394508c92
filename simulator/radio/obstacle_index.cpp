#include "simulator/radio/obstacle_index.hpp"

#include <algorithm>
#include <cmath>

namespace autonomy::sim::radio {

ObstacleIndex::ObstacleIndex(const std::vector<geometry::Rect>& boxes, double cell_size_m)
    : count_(boxes.size()) {
  if (boxes.empty()) return;
  geometry::Rect all = boxes.front();
  double side_sum = 0.0;
  for (const geometry::Rect& r : boxes) {
    all.min_x = std::min(all.min_x, r.min_x);
    all.min_y = std::min(all.min_y, r.min_y);
    all.max_x = std::max(all.max_x, r.max_x);
    all.max_y = std::max(all.max_y, r.max_y);
    side_sum += std::max(r.max_x - r.min_x, r.max_y - r.min_y);
  }
  const double width = std::max(all.max_x - all.min_x, 1e-6);
  const double height = std::max(all.max_y - all.min_y, 1e-6);
  double cell = cell_size_m;
  if (!(cell > 0.0)) {
    cell = std::max(side_sum / static_cast<double>(boxes.size()),
                    std::sqrt(width * height / static_cast<double>(boxes.size())));
  }
  constexpr int kMaxCells = 1024;
  cell = std::max({cell, width / kMaxCells, height / kMaxCells});
  // Margin so boxes on the outer edge and paths grazing them stay inside the grid.
  const double margin = 1e-6 * std::max(width, height) + 1e-9;
  x0_ = all.min_x - margin;
  y0_ = all.min_y - margin;
  cell_ = cell;
  nx_ = std::max(1, static_cast<int>(std::ceil((width + 2 * margin) / cell)));
  ny_ = std::max(1, static_cast<int>(std::ceil((height + 2 * margin) / cell)));

  const auto span = [&](const geometry::Rect& r, int& cx0, int& cy0, int& cx1, int& cy1) {
    const auto clampi = [](double v, int n) {
      return std::clamp(static_cast<int>(std::floor(v)), 0, n - 1);
    };
    cx0 = clampi((r.min_x - margin - x0_) / cell_, nx_);
    cy0 = clampi((r.min_y - margin - y0_) / cell_, ny_);
    cx1 = clampi((r.max_x + margin - x0_) / cell_, nx_);
    cy1 = clampi((r.max_y + margin - y0_) / cell_, ny_);
  };
  std::vector<uint32_t> counts(static_cast<size_t>(nx_) * ny_ + 1, 0);
  for (const geometry::Rect& r : boxes) {
    int cx0, cy0, cx1, cy1;
    span(r, cx0, cy0, cx1, cy1);
    for (int y = cy0; y <= cy1; ++y) {
      for (int x = cx0; x <= cx1; ++x) ++counts[static_cast<size_t>(y) * nx_ + x];
    }
  }
  offsets_.assign(counts.size(), 0);
  for (size_t c = 0; c + 1 < counts.size(); ++c) offsets_[c + 1] = offsets_[c] + counts[c];
  ids_.resize(offsets_.back());
  std::vector<uint32_t> fill(offsets_.begin(), offsets_.end() - 1);
  for (uint32_t id = 0; id < boxes.size(); ++id) {
    int cx0, cy0, cx1, cy1;
    span(boxes[id], cx0, cy0, cx1, cy1);
    for (int y = cy0; y <= cy1; ++y) {
      for (int x = cx0; x <= cx1; ++x) ids_[fill[static_cast<size_t>(y) * nx_ + x]++] = id;
    }
  }
}

}  // namespace autonomy::sim::radio
