// Statistics of the evaluation: the incomplete beta function against closed forms, numeric
// integration and high-precision reference values (mpmath, 30 digits), the t and F tails, Welch's
// t-test and one-way ANOVA on worked examples.
#include "core/eval/statistics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/common/error.hpp"

namespace clm3d {
namespace {

TEST(EvalStatistics, DescribeGivesSampleFigures) {
  const std::vector<double> odd = {3.0, 1.0, 2.0, 10.0, 4.0};
  const auto d = describe(odd);
  EXPECT_EQ(d.count, 5);
  EXPECT_DOUBLE_EQ(d.mean, 4.0);
  EXPECT_DOUBLE_EQ(d.median, 3.0);
  EXPECT_DOUBLE_EQ(d.sd, std::sqrt(50.0 / 4.0));  // squares 1+9+4+36+0 = 50, n - 1 = 4
  EXPECT_DOUBLE_EQ(d.min, 1.0);
  EXPECT_DOUBLE_EQ(d.max, 10.0);
  const std::vector<double> even = {4.0, 1.0, 3.0, 2.0};
  EXPECT_DOUBLE_EQ(describe(even).median, 2.5);
  const std::vector<double> one = {7.0};
  EXPECT_DOUBLE_EQ(describe(one).sd, 0.0);
  EXPECT_TRUE(std::isnan(describe(std::vector<double>{}).mean));
}

TEST(EvalStatistics, IncompleteBetaMatchesClosedForms) {
  for (const double x : {0.0, 0.01, 0.2, 0.5, 0.77, 0.999, 1.0}) {
    for (const double p : {0.5, 1.0, 2.0, 3.5, 17.0}) {
      EXPECT_NEAR(regularizedIncompleteBeta(1.0, p, x), 1.0 - std::pow(1.0 - x, p), 1e-13)
          << "x " << x << " b " << p;
      EXPECT_NEAR(regularizedIncompleteBeta(p, 1.0, x), std::pow(x, p), 1e-13)
          << "x " << x << " a " << p;
      // Symmetry I_x(a, b) = 1 - I_(1-x)(b, a).
      EXPECT_NEAR(regularizedIncompleteBeta(p, 2.5, x) + regularizedIncompleteBeta(2.5, p, 1 - x),
                  1.0, 1e-13);
    }
    // I_x(1/2, 1/2) = (2 / pi) asin(sqrt(x)).
    EXPECT_NEAR(regularizedIncompleteBeta(0.5, 0.5, x),
                2.0 / std::numbers::pi * std::asin(std::sqrt(x)), 1e-13);
  }
  for (const double a : {0.7, 3.0, 40.0}) {
    EXPECT_NEAR(regularizedIncompleteBeta(a, a, 0.5), 0.5, 1e-13);
  }
}

// Composite Simpson integration of the beta density from 0 to x (a, b >= 2: smooth integrand).
double integrateBetaDensity(double a, double b, double x) {
  const int n = 20000;
  const double h = x / n;
  const double logBeta = std::lgamma(a) + std::lgamma(b) - std::lgamma(a + b);
  const auto density = [&](double t) {
    if (t <= 0.0 || t >= 1.0) return 0.0;
    return std::exp((a - 1) * std::log(t) + (b - 1) * std::log1p(-t) - logBeta);
  };
  double sum = density(0.0) + density(x);
  for (int i = 1; i < n; ++i) sum += (i % 2 == 1 ? 4.0 : 2.0) * density(i * h);
  return sum * h / 3.0;
}

TEST(EvalStatistics, IncompleteBetaMatchesNumericIntegration) {
  for (const auto& [a, b] : std::vector<std::pair<double, double>>{
           {2.0, 3.0}, {2.5, 4.5}, {5.0, 2.0}, {10.0, 12.0}, {3.0, 30.0}}) {
    for (const double x : {0.05, 0.3, 0.5, 0.62, 0.95}) {
      EXPECT_NEAR(regularizedIncompleteBeta(a, b, x), integrateBetaDensity(a, b, x), 1e-9)
          << "a " << a << " b " << b << " x " << x;
    }
  }
}

TEST(EvalStatistics, IncompleteBetaMatchesReferenceValues) {
  EXPECT_NEAR(regularizedIncompleteBeta(2.5, 4.5, 0.3), 0.406539016682459274, 1e-13);
  EXPECT_NEAR(regularizedIncompleteBeta(30, 40, 0.45), 0.644748008558568044, 1e-12);
  EXPECT_NEAR(regularizedIncompleteBeta(0.5, 0.5, 0.2), 0.295167235300866548, 1e-13);
  EXPECT_THROW(regularizedIncompleteBeta(0.0, 1.0, 0.5), Error);
  EXPECT_THROW(regularizedIncompleteBeta(1.0, 1.0, 1.5), Error);
}

TEST(EvalStatistics, StudentTTailsMatchReferenceAndClosedForms) {
  EXPECT_NEAR(studentTTwoSidedP(2.0, 10.0), 0.0733880347707403656, 1e-12);
  EXPECT_NEAR(studentTTwoSidedP(-2.0, 10.0), 0.0733880347707403656, 1e-12);
  EXPECT_NEAR(studentTTwoSidedP(1.5, 7.3), 0.175563092803086124, 1e-12);
  EXPECT_NEAR(studentTTwoSidedP(3.2, 45.0), 0.00252011594164262564, 1e-14);
  for (const double t : {0.0, 0.3, 1.0, 2.7, 12.0}) {
    // One degree of freedom is the Cauchy distribution, two have a closed form too.
    EXPECT_NEAR(studentTTwoSidedP(t, 1.0), 1.0 - 2.0 / std::numbers::pi * std::atan(t), 1e-13);
    EXPECT_NEAR(studentTTwoSidedP(t, 2.0), 1.0 - t / std::sqrt(2.0 + t * t), 1e-13);
  }
  // Very many degrees of freedom: the normal distribution.
  EXPECT_NEAR(studentTTwoSidedP(1.959963984540054, 1e7), 0.05, 1e-6);
  EXPECT_NEAR(studentTCdf(2.0, 10.0), 1.0 - 0.0733880347707403656 / 2, 1e-12);
  EXPECT_NEAR(studentTCdf(-2.0, 10.0), 0.0733880347707403656 / 2, 1e-12);
  EXPECT_DOUBLE_EQ(studentTTwoSidedP(INFINITY, 3.0), 0.0);
}

TEST(EvalStatistics, FTailsMatchReferenceAndClosedForms) {
  EXPECT_NEAR(fDistributionSurvival(3.5, 2, 27), 0.0445087539464002371, 1e-13);
  EXPECT_NEAR(fDistributionSurvival(2.1, 4, 13.5), 0.137004109234794660, 1e-12);
  EXPECT_NEAR(fDistributionSurvival(0.7, 5, 40), 0.626653471586625617, 1e-12);
  for (const double f : {0.1, 1.0, 3.0, 9.0}) {
    for (const double d2 : {3.0, 10.0, 60.0}) {
      // F(2, d2): P(F >= f) = (1 + 2 f / d2)^(-d2 / 2).
      EXPECT_NEAR(fDistributionSurvival(f, 2, d2), std::pow(1.0 + 2.0 * f / d2, -d2 / 2), 1e-13);
      // F(1, d2) is t(d2) squared.
      EXPECT_NEAR(fDistributionSurvival(f, 1, d2), studentTTwoSidedP(std::sqrt(f), d2), 1e-13);
    }
  }
  EXPECT_DOUBLE_EQ(fDistributionSurvival(0.0, 3, 4), 1.0);
}

TEST(EvalStatistics, WelchTTestMatchesWorkedExample) {
  const std::vector<double> a = {0.052, 0.061, 0.049, 0.070, 0.058, 0.066, 0.055};
  const std::vector<double> b = {0.071, 0.082, 0.064, 0.090, 0.077, 0.069, 0.085, 0.080, 0.074};
  const auto test = welchTTest(a, b);
  EXPECT_NEAR(test.t, -4.59424587207344868, 1e-10);
  EXPECT_NEAR(test.df, 13.5723615867084137, 1e-9);
  EXPECT_NEAR(test.p, 0.000450912983522511443, 1e-12);
  EXPECT_NEAR(test.meanA, 0.411 / 7, 1e-15);
  // Swapping the groups flips t only.
  const auto swapped = welchTTest(b, a);
  EXPECT_NEAR(swapped.t, -test.t, 1e-12);
  EXPECT_NEAR(swapped.p, test.p, 1e-15);
}

TEST(EvalStatistics, WelchTTestRejectsTooLittleData) {
  const std::vector<double> one = {1.0};
  const std::vector<double> two = {1.0, 2.0};
  const std::vector<double> flat = {3.0, 3.0, 3.0};
  EXPECT_THROW(welchTTest(one, two), InputError);
  EXPECT_THROW(welchTTest(flat, flat), InputError);
  // One group without spread is fine.
  EXPECT_NO_THROW(welchTTest(flat, two));
}

TEST(EvalStatistics, AnovaMatchesWorkedExample) {
  const std::vector<std::vector<double>> groups = {
      {6, 8, 4, 5, 3, 4}, {8, 12, 9, 11, 6, 8}, {13, 9, 11, 8, 7, 12}};
  const auto anova = oneWayAnova(groups);
  EXPECT_NEAR(anova.f, 9.26470588235294118, 1e-12);
  EXPECT_EQ(anova.df1, 2.0);
  EXPECT_EQ(anova.df2, 15.0);
  EXPECT_NEAR(anova.p, 0.00239877732939290831, 1e-13);
}

TEST(EvalStatistics, AnovaOfTwoGroupsIsTheSquaredPooledTTest) {
  const std::vector<double> a = {1.0, 2.5, 3.0, 2.0};
  const std::vector<double> b = {3.5, 4.0, 2.5, 5.0, 4.5};
  const auto anova = oneWayAnova({a, b});
  // Pooled-variance t statistic by hand.
  const double ma = 8.5 / 4, mb = 19.5 / 5;
  double ssa = 0, ssb = 0;
  for (const double v : a) ssa += (v - ma) * (v - ma);
  for (const double v : b) ssb += (v - mb) * (v - mb);
  const double pooled = (ssa + ssb) / 7.0;
  const double t = (ma - mb) / std::sqrt(pooled * (1.0 / 4 + 1.0 / 5));
  EXPECT_NEAR(anova.f, t * t, 1e-12);
  EXPECT_NEAR(anova.p, studentTTwoSidedP(t, 7.0), 1e-13);
}

TEST(EvalStatistics, AnovaRejectsDegenerateInput) {
  EXPECT_THROW(oneWayAnova({{1.0, 2.0}}), InputError);
  EXPECT_THROW(oneWayAnova({{1.0, 2.0}, {}}), InputError);
  EXPECT_THROW(oneWayAnova({{1.0}, {2.0}}), InputError);
  EXPECT_THROW(oneWayAnova({{1.0, 1.0}, {2.0, 2.0}}), InputError);
}

}  // namespace
}  // namespace clm3d
