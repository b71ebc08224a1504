// Tests of the fastncc optimiser and of the derivatives it shares with gauss-newton
// (core/fit/detail/inverse_alignment.hpp, docs/fastncc.md): the 5-tap patch gradient, the
// closed-form maximiser of the linearised NCC against finite differences, the template derivatives
// and the NCC gradient against finite differences of the image, the chain through the projector's
// Jacobian, the inverse sign, and recovery of a perturbed pose and shape of a rendered head.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>
#include <string>

#include "core/fit/detail/inverse_alignment.hpp"
#include "core/fit/fitter.hpp"
#include "core/fit/optimiser.hpp"
#include "tests/unit/fit/inverse_step_check.hpp"
#include "tests/unit/fit/recovery_check.hpp"
#include "tests/unit/fit/synthetic_problem.hpp"

namespace clm3d {
namespace {

// ---------------------------------------------------------------------------------------------
// The 5-tap gradient.

TEST(PatchGradient, ExactOnRampsAndQuadraticsEverywhere) {
  for (int n : {1, 2, 3, 4, 5, 12, 20}) {
    const int pixels = n * n;
    Eigen::VectorXf ramp(pixels), quadratic(pixels), gx(pixels), gy(pixels);
    for (int r = 0; r < n; ++r) {
      for (int c = 0; c < n; ++c) {
        ramp[r * n + c] = 0.7f * c - 1.3f * r + 2.0f;
        quadratic[r * n + c] = 0.05f * c * c + 0.03f * r * r - 0.02f * r * c;
      }
    }
    patchGradient(ramp.data(), n, gx.data(), gy.data());
    for (int i = 0; i < pixels; ++i) {
      EXPECT_NEAR(gx[i], n > 1 ? 0.7f : 0.0f, 1e-5) << "n " << n << " pixel " << i;
      EXPECT_NEAR(gy[i], n > 1 ? -1.3f : 0.0f, 1e-5) << "n " << n << " pixel " << i;
    }
    if (n < 3) continue;
    patchGradient(quadratic.data(), n, gx.data(), gy.data());
    for (int r = 0; r < n; ++r) {
      for (int c = 0; c < n; ++c) {
        EXPECT_NEAR(gx[r * n + c], 0.1f * c - 0.02f * r, 1e-4) << "n " << n;
        EXPECT_NEAR(gy[r * n + c], 0.06f * r - 0.02f * c, 1e-4) << "n " << n;
      }
    }
  }
  // The interior kernel is the thesis's [-1/4, -1/2, 0, 1/2, 1/4] halved: a unit step response.
  Eigen::VectorXf impulse = Eigen::VectorXf::Zero(81), gx(81), gy(81);
  impulse[4 * 9 + 4] = 1.0f;
  patchGradient(impulse.data(), 9, gx.data(), gy.data());
  EXPECT_FLOAT_EQ(gx[4 * 9 + 2], 0.125f);  // d[c] = 1/4 (v[c+1] - v[c-1]) + 1/8 (v[c+2] - v[c-2])
  EXPECT_FLOAT_EQ(gx[4 * 9 + 3], 0.25f);
  EXPECT_FLOAT_EQ(gx[4 * 9 + 5], -0.25f);
  EXPECT_FLOAT_EQ(gx[4 * 9 + 6], -0.125f);
  EXPECT_FLOAT_EQ(gy[2 * 9 + 4], 0.125f);
  EXPECT_FLOAT_EQ(gy[6 * 9 + 4], -0.125f);
}

// ---------------------------------------------------------------------------------------------
// The closed-form maximiser of E(d) = (a + b.d) / sqrt(c + 2 e.d + d'Md).

struct LinearSystem {
  Eigen::VectorXd f, g, b, e;
  Eigen::MatrixXd d, m;
  double a = 0, c = 0;

  double value(const Eigen::VectorXd& delta) const {
    return (a + b.dot(delta)) / std::sqrt(c + 2.0 * e.dot(delta) + delta.dot(m * delta));
  }
  // The largest NCC any vector of span(f, D) reaches with g: |projection of g| / |g|.
  double bestPossible() const {
    Eigen::MatrixXd basis(f.size(), d.cols() + 1);
    basis << f, d;
    const Eigen::VectorXd x = basis.colPivHouseholderQr().solve(g);
    return (basis * x).norm() / g.norm();
  }
};

// A random template f, steepest-descent images D (neither centred nor orthogonal to f) and an
// image g = sign * (f + D x) + noise.
LinearSystem randomSystem(std::mt19937& random, int pixels, int params, double sign) {
  std::normal_distribution<double> normal(0.0, 1.0);
  LinearSystem s;
  s.f.resize(pixels);
  s.d.resize(pixels, params);
  s.g.resize(pixels);
  for (int i = 0; i < pixels; ++i) s.f[i] = normal(random);
  for (Eigen::Index i = 0; i < s.d.size(); ++i) s.d.data()[i] = 0.5 * normal(random);
  Eigen::VectorXd x(params);
  for (int i = 0; i < params; ++i) x[i] = 0.5 * normal(random);
  for (int i = 0; i < pixels; ++i) s.g[i] = 0.4 * normal(random);
  s.g += sign * (s.f + s.d * x);
  const Eigen::VectorXd unit = s.g / s.g.norm();
  s.a = s.f.dot(unit);
  s.b = s.d.transpose() * unit;
  s.c = s.f.squaredNorm();
  s.e = s.d.transpose() * s.f;
  s.m = s.d.transpose() * s.d;
  return s;
}

Eigen::VectorXd numericGradient(const LinearSystem& s, const Eigen::VectorXd& at, double h) {
  Eigen::VectorXd gradient(at.size());
  for (Eigen::Index i = 0; i < at.size(); ++i) {
    Eigen::VectorXd plus = at, minus = at;
    plus[i] += h;
    minus[i] -= h;
    gradient[i] = (s.value(plus) - s.value(minus)) / (2.0 * h);
  }
  return gradient;
}

Eigen::MatrixXd numericHessian(const LinearSystem& s, const Eigen::VectorXd& at, double h) {
  const Eigen::Index n = at.size();
  Eigen::MatrixXd hessian(n, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    Eigen::VectorXd plus = at, minus = at;
    plus[i] += h;
    minus[i] -= h;
    hessian.col(i) = (numericGradient(s, plus, h) - numericGradient(s, minus, h)) / (2.0 * h);
  }
  return 0.5 * (hessian + hessian.transpose());
}

TEST(LinearNcc, ClosedFormIsTheMaximumOfTheLinearisedNcc) {
  std::mt19937 random(11);
  for (int trial = 0; trial < 20; ++trial) {
    const int params = 2 + trial % 6;
    const LinearSystem s = randomSystem(random, 40 + 3 * trial, params, 1.0);
    const Eigen::LDLT<Eigen::MatrixXd> factor(s.m);
    Eigen::VectorXd u, w, delta;
    const LinearNccSolution solution = maximiseLinearNcc(s.a, s.b, s.c, s.e, factor, u, w, delta);
    ASSERT_TRUE(solution.interior) << "trial " << trial;
    EXPECT_GT(solution.kappa, 0.0);
    // A stationary point: the central-difference gradient vanishes (relative to the gradient at 0).
    const double scale = numericGradient(s, Eigen::VectorXd::Zero(params), 1e-5).norm();
    EXPECT_LT(numericGradient(s, delta, 1e-5).norm(), 1e-6 * scale) << "trial " << trial;
    // A maximum: the Hessian is negative definite, and E there is the best any template of
    // span(f, D) can reach.
    const Eigen::VectorXd curvature =
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(numericHessian(s, delta, 1e-3))
            .eigenvalues();
    EXPECT_LT(curvature.maxCoeff(), 0.0) << "trial " << trial;
    EXPECT_NEAR(s.value(delta), s.bestPossible(), 1e-9);
    EXPECT_NEAR(solution.predicted, s.value(delta), 1e-9);
    EXPECT_NEAR(solution.current, s.value(Eigen::VectorXd::Zero(params)), 1e-12);
    EXPECT_GT(s.value(delta), solution.current);
  }
}

TEST(LinearNcc, AnticorrelatedImageHasOnlyAMinimumAndTheStepAvoidsIt) {
  std::mt19937 random(5);
  for (int trial = 0; trial < 10; ++trial) {
    const int params = 3 + trial % 4;
    const LinearSystem s = randomSystem(random, 50, params, -1.0);
    const Eigen::LDLT<Eigen::MatrixXd> factor(s.m);
    Eigen::VectorXd u, w, delta;
    const LinearNccSolution solution = maximiseLinearNcc(s.a, s.b, s.c, s.e, factor, u, w, delta);
    EXPECT_FALSE(solution.interior);
    EXPECT_LT(solution.kappa, 0.0);
    // The formula's stationary point exists but is the minimum, -|projection of g|.
    const Eigen::VectorXd ue = factor.solve(s.b), we = factor.solve(s.e);
    const double lambda = (s.c - s.e.dot(we)) / (s.a - s.b.dot(we));
    const Eigen::VectorXd stationary = lambda * ue - we;
    EXPECT_NEAR(s.value(stationary), -s.bestPossible(), 1e-9);
    const Eigen::VectorXd curvature =
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(numericHessian(s, stationary, 1e-3))
            .eigenvalues();
    EXPECT_GT(curvature.minCoeff(), 0.0);
    // The bounded step goes uphill instead.
    EXPECT_GT(s.value(delta), solution.current);
    EXPECT_NEAR(solution.predicted, s.value(delta), 1e-9);
  }
}

// ---------------------------------------------------------------------------------------------
// Derivatives of the search problem's templates and NCC.

// The synthetic problem's texture model reproduces the image at the truth exactly, so the
// template of landmark k with its texture moved by s is the masked, normalised image patch at
// x_k + s, problem.sampleMasked. D_k must be its derivative. Returns the largest relative error.
double templateGradientError(const test::SyntheticProblem& s, double h) {
  const SearchProblem& problem = *s.problem;
  InverseLinearisation linear;
  EXPECT_TRUE(linear.refresh(problem));
  EXPECT_FALSE(linear.refresh(problem));  // cached until the next synthesis
  const Eigen::Matrix2Xd points = s.points(s.truth);
  const int pixels = problem.patchPixels();
  Eigen::VectorXf plus(pixels), minus(pixels);
  double worst = 0.0;
  for (int k = 0; k < problem.landmarkCount(); ++k) {
    const Eigen::Vector2d x = points.col(k);
    problem.sampleMasked(k, x, plus);
    EXPECT_LT((plus - problem.templ(k)).norm(), 1e-3 * std::sqrt(pixels));
    for (int axis = 0; axis < 2; ++axis) {
      const Eigen::Vector2d step = axis == 0 ? Eigen::Vector2d(h, 0) : Eigen::Vector2d(0, h);
      problem.sampleMasked(k, x + step, plus);
      problem.sampleMasked(k, x - step, minus);
      const Eigen::VectorXf numeric = (plus - minus) / static_cast<float>(2.0 * h);
      const auto analytic = linear.templateGradients().col(2 * k + axis);
      worst = std::max(worst, double((analytic - numeric).norm() / numeric.norm()));
      // Normalisation: each derivative is centred and orthogonal to its template.
      EXPECT_NEAR(analytic.sum(), 0.0, 1e-4 * analytic.norm() * pixels);
      EXPECT_NEAR(analytic.dot(problem.templ(k)), 0.0, 1e-4 * analytic.norm() * pixels);
    }
    const Eigen::Matrix2d hk = linear.landmarkHessian(k);
    const auto dk = linear.templateGradients().middleCols(2 * k, 2);
    EXPECT_LT((hk - (dk.transpose() * dk).cast<double>()).norm(), 1e-4 * hk.norm());
  }
  return worst;
}

TEST(FastNccDerivatives, TemplateGradientsMatchFiniteDifferencesExactlyOnABilinearImage) {
  // Exact up to float rounding (hence a half-pixel step) and the O(h^2) of central differences:
  // tests the chain of normalisations and the mask.
  for (const bool masked : {false, true}) {
    test::SyntheticOptions options;
    options.alphaMask = masked;
    options.patchSize = 15;
    options.bilinear = true;
    const auto s = test::makeSyntheticProblem(options);
    EXPECT_LT(templateGradientError(*s, 0.5), 5e-3) << "masked " << masked;
  }
}

TEST(FastNccDerivatives, TemplateGradientsMatchFiniteDifferencesOnASmoothImage) {
  // The 5-tap kernel smooths a little: a few percent against a one-pixel central difference.
  for (const bool masked : {false, true}) {
    const auto s = test::makeSyntheticProblem(false, masked, 15, true);
    EXPECT_LT(templateGradientError(*s, 0.5), 0.08) << "masked " << masked;
  }
}

TEST(FastNccDerivatives, NccGradientMatchesFiniteDifferencesOfSampleMasked) {
  // The optimisers predict the change of landmark k's NCC when the image point moves by s from
  // the template side: d NCC / ds = -D_k' g_k / N (moving the image by s = moving the template by
  // -s). Check against central differences of the NCC of problem.sampleMasked patches, a little
  // away from the match (at the match both are zero).
  for (const bool masked : {false, true}) {
    const auto s = test::makeSyntheticProblem(false, masked, 15, true);
    const SearchProblem& problem = *s->problem;
    const int pixels = problem.patchPixels();
    Eigen::VectorXd p = s->truth;
    p[kParamTx] += 0.8;
    p[kParamTy] -= 0.6;
    InverseLinearisation linear;
    linear.linearise(problem, p);
    Eigen::VectorXf g(pixels);
    auto ncc = [&](int k, const Eigen::Vector2d& at) {
      problem.sampleMasked(k, at, g);
      return static_cast<double>(g.dot(problem.templ(k))) / pixels;
    };
    for (int k = 0; k < problem.landmarkCount(); ++k) {
      const Eigen::Vector2d x = linear.points().col(k);
      const double h = 0.05;
      const Eigen::Vector2d numeric(
          (ncc(k, x + Eigen::Vector2d(h, 0)) - ncc(k, x - Eigen::Vector2d(h, 0))) / (2 * h),
          (ncc(k, x + Eigen::Vector2d(0, h)) - ncc(k, x - Eigen::Vector2d(0, h))) / (2 * h));
      const Eigen::Vector2d predicted = -linear.imageGradient().segment<2>(2 * k) / pixels;
      EXPECT_GT(predicted.dot(numeric), 0.9 * predicted.norm() * numeric.norm())
          << "landmark " << k << " masked " << masked;
      EXPECT_LT((predicted - numeric).norm(), 0.25 * numeric.norm())
          << "landmark " << k << " masked " << masked;
      // The sums the optimisers use are those of the sampled patches.
      problem.sampleMasked(k, x, g);
      EXPECT_NEAR(linear.cross()[k], g.dot(problem.templ(k)), 1e-3 * pixels);
      EXPECT_NEAR(linear.imageNorm2()[k], pixels, 1e-2 * pixels);
    }
  }
}

TEST(FastNccDerivatives, ChainThroughTheProjectorJacobianMatchesTheDenseSteepestDescentImages) {
  for (const bool planar : {false, true}) {
    const auto s = test::makeSyntheticProblem(planar, true, 13, true);
    const SearchProblem& problem = *s->problem;
    const int m = problem.landmarkCount();
    const int pixels = problem.patchPixels();
    const int params = problem.paramCount();
    Eigen::VectorXd p = s->truth;
    p[kParamTx] += 0.3;
    p[kParamRoll] += 0.004;
    p[shapeParam(0)] -= 0.2;
    InverseLinearisation linear;
    linear.linearise(problem, p);

    // The Jacobian is the projector's, at p.
    Eigen::MatrixXd jacobian(2 * m, params);
    problem.projector().jacobian(p, jacobian);
    EXPECT_LT((linear.jacobian() - jacobian).cwiseAbs().maxCoeff(), 1e-12);

    // Dense steepest-descent images (thesis eq. A.20): SD = [D_k J_k] stacked over landmarks.
    Eigen::MatrixXd sd(Eigen::Index(pixels) * m, params);
    Eigen::VectorXd g(Eigen::Index(pixels) * m);
    for (int k = 0; k < m; ++k) {
      sd.middleRows(Eigen::Index(k) * pixels, pixels) =
          linear.templateGradients().middleCols(2 * k, 2).cast<double>() *
          jacobian.middleRows(2 * k, 2);
      g.segment(Eigen::Index(k) * pixels, pixels) = linear.imagePatches().col(k).cast<double>();
    }
    const Eigen::MatrixXd dense = sd.transpose() * sd;
    EXPECT_LT((linear.hessian() - dense).norm(), 1e-4 * dense.norm());
    Eigen::VectorXd chained(params);
    linear.chain(linear.imageGradient(), chained);
    const Eigen::VectorXd direct = sd.transpose() * g;
    EXPECT_LT((chained - direct).norm(), 1e-4 * direct.norm());

    // And through the chain, the predicted gradient of the mean NCC with respect to p matches
    // central differences of problem.meanNcc (the image side). Pitch and yaw of the planar model
    // do not move any point: zero gradient, and fixed.
    const Eigen::VectorXd predicted = -chained / (double(m) * pixels);
    for (int i = 0; i < params; ++i) {
      Eigen::VectorXd plus = p, minus = p;
      const double h = 1e-3;
      plus[i] += h;
      minus[i] -= h;
      const double numeric = (problem.meanNcc(plus) - problem.meanNcc(minus)) / (2 * h);
      if (planar && (i == kParamPitch || i == kParamYaw)) {
        EXPECT_TRUE(linear.fixed(i));
        EXPECT_EQ(predicted[i], 0.0);
        continue;
      }
      EXPECT_FALSE(linear.fixed(i));
      EXPECT_NEAR(predicted[i], numeric, 0.25 * std::abs(numeric) + 1e-4)
          << "parameter " << i << " planar " << planar;
    }
  }
}

// ---------------------------------------------------------------------------------------------
// The optimiser.

TEST(FastNccOptimiser, RegisteredByName) {
  EXPECT_EQ(makeOptimiser("fastncc")->name(), "fastncc");
  const auto& names = optimiserNames();
  EXPECT_NE(std::find(names.begin(), names.end(), "fastncc"), names.end());
}

TEST(FastNccOptimiser, StepsTowardsTheTruthInverseSign) {
  test::expectStepsTowardsTheTruth("fastncc");
}

TEST(FastNccOptimiser, RecoversPoseAndShapeOfARenderedHead3D) {
  test::expectRecovery(test::fitTestModel(), "fastncc", 0.0);
  test::expectRecovery(test::fitTestModel(), "fastncc", 20.0);
}

TEST(FastNccOptimiser, RecoversPoseAndShapeOfARenderedHeadPlanar) {
  test::expectRecovery(test::fitTestModel2D(), "fastncc", 0.0);
}

}  // namespace
}  // namespace clm3d
