#include "tools/experiments/stats/stats.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace autonomy::stats {
namespace {

TEST(StatsTest, MeanAndSampleStddev) {
  EXPECT_DOUBLE_EQ(mean({}), 0.0);
  EXPECT_DOUBLE_EQ(mean({2.0, 4.0, 6.0}), 4.0);
  // 2,4,4,4,5,5,7,9: mean 5, sum of squares 32, sample variance 32/7.
  const std::vector<double> xs = {2, 4, 4, 4, 5, 5, 7, 9};
  EXPECT_DOUBLE_EQ(mean(xs), 5.0);
  EXPECT_NEAR(sample_variance(xs), 32.0 / 7.0, 1e-12);
  EXPECT_NEAR(sample_stddev(xs), std::sqrt(32.0 / 7.0), 1e-12);
  EXPECT_DOUBLE_EQ(sample_stddev({3.0}), 0.0);
  EXPECT_DOUBLE_EQ(sample_stddev({}), 0.0);
}

TEST(StatsTest, IncompleteBetaClosedForms) {
  EXPECT_DOUBLE_EQ(regularized_incomplete_beta(2.0, 3.0, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(regularized_incomplete_beta(2.0, 3.0, 1.0), 1.0);
  for (double x : {0.05, 0.3, 0.5, 0.77, 0.99}) {
    EXPECT_NEAR(regularized_incomplete_beta(1.0, 1.0, x), x, 1e-12);
    EXPECT_NEAR(regularized_incomplete_beta(3.0, 1.0, x), std::pow(x, 3.0), 1e-12);
    EXPECT_NEAR(regularized_incomplete_beta(1.0, 4.0, x), 1.0 - std::pow(1.0 - x, 4.0), 1e-12);
    // Symmetry I_x(a, b) = 1 - I_{1-x}(b, a).
    EXPECT_NEAR(regularized_incomplete_beta(2.5, 7.0, x),
                1.0 - regularized_incomplete_beta(7.0, 2.5, 1.0 - x), 1e-12);
  }
  // Integer parameters: binomial tail. I_0.3(2, 3) = sum_{j=2..4} C(4,j) .3^j .7^(4-j).
  EXPECT_NEAR(regularized_incomplete_beta(2.0, 3.0, 0.3), 0.3483, 1e-12);
  EXPECT_NEAR(regularized_incomplete_beta(7.5, 7.5, 0.5), 0.5, 1e-12);
  EXPECT_TRUE(std::isnan(regularized_incomplete_beta(0.0, 1.0, 0.5)));
  EXPECT_TRUE(std::isnan(regularized_incomplete_beta(1.0, 1.0, 1.5)));
}

TEST(StatsTest, StudentTTwoSidedTableValues) {
  EXPECT_NEAR(student_t_two_sided_p(2.0, 10.0), 0.0734, 5e-5);
  EXPECT_NEAR(student_t_two_sided_p(1.0, 5.0), 0.3632, 5e-5);
  // Critical values: t_{0.975, 10} = 2.228, t_{0.975, 29} = 2.045, t_{0.995, 58} = 2.663.
  EXPECT_NEAR(student_t_two_sided_p(2.228, 10.0), 0.05, 2e-4);
  EXPECT_NEAR(student_t_two_sided_p(2.045, 29.0), 0.05, 2e-4);
  EXPECT_NEAR(student_t_two_sided_p(2.663, 58.0), 0.01, 2e-4);
  // Large df approaches the normal distribution: 1.959964 -> 0.05.
  EXPECT_NEAR(student_t_two_sided_p(1.959964, 1e7), 0.05, 1e-5);
}

TEST(StatsTest, StudentTClosedFormsAndSymmetry) {
  for (double t : {0.1, 0.5, 1.0, 3.0, 12.0}) {
    // df = 1 (Cauchy): p = 1 - (2/pi) atan|t|; df = 2: p = 1 - |t| / sqrt(2 + t^2).
    EXPECT_NEAR(student_t_two_sided_p(t, 1.0), 1.0 - 2.0 / M_PI * std::atan(t), 1e-12);
    EXPECT_NEAR(student_t_two_sided_p(t, 2.0), 1.0 - t / std::sqrt(2.0 + t * t), 1e-12);
    EXPECT_DOUBLE_EQ(student_t_two_sided_p(-t, 7.3), student_t_two_sided_p(t, 7.3));
  }
  EXPECT_DOUBLE_EQ(student_t_two_sided_p(0.0, 4.0), 1.0);
  EXPECT_DOUBLE_EQ(student_t_two_sided_p(INFINITY, 4.0), 0.0);
  EXPECT_TRUE(std::isnan(student_t_two_sided_p(1.0, 0.0)));
  // Decreasing in |t|.
  EXPECT_GT(student_t_two_sided_p(1.0, 8.0), student_t_two_sided_p(1.5, 8.0));
}

TEST(StatsTest, WelchByHand) {
  // a: mean 3, var 2.5; b: mean 6, var 10. se^2 = 2.5/5 + 10/5 = 2.5, t = -3/sqrt(2.5),
  // df = 2.5^2 / (0.5^2/4 + 2^2/4) = 6.25 / 1.0625.
  const std::vector<double> a = {1, 2, 3, 4, 5};
  const std::vector<double> b = {2, 4, 6, 8, 10};
  const WelchResult r = welch_t_test(a, b);
  ASSERT_TRUE(r.valid);
  EXPECT_NEAR(r.t, -3.0 / std::sqrt(2.5), 1e-12);
  EXPECT_NEAR(r.df, 6.25 / 1.0625, 1e-12);
  EXPECT_NEAR(r.p, student_t_two_sided_p(r.t, r.df), 1e-15);
  EXPECT_NEAR(r.p, 0.1077, 5e-4);  // R: t.test(1:5, seq(2, 10, 2)) -> p-value = 0.1077
}

TEST(StatsTest, WelchSymmetry) {
  const std::vector<double> a = {66.1, 70.3, 52.0, 80.4, 61.7, 59.9};
  const std::vector<double> b = {49.5, 45.1, 52.3, 47.7, 55.0};
  const WelchResult ab = welch_t_test(a, b);
  const WelchResult ba = welch_t_test(b, a);
  EXPECT_DOUBLE_EQ(ab.t, -ba.t);
  EXPECT_DOUBLE_EQ(ab.df, ba.df);
  EXPECT_DOUBLE_EQ(ab.p, ba.p);
  EXPECT_GT(ab.t, 0.0);
  EXPECT_GT(ab.p, 0.0);
  EXPECT_LT(ab.p, 1.0);
  // df lies between min(n) - 1 and n_a + n_b - 2.
  EXPECT_GE(ab.df, 4.0);
  EXPECT_LE(ab.df, 9.0);
}

TEST(StatsTest, WelchIdenticalAndDegenerateSamples) {
  const std::vector<double> a = {1.0, 2.0, 3.0, 4.0};
  const WelchResult same = welch_t_test(a, a);
  EXPECT_TRUE(same.valid);
  EXPECT_DOUBLE_EQ(same.t, 0.0);
  EXPECT_DOUBLE_EQ(same.p, 1.0);

  const WelchResult constant_equal = welch_t_test({5, 5, 5}, {5, 5});
  EXPECT_TRUE(constant_equal.valid);
  EXPECT_DOUBLE_EQ(constant_equal.p, 1.0);

  const WelchResult constant_different = welch_t_test({5, 5, 5}, {6, 6});
  EXPECT_TRUE(constant_different.valid);
  EXPECT_DOUBLE_EQ(constant_different.p, 0.0);
  EXPECT_TRUE(std::isinf(constant_different.t) && constant_different.t < 0.0);

  EXPECT_FALSE(welch_t_test({1.0}, {1.0, 2.0}).valid);
  EXPECT_FALSE(welch_t_test({}, {}).valid);
}

}  // namespace
}  // namespace autonomy::stats
