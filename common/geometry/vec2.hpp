#pragma once
// A point or direction in the plane. Eigen's Vector2d served here first; its <Eigen/Core> cost
// 1.7 s of parsing in each of 128 of the tree's 177 translation units (measured 2026-12-02),
// most of a CI build, for x, y and a norm. The names follow Eigen's (norm, squaredNorm,
// normalized, isApprox, Zero), with the same results, so the call sites did not change.
// Eigen stays where real linear algebra is done (the spacecraft's attitude).
#include <algorithm>
#include <cmath>
#include <ostream>
#include <type_traits>

namespace autonomy::geometry {

class Vec2 {
 public:
  constexpr Vec2() = default;
  // From any arithmetic pair, as Eigen's constructor took ints ({col, row}) too.
  template <typename X, typename Y,
            typename = std::enable_if_t<std::is_arithmetic_v<X> && std::is_arithmetic_v<Y>>>
  constexpr Vec2(X x, Y y) : x_(static_cast<double>(x)), y_(static_cast<double>(y)) {}

  static constexpr Vec2 Zero() { return {}; }

  constexpr double x() const { return x_; }
  constexpr double y() const { return y_; }
  double& x() { return x_; }
  double& y() { return y_; }
  // 0: x, 1: y (for code that walks both axes).
  constexpr double operator[](int axis) const { return axis == 0 ? x_ : y_; }
  double& operator[](int axis) { return axis == 0 ? x_ : y_; }

  constexpr double dot(const Vec2& o) const { return x_ * o.x_ + y_ * o.y_; }
  constexpr double squaredNorm() const { return x_ * x_ + y_ * y_; }
  double norm() const { return std::sqrt(squaredNorm()); }
  // A zero vector stays zero (as with Eigen).
  Vec2 normalized() const {
    const double n = norm();
    return n > 0.0 ? Vec2(x_ / n, y_ / n) : *this;
  }
  void normalize() { *this = normalized(); }
  // Eigen's fuzzy comparison: |a - b| <= precision * min(|a|, |b|).
  bool isApprox(const Vec2& o, double precision = 1e-12) const {
    return (*this - o).norm() <= precision * std::min(norm(), o.norm());
  }
  // Printing as a row, "x y", the way tests print Eigen vectors (v.transpose()).
  constexpr const Vec2& transpose() const { return *this; }

  constexpr Vec2 operator-() const { return {-x_, -y_}; }
  constexpr Vec2 operator+(const Vec2& o) const { return {x_ + o.x_, y_ + o.y_}; }
  constexpr Vec2 operator-(const Vec2& o) const { return {x_ - o.x_, y_ - o.y_}; }
  constexpr Vec2 operator*(double s) const { return {x_ * s, y_ * s}; }
  constexpr Vec2 operator/(double s) const { return {x_ / s, y_ / s}; }
  Vec2& operator+=(const Vec2& o) { return *this = *this + o; }
  Vec2& operator-=(const Vec2& o) { return *this = *this - o; }
  Vec2& operator*=(double s) { return *this = *this * s; }
  Vec2& operator/=(double s) { return *this = *this / s; }
  constexpr bool operator==(const Vec2& o) const { return x_ == o.x_ && y_ == o.y_; }
  constexpr bool operator!=(const Vec2& o) const { return !(*this == o); }

 private:
  double x_ = 0.0;
  double y_ = 0.0;
};

constexpr Vec2 operator*(double s, const Vec2& v) { return v * s; }

inline std::ostream& operator<<(std::ostream& out, const Vec2& v) { return out << v.x() << ' ' << v.y(); }

}  // namespace autonomy::geometry
