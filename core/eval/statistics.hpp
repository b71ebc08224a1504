// The statistics the thesis uses to compare trackers (section 5.1, "Statistical Analysis"):
// descriptive figures of an error sample, Welch's t-test for two groups and one-way ANOVA for
// two or more, with the Student t and F distributions computed from the regularised incomplete
// beta function (written here, so the core needs no statistics library).
#pragma once

#include <span>
#include <vector>

namespace clm3d {

// Count, mean, median, sample standard deviation (n - 1 in the denominator; 0 for one value),
// minimum and maximum. Every figure is NaN for an empty sample. Values must be finite.
struct Descriptive {
  int count = 0;
  double mean = 0.0;
  double median = 0.0;
  double sd = 0.0;
  double min = 0.0;
  double max = 0.0;
};
Descriptive describe(std::span<const double> values);

// I_x(a, b), the regularised incomplete beta function, for a, b > 0 and 0 <= x <= 1 (Error
// otherwise). Evaluated by its continued fraction (modified Lentz), accurate to about 1e-14.
double regularizedIncompleteBeta(double a, double b, double x);

// P(|T| >= |t|) for Student's t with df > 0 degrees of freedom (df need not be whole).
double studentTTwoSidedP(double t, double df);
// P(T <= t).
double studentTCdf(double t, double df);
// P(F >= f) for the F distribution with (df1, df2) degrees of freedom.
double fDistributionSurvival(double f, double df1, double df2);

// Welch's unequal-variance t-test of mean(a) == mean(b): t = (mean a - mean b) / se, the
// Welch-Satterthwaite degrees of freedom and the two-sided p-value.
struct WelchTTest {
  double t = 0.0;
  double df = 0.0;
  double p = 1.0;
  double meanA = 0.0;
  double meanB = 0.0;
};
// Throws InputError if a group has fewer than two values or both groups have no spread.
WelchTTest welchTTest(std::span<const double> a, std::span<const double> b);

// One-way ANOVA of k >= 2 groups: F = between-group mean square / within-group mean square with
// (k - 1, N - k) degrees of freedom, and P(F' >= F).
struct Anova {
  double f = 0.0;
  double df1 = 0.0;
  double df2 = 0.0;
  double p = 1.0;
};
// Throws InputError for fewer than two groups, an empty group, N <= k, or no spread within groups.
Anova oneWayAnova(const std::vector<std::vector<double>>& groups);

}  // namespace clm3d
