#pragma once
// A variable's domain: a real or integer interval [lo, hi], or a finite set of values
// (enumerations, object references and small integer sets are all sets of int64 codes).
#include <cstdint>
#include <string>
#include <vector>

namespace autonomy::planner {

class Domain {
 public:
  static Domain real(double lo, double hi);
  static Domain integer(double lo, double hi);
  static Domain values(std::vector<std::int64_t> values);  // sorted and deduplicated here
  static Domain singleton(std::int64_t v) { return values({v}); }

  bool is_set() const { return set_; }
  bool is_integer() const { return integer_ || set_; }
  bool empty() const;
  bool is_singleton() const;
  double lo() const;
  double hi() const;
  // Number of values (sets and integer intervals); intervals of reals count as infinite.
  double size() const;
  const std::vector<std::int64_t>& set_values() const { return values_; }
  bool contains(double v) const;

  // Narrowing; each returns true when the domain changed.
  bool intersect(const Domain& other);
  bool restrict_bounds(double lo, double hi);
  bool remove(std::int64_t v);

  bool operator==(const Domain& o) const;
  std::string to_string() const;

 private:
  bool set_ = false, integer_ = false;
  double lo_ = 0, hi_ = 0;
  std::vector<std::int64_t> values_;
};

}  // namespace autonomy::planner
