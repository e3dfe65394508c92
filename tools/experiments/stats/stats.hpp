#pragma once
// Descriptive statistics and Welch's two-sample t-test, as used to compare the configurations of
// Wagner & Arkin, "Internalized Plans for Communication-Sensitive Robot Team Behaviors", Table 1
// (two-sided p-values). Pure: no I/O, no external numerics library.

#include <vector>

namespace autonomy::stats {

// Arithmetic mean; 0 for an empty sample.
double mean(const std::vector<double>& xs);

// Sample (n - 1) variance and standard deviation; 0 for fewer than two values.
double sample_variance(const std::vector<double>& xs);
double sample_stddev(const std::vector<double>& xs);

// Regularized incomplete beta function I_x(a, b) for a, b > 0 and 0 <= x <= 1 (continued
// fraction evaluated with the modified Lentz method). NaN for arguments out of range.
double regularized_incomplete_beta(double a, double b, double x);

// Two-sided p-value of Student's t-distribution: P(|T| >= |t|) with df > 0 degrees of freedom
// (df need not be an integer). 1 for t = 0; NaN when df <= 0 or t is NaN.
double student_t_two_sided_p(double t, double df);

struct WelchResult {
  double t = 0.0;   // (mean_a - mean_b) / sqrt(var_a/n_a + var_b/n_b)
  double df = 0.0;  // Welch-Satterthwaite degrees of freedom
  double p = 1.0;   // two-sided
  bool valid = false;  // false when either sample has fewer than two values
};

// Welch's unequal-variance t-test of a against b. When both samples have zero variance: equal
// means give t = 0, p = 1; different means give t = +/-inf, p = 0 (df is then n_a + n_b - 2).
WelchResult welch_t_test(const std::vector<double>& a, const std::vector<double>& b);

}  // namespace autonomy::stats
