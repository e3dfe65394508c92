#include "tools/experiments/stats/stats.hpp"

#include <cmath>
#include <limits>

namespace autonomy::stats {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// Continued fraction of the incomplete beta function,
//   1 / (1 + d1 / (1 + d2 / (1 + ...))), with
//   d_{2m+1} = -(a + m)(a + b + m) x / ((a + 2m)(a + 2m + 1)),
//   d_{2m}   =  m (b - m) x / ((a + 2m - 1)(a + 2m)),
// evaluated front to back with the modified Lentz method. Converges fast for x < (a+1)/(a+b+2).
double beta_continued_fraction(double a, double b, double x) {
  constexpr int kMaxIterations = 500;
  constexpr double kEpsilon = 1e-15;
  constexpr double kTiny = 1e-300;

  auto guard = [](double v) { return std::fabs(v) < kTiny ? kTiny : v; };

  double c = 1.0;
  double d = 1.0 / guard(1.0 - (a + b) * x / (a + 1.0));
  double result = d;
  for (int m = 1; m <= kMaxIterations; ++m) {
    const double md = static_cast<double>(m);
    const double two_m = 2.0 * md;
    // Even step.
    double coeff = md * (b - md) * x / ((a + two_m - 1.0) * (a + two_m));
    d = 1.0 / guard(1.0 + coeff * d);
    c = guard(1.0 + coeff / c);
    result *= d * c;
    // Odd step.
    coeff = -(a + md) * (a + b + md) * x / ((a + two_m) * (a + two_m + 1.0));
    d = 1.0 / guard(1.0 + coeff * d);
    c = guard(1.0 + coeff / c);
    const double delta = d * c;
    result *= delta;
    if (std::fabs(delta - 1.0) < kEpsilon) break;
  }
  return result;
}

}  // namespace

double mean(const std::vector<double>& xs) {
  if (xs.empty()) return 0.0;
  double sum = 0.0;
  for (double x : xs) sum += x;
  return sum / static_cast<double>(xs.size());
}

double sample_variance(const std::vector<double>& xs) {
  if (xs.size() < 2) return 0.0;
  const double m = mean(xs);
  double ss = 0.0;
  for (double x : xs) ss += (x - m) * (x - m);
  return ss / static_cast<double>(xs.size() - 1);
}

double sample_stddev(const std::vector<double>& xs) { return std::sqrt(sample_variance(xs)); }

double regularized_incomplete_beta(double a, double b, double x) {
  if (!(a > 0.0) || !(b > 0.0) || !(x >= 0.0) || !(x <= 1.0)) return kNaN;
  if (x == 0.0) return 0.0;
  if (x == 1.0) return 1.0;
  // Prefactor x^a (1-x)^b / (a B(a, b)), through logarithms.
  const double log_front = std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) +
                           a * std::log(x) + b * std::log1p(-x);
  const double front = std::exp(log_front);
  // Use the symmetry I_x(a, b) = 1 - I_{1-x}(b, a) where the fraction converges faster.
  if (x < (a + 1.0) / (a + b + 2.0)) {
    return front * beta_continued_fraction(a, b, x) / a;
  }
  return 1.0 - front * beta_continued_fraction(b, a, 1.0 - x) / b;
}

double student_t_two_sided_p(double t, double df) {
  if (std::isnan(t) || !(df > 0.0)) return kNaN;
  if (std::isinf(t)) return 0.0;
  // P(|T| >= |t|) = I_{df / (df + t^2)}(df / 2, 1 / 2).
  const double x = df / (df + t * t);
  double p = regularized_incomplete_beta(0.5 * df, 0.5, x);
  if (p < 0.0) p = 0.0;
  if (p > 1.0) p = 1.0;
  return p;
}

WelchResult welch_t_test(const std::vector<double>& a, const std::vector<double>& b) {
  WelchResult r;
  if (a.size() < 2 || b.size() < 2) return r;
  r.valid = true;
  const double na = static_cast<double>(a.size());
  const double nb = static_cast<double>(b.size());
  const double va = sample_variance(a) / na;
  const double vb = sample_variance(b) / nb;
  const double diff = mean(a) - mean(b);
  const double se2 = va + vb;
  if (se2 == 0.0) {
    r.df = na + nb - 2.0;
    if (diff == 0.0) {
      r.t = 0.0;
      r.p = 1.0;
    } else {
      r.t = diff > 0.0 ? kInf : -kInf;
      r.p = 0.0;
    }
    return r;
  }
  r.t = diff / std::sqrt(se2);
  r.df = se2 * se2 / (va * va / (na - 1.0) + vb * vb / (nb - 1.0));
  r.p = student_t_two_sided_p(r.t, r.df);
  return r;
}

}  // namespace autonomy::stats
