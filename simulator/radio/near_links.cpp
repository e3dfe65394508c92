#include "simulator/radio/near_links.hpp"

#include "simulator/radio/link_range.hpp"

#include <algorithm>
#include <cmath>

namespace autonomy::sim::radio {

namespace {
// Grid of at most this many cells per side, whatever the range: a huge range makes one cell.
constexpr int kNearLinkMaxCellsPerSide = 1024;
}  // namespace

const LinkQuality* NearLinkTable::find(size_t i, size_t j) const {
  if (i == j || i >= n_ || j >= n_) return nullptr;
  if (i > j) std::swap(i, j);
  const auto begin = links_.begin() + first_of_[i];
  const auto end = links_.begin() + first_of_[i + 1];
  const auto it = std::lower_bound(begin, end, j, [](const NearLink& l, size_t v) { return l.j < v; });
  return it != end && it->j == j ? &it->quality : nullptr;
}

void NearLinkTable::update(const RadioModel& model, const std::vector<geometry::Vec2>& positions) {
  n_ = positions.size();
  links_.clear();
  pairs_in_range_ = 0;
  first_of_.assign(n_ + 1, 0);
  const std::optional<double> range = max_link_range_m(model.parameters());
  if (n_ < 2 || !range) return;

  // Bucket the radios by cell (counting sort), cells at least one range wide.
  double min_x = positions[0].x(), max_x = min_x, min_y = positions[0].y(), max_y = min_y;
  for (const auto& p : positions) {
    min_x = std::min(min_x, p.x());
    max_x = std::max(max_x, p.x());
    min_y = std::min(min_y, p.y());
    max_y = std::max(max_y, p.y());
  }
  const double extent = std::max({max_x - min_x, max_y - min_y, 1e-9});
  const double cell = std::max(*range, extent / kNearLinkMaxCellsPerSide);
  const auto cells_along = [&](double span) {
    return static_cast<int>(std::min<double>(kNearLinkMaxCellsPerSide, std::floor(span / cell) + 1));
  };
  const int nx = cells_along(max_x - min_x);
  const int ny = cells_along(max_y - min_y);
  const auto column = [&](double x) { return std::min(nx - 1, static_cast<int>((x - min_x) / cell)); };
  const auto row = [&](double y) { return std::min(ny - 1, static_cast<int>((y - min_y) / cell)); };
  cell_start_.assign(static_cast<size_t>(nx) * static_cast<size_t>(ny) + 1, 0);
  for (const auto& p : positions) ++cell_start_[static_cast<size_t>(row(p.y())) * nx + column(p.x()) + 1];
  for (size_t c = 1; c < cell_start_.size(); ++c) cell_start_[c] += cell_start_[c - 1];
  by_cell_.assign(n_, 0);
  {
    std::vector<uint32_t> fill(cell_start_.begin(), cell_start_.end() - 1);
    for (uint32_t k = 0; k < n_; ++k) {
      by_cell_[fill[static_cast<size_t>(row(positions[k].y())) * nx + column(positions[k].x())]++] = k;
    }
  }

  // For each radio, the partners with a larger index within range, in increasing order, so the
  // links come out ordered by (i, j) and every pair is computed once.
  RadioModel::Visited visited = model.new_visited();
  const double range_sq = *range * *range;
  for (uint32_t i = 0; i < n_; ++i) {
    first_of_[i] = static_cast<uint32_t>(links_.size());
    partners_.clear();
    const geometry::Vec2& a = positions[i];
    const int cx = column(a.x());
    const int cy = row(a.y());
    for (int y = std::max(0, cy - 1); y <= std::min(ny - 1, cy + 1); ++y) {
      for (int x = std::max(0, cx - 1); x <= std::min(nx - 1, cx + 1); ++x) {
        const size_t c = static_cast<size_t>(y) * nx + x;
        for (uint32_t k = cell_start_[c]; k < cell_start_[c + 1]; ++k) {
          const uint32_t j = by_cell_[k];
          if (j > i && (positions[j] - a).squaredNorm() <= range_sq) partners_.push_back(j);
        }
      }
    }
    std::sort(partners_.begin(), partners_.end());
    pairs_in_range_ += partners_.size();
    for (uint32_t j : partners_) {
      if (auto q = model.connected_link(a, positions[j], visited)) links_.push_back({i, j, *q});
    }
  }
  first_of_[n_] = static_cast<uint32_t>(links_.size());
}

}  // namespace autonomy::sim::radio
