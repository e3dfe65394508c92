#include "simulator/radio/radio_model.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace autonomy::sim::radio {

using geometry::Vec2;

namespace {

std::vector<geometry::Rect> bounds_of(const std::vector<Attenuator>& attenuators) {
  std::vector<geometry::Rect> boxes;
  boxes.reserve(attenuators.size());
  for (const Attenuator& a : attenuators) boxes.push_back(a.shape.bounds());
  return boxes;
}

void add(ObstacleLoss& total, const Attenuator& at, const Traversal& t) {
  if (t.stretches == 0) return;
  total.loss_db += at.loss_db(t);
  total.crossings += t.crossings;
  total.inside_m += t.inside_m;
}

// Canonical order of the endpoints, so that link(a, b) and link(b, a) run the same arithmetic.
bool before(const Vec2& a, const Vec2& b) {
  return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
}

}  // namespace

RadioModel::RadioModel(RadioParameters params, std::vector<Attenuator> attenuators,
                       double index_cell_size_m)
    : params_(std::move(params)), attenuators_(std::move(attenuators)) {
  if (auto why = problem(params_)) throw std::invalid_argument("radio parameters: " + *why);
  for (const Attenuator& a : attenuators_) {
    if (auto why = attenuator_problem(a)) throw std::invalid_argument(*why);
  }
  index_ = ObstacleIndex(bounds_of(attenuators_), index_cell_size_m);
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

ObstacleLoss RadioModel::obstacle_loss(const Vec2& a, const Vec2& b, Visited& v) const {
  ObstacleLoss total;
  if (attenuators_.empty()) return total;
  if (++v.current == 0) {  // wrapped: forget every old mark
    std::fill(v.stamp.begin(), v.stamp.end(), 0);
    v.current = 1;
  }
  index_.visit(a, b, [&](uint32_t id) {
    if (v.stamp[id] == v.current) return;
    v.stamp[id] = v.current;
    const Attenuator& at = attenuators_[id];
    add(total, at, at.shape.traverse(a, b));
  });
  return total;
}

ObstacleLoss RadioModel::obstacle_loss(const Vec2& a, const Vec2& b) const {
  Visited v;
  v.stamp.assign(attenuators_.size(), 0);
  return before(b, a) ? obstacle_loss(b, a, v) : obstacle_loss(a, b, v);
}

ObstacleLoss RadioModel::obstacle_loss_exhaustive(const Vec2& a, const Vec2& b) const {
  const Vec2& p = before(b, a) ? b : a;
  const Vec2& q = before(b, a) ? a : b;
  ObstacleLoss total;
  for (const Attenuator& at : attenuators_) add(total, at, at.shape.traverse(p, q));
  return total;
}

LinkQuality RadioModel::link(const Vec2& a, const Vec2& b, Visited& v) const {
  const Vec2& p = before(b, a) ? b : a;
  const Vec2& q = before(b, a) ? a : b;
  LinkQuality l;
  l.distance_m = (q - p).norm();
  l.distance_loss_db = distance_loss_db(l.distance_m);
  const ObstacleLoss o = obstacle_loss(p, q, v);
  l.obstacle_loss_db = o.loss_db;
  l.crossings = o.crossings;
  l.inside_m = o.inside_m;
  l.path_loss_db = l.distance_loss_db + l.obstacle_loss_db;
  l.signal_dbm = params_.tx_power_dbm - l.path_loss_db;
  l.margin_db = l.signal_dbm - params_.receiver_sensitivity_dbm;
  l.connected = l.margin_db >= 0.0;
  return l;
}

LinkQuality RadioModel::link(const Vec2& a, const Vec2& b) const {
  Visited v;
  v.stamp.assign(attenuators_.size(), 0);
  return link(a, b, v);
}

void RadioModel::update(const std::vector<Vec2>& positions, LinkTable& table) const {
  const size_t n = positions.size();
  table.n_ = n;
  table.links_.resize(n < 2 ? 0 : n * (n - 1) / 2);
  Visited v;
  v.stamp.assign(attenuators_.size(), 0);
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
