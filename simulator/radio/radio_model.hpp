#pragma once
// RadioAttenuationModel of the simulator: received signal strength between two radios on the
// ground plane, from distance (log-distance or ITU-R P.1238) and from the walls, buildings and
// declared areas on the straight path between them, and the link table of a whole team.
//
//   signal_dbm = tx_power_dbm - distance_loss_db(d) - sum over attenuators of their loss_db
//   margin_db  = signal_dbm - receiver_sensitivity_dbm;  connected = margin_db >= 0
//
// Links are symmetric: link(a, b) == link(b, a) exactly (the endpoints are put in a canonical
// order before any computation). No fading or shadowing noise: the same geometry always gives
// the same link, so runs are reproducible; randomness lives in delivery (see delivery.hpp).
//
// Cost: a path only tests the attenuators in the grid cells it crosses (ObstacleIndex), each
// once. All const methods are thread safe (no shared scratch).
#include "common/geometry/geometry.hpp"
#include "simulator/radio/attenuator.hpp"
#include "simulator/radio/obstacle_index.hpp"
#include "simulator/radio/radio_parameters.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace autonomy::sim::radio {

struct ObstacleLoss {
  double loss_db = 0.0;
  int crossings = 0;      // boundaries crossed, all attenuators together
  double inside_m = 0.0;  // path length inside attenuators (overlapping ones count each)
};

struct LinkQuality {
  double distance_m = 0.0;
  double distance_loss_db = 0.0;  // the distance model's part of the path loss
  double obstacle_loss_db = 0.0;  // walls, buildings and areas
  double path_loss_db = 0.0;      // distance_loss_db + obstacle_loss_db
  double signal_dbm = 0.0;        // received signal strength
  double margin_db = 0.0;         // signal_dbm - receiver_sensitivity_dbm
  bool connected = false;         // margin_db >= 0
  int crossings = 0;
  double inside_m = 0.0;
};

// Links between every pair of n radios, indexed by the radios' positions in the vector given to
// RadioModel::update (the caller keeps the index <-> robot id mapping, e.g. robots sorted by id).
class LinkTable {
 public:
  LinkTable() = default;
  size_t size() const { return n_; }
  // i != j, both < size(); at(i, j) and at(j, i) are the same entry.
  const LinkQuality& at(size_t i, size_t j) const { return links_[index(i, j)]; }
  bool connected(size_t i, size_t j) const { return i != j && at(i, j).connected; }
  size_t pair_count() const { return links_.size(); }

 private:
  friend class RadioModel;
  size_t index(size_t i, size_t j) const {
    if (i > j) std::swap(i, j);
    return i * (2 * n_ - i - 1) / 2 + (j - i - 1);
  }
  size_t n_ = 0;
  std::vector<LinkQuality> links_;  // upper triangle, row by row
};

class RadioModel {
 public:
  // Throws std::invalid_argument when problem(params) or attenuator_problem() finds something:
  // the scenario loader is expected to have reported those with file positions already.
  // index_cell_size_m <= 0 lets ObstacleIndex choose.
  RadioModel(RadioParameters params, std::vector<Attenuator> attenuators,
             double index_cell_size_m = 0.0);

  LinkQuality link(const geometry::Vec2& a, const geometry::Vec2& b) const;

  // Recomputes every pair of `positions` into `table` (reusing its memory).
  void update(const std::vector<geometry::Vec2>& positions, LinkTable& table) const;
  LinkTable table(const std::vector<geometry::Vec2>& positions) const;

  // Loss from distance alone, d in metres (clamped to the reference distance from below).
  double distance_loss_db(double distance_m) const;
  // Loss from the attenuators along a-b, through the index.
  ObstacleLoss obstacle_loss(const geometry::Vec2& a, const geometry::Vec2& b) const;
  // The same by testing every attenuator: the reference for tests and benchmarks.
  ObstacleLoss obstacle_loss_exhaustive(const geometry::Vec2& a, const geometry::Vec2& b) const;

  const RadioParameters& parameters() const { return params_; }
  const std::vector<Attenuator>& attenuators() const { return attenuators_; }
  const ObstacleIndex& index() const { return index_; }

 private:
  // Marks attenuators already tested on the current path (a path meets one in several cells).
  struct Visited {
    std::vector<uint32_t> stamp;
    uint32_t current = 0;
  };
  ObstacleLoss obstacle_loss(const geometry::Vec2& a, const geometry::Vec2& b, Visited& v) const;
  LinkQuality link(const geometry::Vec2& a, const geometry::Vec2& b, Visited& v) const;

  RadioParameters params_;
  std::vector<Attenuator> attenuators_;
  ObstacleIndex index_;
};

}  // namespace autonomy::sim::radio
