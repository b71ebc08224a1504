#include "core/eval/statistics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/common/error.hpp"
#include "core/common/median.hpp"
#include "core/common/number_text.hpp"

namespace clm3d {
namespace {

double sampleVariance(std::span<const double> values, double mean) {
  if (values.size() < 2) return 0.0;
  double sum = 0.0;
  for (const double v : values) sum += (v - mean) * (v - mean);
  return sum / static_cast<double>(values.size() - 1);
}

double meanOf(std::span<const double> values) {
  double sum = 0.0;
  for (const double v : values) sum += v;
  return sum / static_cast<double>(values.size());
}

// The continued fraction of I_x(a, b) (without its prefactor):
//   1 / (1 + d1 / (1 + d2 / (1 + ...))), with
//   d(2m+1) = -(a + m)(a + b + m) x / ((a + 2m)(a + 2m + 1)),
//   d(2m)   =  m (b - m) x / ((a + 2m - 1)(a + 2m)),
// evaluated by the modified Lentz method (each partial denominator is 1). Converges quickly for
// x < (a + 1) / (a + b + 2); the caller uses the symmetry I_x(a, b) = 1 - I_(1-x)(b, a) otherwise.
double betaContinuedFraction(double a, double b, double x) {
  constexpr double kTiny = 1e-300;
  constexpr double kEpsilon = 1e-15;
  constexpr int kMaxTerms = 10000;
  // Value of 1 + d1 / (1 + d2 / ...), built up as f = f0 * prod(C_j * D_j).
  double f = 1.0;
  double c = 1.0;
  double d = 0.0;
  for (int j = 1; j <= kMaxTerms; ++j) {
    const int m = j / 2;
    double coefficient = 0.0;
    if (j % 2 == 1) {
      coefficient = -(a + m) * (a + b + m) * x / ((a + 2.0 * m) * (a + 2.0 * m + 1.0));
    } else {
      coefficient = m * (b - m) * x / ((a + 2.0 * m - 1.0) * (a + 2.0 * m));
    }
    d = 1.0 + coefficient * d;
    if (std::abs(d) < kTiny) d = kTiny;
    c = 1.0 + coefficient / c;
    if (std::abs(c) < kTiny) c = kTiny;
    d = 1.0 / d;
    const double delta = c * d;
    f *= delta;
    if (std::abs(delta - 1.0) < kEpsilon) return 1.0 / f;
  }
  throw Error("incomplete beta: continued fraction did not converge for a = " + std::to_string(a) +
              ", b = " + std::to_string(b) + ", x = " + std::to_string(x));
}

}  // namespace

Descriptive describe(std::span<const double> values) {
  Descriptive result;
  result.count = static_cast<int>(values.size());
  if (values.empty()) {
    result.mean = result.median = result.sd = result.min = result.max = kNan;
    return result;
  }
  result.mean = meanOf(values);
  result.sd = std::sqrt(sampleVariance(values, result.mean));
  result.median = medianOf(std::vector<double>(values.begin(), values.end()));
  const auto [min, max] = std::minmax_element(values.begin(), values.end());
  result.min = *min;
  result.max = *max;
  return result;
}

double regularizedIncompleteBeta(double a, double b, double x) {
  if (!(a > 0.0) || !(b > 0.0) || !std::isfinite(a) || !std::isfinite(b)) {
    throw Error("incomplete beta: a and b must be positive and finite");
  }
  if (!(x >= 0.0 && x <= 1.0)) throw Error("incomplete beta: x must be in [0, 1]");
  if (x == 0.0) return 0.0;
  if (x == 1.0) return 1.0;
  // x^a (1 - x)^b / B(a, b), in logarithms so large a and b do not overflow.
  const double logBeta = std::lgamma(a) + std::lgamma(b) - std::lgamma(a + b);
  const double front = std::exp(a * std::log(x) + b * std::log1p(-x) - logBeta);
  if (x < (a + 1.0) / (a + b + 2.0)) return front * betaContinuedFraction(a, b, x) / a;
  return 1.0 - front * betaContinuedFraction(b, a, 1.0 - x) / b;
}

double studentTTwoSidedP(double t, double df) {
  if (!(df > 0.0)) throw Error("Student t: degrees of freedom must be positive");
  if (std::isnan(t)) return kNan;
  if (std::isinf(t)) return 0.0;
  // P(|T| >= |t|) = I_(df / (df + t^2))(df / 2, 1 / 2).
  return std::clamp(regularizedIncompleteBeta(0.5 * df, 0.5, df / (df + t * t)), 0.0, 1.0);
}

double studentTCdf(double t, double df) {
  const double tail = 0.5 * studentTTwoSidedP(t, df);
  return t >= 0.0 ? 1.0 - tail : tail;
}

double fDistributionSurvival(double f, double df1, double df2) {
  if (!(df1 > 0.0) || !(df2 > 0.0)) throw Error("F distribution: degrees of freedom must be > 0");
  if (std::isnan(f)) return kNan;
  if (f <= 0.0) return 1.0;
  if (std::isinf(f)) return 0.0;
  // P(F >= f) = I_(df2 / (df2 + df1 f))(df2 / 2, df1 / 2).
  return std::clamp(regularizedIncompleteBeta(0.5 * df2, 0.5 * df1, df2 / (df2 + df1 * f)), 0.0,
                    1.0);
}

WelchTTest welchTTest(std::span<const double> a, std::span<const double> b) {
  if (a.size() < 2 || b.size() < 2) {
    throw InputError("Welch's t-test needs at least two values in each group (got " +
                     std::to_string(a.size()) + " and " + std::to_string(b.size()) + ")");
  }
  WelchTTest result;
  result.meanA = meanOf(a);
  result.meanB = meanOf(b);
  const double na = static_cast<double>(a.size());
  const double nb = static_cast<double>(b.size());
  const double wa = sampleVariance(a, result.meanA) / na;  // squared standard error of mean a
  const double wb = sampleVariance(b, result.meanB) / nb;
  const double se2 = wa + wb;
  if (!(se2 > 0.0)) {
    throw InputError("Welch's t-test: both groups have no spread (all values equal)");
  }
  result.t = (result.meanA - result.meanB) / std::sqrt(se2);
  result.df = se2 * se2 / (wa * wa / (na - 1.0) + wb * wb / (nb - 1.0));
  result.p = studentTTwoSidedP(result.t, result.df);
  return result;
}

Anova oneWayAnova(const std::vector<std::vector<double>>& groups) {
  if (groups.size() < 2) throw InputError("ANOVA needs at least two groups");
  double total = 0.0;
  std::size_t count = 0;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    if (groups[g].empty()) {
      throw InputError("ANOVA: group " + std::to_string(g + 1) + " has no values");
    }
    for (const double v : groups[g]) total += v;
    count += groups[g].size();
  }
  if (count <= groups.size()) {
    throw InputError("ANOVA needs more values than groups (got " + std::to_string(count) +
                     " values in " + std::to_string(groups.size()) + " groups)");
  }
  const double grandMean = total / static_cast<double>(count);
  double between = 0.0;
  double within = 0.0;
  for (const auto& group : groups) {
    const double m = meanOf(group);
    between += static_cast<double>(group.size()) * (m - grandMean) * (m - grandMean);
    for (const double v : group) within += (v - m) * (v - m);
  }
  Anova result;
  result.df1 = static_cast<double>(groups.size() - 1);
  result.df2 = static_cast<double>(count - groups.size());
  if (!(within > 0.0)) throw InputError("ANOVA: no spread within the groups (all values equal)");
  result.f = (between / result.df1) / (within / result.df2);
  result.p = fDistributionSurvival(result.f, result.df1, result.df2);
  return result;
}

}  // namespace clm3d
