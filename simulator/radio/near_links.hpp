#pragma once
// The connected links of a team, found without computing every pair: LinkTable (radio_model.hpp)
// holds all n (n - 1) / 2 pairs, which at 1,000 robots is 500k obstacle walks per update.
//
// Which pairs are computed: only those within max_link_range_m (link_range.hpp) of each other,
// found through a uniform grid of cells one range wide (each radio looks at the 3 x 3 cells
// around its own); farther pairs cannot be connected, whatever the obstacles. For a pair in range
// the obstacle walk stops as soon as the losses exceed the budget the distance leaves
// (RadioModel::connected_link). Only connected pairs are kept, with exactly the LinkQuality
// RadioModel::link gives them, so connected(i, j) and the Connectivity built from this table are
// those of the full LinkTable for the same positions.
#include "simulator/radio/radio_model.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace autonomy::sim::radio {

struct NearLink {
  uint32_t i = 0;  // i < j, indices into the positions given to update
  uint32_t j = 0;
  LinkQuality quality;  // connected
};

class NearLinkTable {
 public:
  size_t size() const { return n_; }
  // Connected pairs, ordered by (i, j).
  const std::vector<NearLink>& links() const { return links_; }
  // The link of i and j (either order) if it is connected, else null.
  const LinkQuality* find(size_t i, size_t j) const;
  bool connected(size_t i, size_t j) const { return find(i, j) != nullptr; }
  // Pairs within range whose link was computed at the last update (for benchmarks).
  size_t pairs_in_range() const { return pairs_in_range_; }

  // Recomputes the table for `positions` (reusing its memory).
  void update(const RadioModel& model, const std::vector<geometry::Vec2>& positions);

 private:
  size_t n_ = 0;
  size_t pairs_in_range_ = 0;
  std::vector<NearLink> links_;
  std::vector<uint32_t> first_of_;  // links_[first_of_[i] .. first_of_[i + 1]) have this i
  // Scratch kept between updates.
  std::vector<uint32_t> cell_start_;
  std::vector<uint32_t> by_cell_;
  std::vector<uint32_t> partners_;
};

}  // namespace autonomy::sim::radio
