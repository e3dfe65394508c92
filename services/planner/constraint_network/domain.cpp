#include "domain.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace autonomy::planner {

namespace {
// Reals compare with a small tolerance so that s + r*d = e does not fail on rounding.
constexpr double kEpsilon = 1e-9;
}  // namespace

Domain Domain::real(double lo, double hi) {
  Domain d;
  d.lo_ = lo;
  d.hi_ = hi;
  return d;
}

Domain Domain::integer(double lo, double hi) {
  Domain d;
  d.integer_ = true;
  d.lo_ = std::ceil(lo - kEpsilon);
  d.hi_ = std::floor(hi + kEpsilon);
  return d;
}

Domain Domain::values(std::vector<std::int64_t> values) {
  Domain d;
  d.set_ = true;
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  d.values_ = std::move(values);
  return d;
}

bool Domain::empty() const {
  return set_ ? values_.empty() : lo_ > hi_ + kEpsilon;
}

bool Domain::is_singleton() const {
  if (set_) return values_.size() == 1;
  return integer_ ? lo_ == hi_ : std::abs(hi_ - lo_) <= kEpsilon;
}

double Domain::lo() const {
  return set_ ? (values_.empty() ? 0.0 : double(values_.front())) : lo_;
}
double Domain::hi() const {
  return set_ ? (values_.empty() ? -1.0 : double(values_.back())) : hi_;
}

double Domain::size() const {
  if (set_) return double(values_.size());
  if (empty()) return 0;
  if (integer_) return hi_ - lo_ + 1;
  return is_singleton() ? 1 : HUGE_VAL;
}

bool Domain::contains(double v) const {
  if (set_) {
    if (v != std::floor(v)) return false;
    return std::binary_search(values_.begin(), values_.end(), std::int64_t(v));
  }
  if (integer_ && v != std::floor(v)) return false;
  return v >= lo_ - kEpsilon && v <= hi_ + kEpsilon;
}

bool Domain::restrict_bounds(double lo, double hi) {
  if (set_) {
    std::size_t before = values_.size();
    values_.erase(std::remove_if(values_.begin(), values_.end(),
                                 [&](std::int64_t v) {
                                   return double(v) < lo - kEpsilon || double(v) > hi + kEpsilon;
                                 }),
                  values_.end());
    return values_.size() != before;
  }
  if (integer_) {
    lo = std::ceil(lo - kEpsilon);
    hi = std::floor(hi + kEpsilon);
  }
  bool changed = false;
  // Reals: only a tightening by more than the tolerance counts, so propagation terminates.
  if (lo > lo_ + kEpsilon) {
    lo_ = lo;
    changed = true;
  }
  if (hi < hi_ - kEpsilon) {
    hi_ = hi;
    changed = true;
  }
  return changed;
}

bool Domain::intersect(const Domain& other) {
  if (set_ && other.set_) {
    std::vector<std::int64_t> common;
    std::set_intersection(values_.begin(), values_.end(), other.values_.begin(),
                          other.values_.end(), std::back_inserter(common));
    bool changed = common.size() != values_.size();
    values_ = std::move(common);
    return changed;
  }
  if (set_) {  // a set against an interval
    std::size_t before = values_.size();
    values_.erase(std::remove_if(values_.begin(), values_.end(),
                                 [&](std::int64_t v) { return !other.contains(double(v)); }),
                  values_.end());
    return values_.size() != before;
  }
  if (other.set_) {  // an interval becomes the set of the other's values inside it
    std::vector<std::int64_t> kept;
    for (std::int64_t v : other.values_)
      if (contains(double(v))) kept.push_back(v);
    *this = values(std::move(kept));
    return true;
  }
  bool changed = false;
  if (other.integer_ && !integer_) {
    integer_ = true;
    changed = true;
  }
  changed |= restrict_bounds(other.lo_, other.hi_);
  return changed;
}

bool Domain::remove(std::int64_t v) {
  if (set_) {
    auto it = std::lower_bound(values_.begin(), values_.end(), v);
    if (it == values_.end() || *it != v) return false;
    values_.erase(it);
    return true;
  }
  if (!integer_) return false;  // a point cannot be cut out of a real interval
  if (double(v) == lo_) {
    lo_ += 1;
    return true;
  }
  if (double(v) == hi_) {
    hi_ -= 1;
    return true;
  }
  return false;
}

bool Domain::operator==(const Domain& o) const {
  return set_ == o.set_ && integer_ == o.integer_ && lo_ == o.lo_ && hi_ == o.hi_ &&
         values_ == o.values_;
}

std::string Domain::to_string() const {
  std::ostringstream out;
  if (set_) {
    out << '{';
    for (std::size_t i = 0; i < values_.size(); ++i) out << (i ? ", " : "") << values_[i];
    out << '}';
  } else {
    out << '[' << lo_ << ", " << hi_ << ']';
  }
  return out.str();
}

}  // namespace autonomy::planner
