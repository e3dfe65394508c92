#include "simulator/radio/radio_model.hpp"

#include "common/geometry/shapes.hpp"  // cross

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace autonomy::sim::radio {

using geometry::cross;
using geometry::Vec2;

namespace {

constexpr double kModelTol = kBoundaryToleranceM;

std::vector<geometry::Rect> bounds_of(const std::vector<Attenuator>& attenuators,
                                      const std::vector<MovingWall>& walls) {
  std::vector<geometry::Rect> boxes;
  boxes.reserve(attenuators.size() + walls.size());
  for (const Attenuator& a : attenuators) boxes.push_back(a.shape.bounds());
  for (const MovingWall& w : walls) boxes.push_back(w.reach);
  return boxes;
}

template <typename A>
void add(ObstacleLoss& total, const A& at, const Traversal& t) {
  if (t.stretches == 0) return;
  total.loss_db += at.loss_db(t);
  total.crossings += t.crossings;
  total.inside_m += t.inside_m;
}

void add(ObstacleLoss& total, const MovingWall& w, const Vec2& a, const Vec2& b) {
  if (!crosses(a, b, w.a, w.b)) return;
  total.loss_db += w.loss_db;
  total.crossings += 1;
}

bool within(const geometry::Rect& r, const Vec2& p) {
  return p.x() >= r.min_x - kModelTol && p.x() <= r.max_x + kModelTol && p.y() >= r.min_y - kModelTol &&
         p.y() <= r.max_y + kModelTol;
}


// Canonical order of the endpoints, so that link(a, b) and link(b, a) run the same arithmetic.
bool before(const Vec2& a, const Vec2& b) {
  return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
}

}  // namespace

MovingWall MovingWall::door_leaf(const Vec2& hinge, const Vec2& tip, double length,
                                 const RadioParameters& params, std::string name) {
  MovingWall w;
  w.reach = {hinge.x() - length, hinge.y() - length, hinge.x() + length, hinge.y() + length};
  w.a = hinge;
  w.b = tip;
  w.loss_db = params.wall_loss_db;
  w.name = std::move(name);
  return w;
}

bool crosses(const Vec2& p, const Vec2& q, const Vec2& a, const Vec2& b) {
  const Vec2 pq = q - p;
  const Vec2 ab = b - a;
  const double pq_len = pq.norm();
  const double ab_len = ab.norm();
  if (pq_len <= kModelTol || ab_len <= kModelTol) return false;
  // Signed distances (times the length of the other segment) of each end from the other line:
  // strictly on opposite sides, by more than the tolerance, for both segments.
  const double sa = cross(pq, a - p);
  const double sb = cross(pq, b - p);
  const double sp = cross(ab, p - a);
  const double sq = cross(ab, q - a);
  const double tol_pq = kModelTol * pq_len;
  const double tol_ab = kModelTol * ab_len;
  return ((sa > tol_pq && sb < -tol_pq) || (sa < -tol_pq && sb > tol_pq)) &&
         ((sp > tol_ab && sq < -tol_ab) || (sp < -tol_ab && sq > tol_ab));
}

RadioModel::RadioModel(RadioParameters params, std::vector<Attenuator> attenuators,
                       double index_cell_size_m)
    : RadioModel(std::move(params), std::move(attenuators), {}, {}, index_cell_size_m) {}

RadioModel::RadioModel(RadioParameters params, std::vector<Attenuator> attenuators,
                       std::vector<RasterAttenuator> rasters, std::vector<MovingWall> walls,
                       double index_cell_size_m)
    : params_(std::move(params)), attenuators_(std::move(attenuators)), rasters_(std::move(rasters)),
      walls_(std::move(walls)) {
  if (auto why = problem(params_)) throw std::invalid_argument("radio parameters: " + *why);
  for (const Attenuator& a : attenuators_) {
    if (auto why = attenuator_problem(a)) throw std::invalid_argument(*why);
  }
  for (const MovingWall& w : walls_) {
    if (!std::isfinite(w.loss_db) || w.loss_db < 0.0)
      throw std::invalid_argument("wall '" + w.name + "': loss must be finite and >= 0");
    if (!w.reach.valid()) throw std::invalid_argument("wall '" + w.name + "': invalid reach");
    if (!within(w.reach, w.a) || !within(w.reach, w.b))
      throw std::invalid_argument("wall '" + w.name + "' is outside its reach");
  }
  index_ = ObstacleIndex(bounds_of(attenuators_, walls_), index_cell_size_m);
}

void RadioModel::move_wall(size_t i, const Vec2& a, const Vec2& b) {
  MovingWall& w = walls_.at(i);
  if (!within(w.reach, a) || !within(w.reach, b))
    throw std::invalid_argument("wall '" + w.name + "' moved outside its reach");
  w.a = a;
  w.b = b;
}

double RadioModel::distance_loss_db(double distance_m) const {
  const double d = std::max(distance_m, params_.reference_distance_m);
  switch (params_.distance_model) {
    case DistanceModel::kItuP1238:
      return 20.0 * std::log10(params_.frequency_hz / 1e6) +
             params_.p1238_power_loss_coefficient * std::log10(d) +
             params_.p1238_floor_penetration_db - 28.0;
    case DistanceModel::kLogDistance:
      break;
  }
  return params_.reference_loss_db +
         10.0 * params_.path_loss_exponent * std::log10(d / params_.reference_distance_m);
}

ObstacleLoss RadioModel::obstacle_loss(const Vec2& a, const Vec2& b, Visited& v, double stop_above_db) const {
  ObstacleLoss total;
  for (const RasterAttenuator& r : rasters_) {
    add(total, r, r.traverse(a, b));
    if (total.loss_db > stop_above_db) return total;
  }
  if (attenuators_.empty() && walls_.empty()) return total;
  if (++v.current == 0) {  // wrapped: forget every old mark
    std::fill(v.stamp.begin(), v.stamp.end(), 0);
    v.current = 1;
  }
  const size_t n_attenuators = attenuators_.size();
  index_.visit_while(a, b, [&](uint32_t id) {
    if (v.stamp[id] == v.current) return true;
    v.stamp[id] = v.current;
    if (id < n_attenuators) {
      const Attenuator& at = attenuators_[id];
      add(total, at, at.shape.traverse(a, b));
    } else {
      add(total, walls_[id - n_attenuators], a, b);
    }
    return !(total.loss_db > stop_above_db);
  });
  return total;
}

RadioModel::Visited RadioModel::new_visited() const {
  Visited v;
  v.stamp.assign(attenuators_.size() + walls_.size(), 0);
  return v;
}

ObstacleLoss RadioModel::obstacle_loss(const Vec2& a, const Vec2& b) const {
  Visited v = new_visited();
  constexpr double kAll = std::numeric_limits<double>::infinity();
  return before(b, a) ? obstacle_loss(b, a, v, kAll) : obstacle_loss(a, b, v, kAll);
}

ObstacleLoss RadioModel::obstacle_loss_exhaustive(const Vec2& a, const Vec2& b) const {
  const Vec2& p = before(b, a) ? b : a;
  const Vec2& q = before(b, a) ? a : b;
  ObstacleLoss total;
  for (const RasterAttenuator& r : rasters_) add(total, r, r.traverse(p, q));
  for (const Attenuator& at : attenuators_) add(total, at, at.shape.traverse(p, q));
  for (const MovingWall& w : walls_) add(total, w, p, q);
  return total;
}

LinkQuality RadioModel::assemble(const Vec2& p, const Vec2& q, double distance_loss, const ObstacleLoss& o) const {
  LinkQuality l;
  l.distance_m = (q - p).norm();
  l.distance_loss_db = distance_loss;
  l.obstacle_loss_db = o.loss_db;
  l.crossings = o.crossings;
  l.inside_m = o.inside_m;
  l.path_loss_db = l.distance_loss_db + l.obstacle_loss_db;
  l.signal_dbm = params_.tx_power_dbm - l.path_loss_db;
  l.margin_db = l.signal_dbm - params_.receiver_sensitivity_dbm;
  l.connected = l.margin_db >= 0.0;
  return l;
}

LinkQuality RadioModel::link(const Vec2& a, const Vec2& b, Visited& v) const {
  const Vec2& p = before(b, a) ? b : a;
  const Vec2& q = before(b, a) ? a : b;
  return assemble(p, q, distance_loss_db((q - p).norm()),
                  obstacle_loss(p, q, v, std::numeric_limits<double>::infinity()));
}

LinkQuality RadioModel::link(const Vec2& a, const Vec2& b) const {
  Visited v = new_visited();
  return link(a, b, v);
}

std::optional<LinkQuality> RadioModel::connected_link(const Vec2& a, const Vec2& b, Visited& v) const {
  // Far above the rounding of a few additions of dB values, far below any loss that matters: a
  // walk stopped at more than (budget left + this) is certainly disconnected.
  constexpr double kStopSlackDb = 1e-6;
  const Vec2& p = before(b, a) ? b : a;
  const Vec2& q = before(b, a) ? a : b;
  const double distance_loss = distance_loss_db((q - p).norm());
  const double left_db = params_.tx_power_dbm - params_.receiver_sensitivity_dbm - distance_loss;
  if (left_db < -kStopSlackDb) return std::nullopt;
  const ObstacleLoss o = obstacle_loss(p, q, v, left_db + kStopSlackDb);
  if (o.loss_db > left_db + kStopSlackDb) return std::nullopt;
  const LinkQuality l = assemble(p, q, distance_loss, o);
  if (!l.connected) return std::nullopt;
  return l;
}

void RadioModel::update(const std::vector<Vec2>& positions, LinkTable& table) const {
  const size_t n = positions.size();
  table.n_ = n;
  table.links_.resize(n < 2 ? 0 : n * (n - 1) / 2);
  Visited v = new_visited();
  size_t k = 0;
  for (size_t i = 0; i < n; ++i) {
    for (size_t j = i + 1; j < n; ++j) table.links_[k++] = link(positions[i], positions[j], v);
  }
}

LinkTable RadioModel::table(const std::vector<Vec2>& positions) const {
  LinkTable t;
  update(positions, t);
  return t;
}

}  // namespace autonomy::sim::radio
