#pragma once
// RadioAttenuationModel of the simulator: received signal strength between two radios on the
// ground plane, from distance (log-distance or ITU-R P.1238) and from the walls, buildings and
// declared areas on the straight path between them, the occupancy maps it passes (walls of
// blocked cells, raster_attenuator.hpp) and the thin walls that move (door leaves), and the link
// table of a whole team.
//
//   signal_dbm = tx_power_dbm - distance_loss_db(d) - sum over attenuators of their loss_db
//   margin_db  = signal_dbm - receiver_sensitivity_dbm;  connected = margin_db >= 0
//
// Links are symmetric: link(a, b) == link(b, a) exactly (the endpoints are put in a canonical
// order before any computation). No fading or shadowing noise: the same geometry always gives
// the same link, so runs are reproducible; randomness lives in delivery (see delivery.hpp).
//
// Cost: a path only tests the attenuators and moving walls in the grid cells it crosses
// (ObstacleIndex), each once, and walks each raster it meets (RasterAttenuator). All const methods
// are thread safe (no shared scratch); move_wall is not, and must not run beside them.
#include "common/geometry/geometry.hpp"
#include "simulator/radio/attenuator.hpp"
#include "simulator/radio/obstacle_index.hpp"
#include "simulator/radio/radio_parameters.hpp"
#include "simulator/radio/raster_attenuator.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace autonomy::sim::radio {

// A thin wall that moves inside a fixed box: a door leaf turning about its hinge. A path that
// crosses the segment a-b at a point inside both pays loss_db once; touching an end, running along
// it, or ending on it does not count (the boundary convention of attenuator.hpp).
struct MovingWall {
  geometry::Rect reach;  // every position the wall can take lies in it (the index is built from it)
  geometry::Vec2 a{0.0, 0.0};
  geometry::Vec2 b{0.0, 0.0};
  double loss_db = 0.0;
  std::string name;

  // A door leaf hinged at `hinge`, `length` long, now from hinge to tip: reach is the square
  // around the hinge the leaf can sweep; loss params.wall_loss_db (a closed door is a wall).
  static MovingWall door_leaf(const geometry::Vec2& hinge, const geometry::Vec2& tip, double length,
                              const RadioParameters& params, std::string name = {});
};

// Segment p-q crosses segment a-b at a point interior to both (by more than kBoundaryToleranceM).
bool crosses(const geometry::Vec2& p, const geometry::Vec2& q, const geometry::Vec2& a,
             const geometry::Vec2& b);

struct ObstacleLoss {
  double loss_db = 0.0;
  int crossings = 0;      // boundaries crossed, all attenuators, raster walls and moving walls
  double inside_m = 0.0;  // path length inside attenuators and rasters (overlapping ones count each)
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
  // With occupancy maps and moving walls too. Also throws std::invalid_argument for a moving
  // wall that is not inside its reach or has a negative / non-finite loss.
  RadioModel(RadioParameters params, std::vector<Attenuator> attenuators,
             std::vector<RasterAttenuator> rasters, std::vector<MovingWall> walls,
             double index_cell_size_m = 0.0);

  // Puts moving wall i at a-b (e.g. a door's leaf at its current angle). Throws std::out_of_range
  // for a bad index and std::invalid_argument when a-b leaves the wall's reach.
  void move_wall(size_t i, const geometry::Vec2& a, const geometry::Vec2& b);

  LinkQuality link(const geometry::Vec2& a, const geometry::Vec2& b) const;

  // Marks attenuators and walls already tested on the current path (a path meets one in several
  // cells), reused across paths: one per thread. Index ids: attenuators first, then walls.
  struct Visited {
    std::vector<uint32_t> stamp;
    uint32_t current = 0;
  };
  Visited new_visited() const;
  // The link a-b if it is connected, else nothing. Losses only add (every loss is >= 0), so the
  // walk along the path stops as soon as the obstacles have taken more than the distance left of
  // the link budget: a blocked path costs its first walls, not all of them. A connected link is
  // the same arithmetic as link(a, b), bit for bit.
  std::optional<LinkQuality> connected_link(const geometry::Vec2& a, const geometry::Vec2& b, Visited& v) const;

  // Recomputes every pair of `positions` into `table` (reusing its memory).
  void update(const std::vector<geometry::Vec2>& positions, LinkTable& table) const;
  LinkTable table(const std::vector<geometry::Vec2>& positions) const;

  // Loss from distance alone, d in metres (clamped to the reference distance from below).
  double distance_loss_db(double distance_m) const;
  // Loss from the attenuators, rasters and moving walls along a-b, through the index.
  ObstacleLoss obstacle_loss(const geometry::Vec2& a, const geometry::Vec2& b) const;
  // The same by testing every attenuator and wall: the reference for tests and benchmarks.
  ObstacleLoss obstacle_loss_exhaustive(const geometry::Vec2& a, const geometry::Vec2& b) const;

  const RadioParameters& parameters() const { return params_; }
  const std::vector<Attenuator>& attenuators() const { return attenuators_; }
  const std::vector<RasterAttenuator>& rasters() const { return rasters_; }
  const std::vector<MovingWall>& walls() const { return walls_; }
  const ObstacleIndex& index() const { return index_; }

 private:
  // Stops adding once the loss is above stop_above_db (then the total is partial).
  ObstacleLoss obstacle_loss(const geometry::Vec2& a, const geometry::Vec2& b, Visited& v,
                             double stop_above_db) const;
  LinkQuality link(const geometry::Vec2& a, const geometry::Vec2& b, Visited& v) const;
  // The link of p-q (canonical order) from its distance loss and obstacle loss.
  LinkQuality assemble(const geometry::Vec2& p, const geometry::Vec2& q, double distance_loss_db,
                       const ObstacleLoss& o) const;

  RadioParameters params_;
  std::vector<Attenuator> attenuators_;
  std::vector<RasterAttenuator> rasters_;
  std::vector<MovingWall> walls_;
  ObstacleIndex index_;
};

}  // namespace autonomy::sim::radio
