// The Nelder-Mead downhill simplex method (the original CLM's optimiser, thesis section 4.2):
// n + 1 points in n dimensions; each iteration replaces the worst point by its reflection through
// the centroid of the others, expanded, or contracted, or shrinks the simplex towards the best
// point. A pure algorithm over any objective functor, independent of the CLM search, so it can be
// tested on analytic functions; core/fit/nelder_mead_optimiser.cpp wraps it for SearchProblem.
// Buffers are sized once per dimension; minimising allocates nothing.
#pragma once

#include <Eigen/Core>
#include <cmath>

namespace clm3d {

struct SimplexSettings {
  double initialSize = 2.0;  // the initial simplex is x and x + initialSize e_i
  int maxIterations = 200;
  // Converged when every vertex is within xTolerance of the best one (max norm) and the values
  // differ by at most fTolerance.
  double xTolerance = 1e-3;
  double fTolerance = 1e-9;
  // The standard coefficients (Nelder and Mead 1965).
  double reflection = 1.0;
  double expansion = 2.0;
  double contraction = 0.5;
  double shrink = 0.5;
};

class NelderMeadSimplex {
 public:
  // Calls of f during the last minimise().
  int evaluations() const { return evaluations_; }
  int iterations() const { return iterations_; }

  // Minimises f: double(const Eigen::VectorXd&) from x, where fx = f(x); writes the best vertex
  // to x and returns its value.
  template <class F>
  double minimise(F& f, Eigen::VectorXd& x, double fx, const SimplexSettings& settings) {
    const int n = static_cast<int>(x.size());
    resize(n);
    evaluations_ = 0;
    iterations_ = 0;
    vertices_.col(0) = x;
    values_[0] = fx;
    for (int i = 0; i < n; ++i) {
      vertices_.col(i + 1) = x;
      vertices_(i, i + 1) += settings.initialSize;
      values_[i + 1] = evaluate(f, vertices_.col(i + 1));
    }
    while (iterations_ < settings.maxIterations) {
      // Best, worst and second-worst vertices.
      int best = 0, worst = 0;
      for (int i = 1; i <= n; ++i) {
        if (values_[i] < values_[best]) best = i;
        if (values_[i] > values_[worst]) worst = i;
      }
      if (best == worst) worst = (best == 0) ? 1 : 0;  // all equal: any other vertex is worst
      int second = best;
      for (int i = 0; i <= n; ++i) {
        if (i != worst && values_[i] >= values_[second]) second = i;
      }
      if (converged(best, worst, settings)) break;
      ++iterations_;

      centroid_.setZero();
      for (int i = 0; i <= n; ++i) {
        if (i != worst) centroid_ += vertices_.col(i);
      }
      centroid_ /= n;

      // Reflect the worst vertex through the centroid.
      reflected_ = centroid_ + settings.reflection * (centroid_ - vertices_.col(worst));
      const double fr = evaluate(f, reflected_);
      if (fr < values_[best]) {
        // Better than the best: try going further.
        trial_ = centroid_ + settings.expansion * (reflected_ - centroid_);
        const double fe = evaluate(f, trial_);
        if (fe < fr) {
          replace(worst, trial_, fe);
        } else {
          replace(worst, reflected_, fr);
        }
        continue;
      }
      if (fr < values_[second]) {  // better than the second worst: accept the reflection
        replace(worst, reflected_, fr);
        continue;
      }
      // The reflection is no improvement on the second worst: contract, outside the simplex
      // (towards the reflection) if the reflection beats the worst vertex, else inside.
      if (fr < values_[worst]) {
        trial_ = centroid_ + settings.contraction * (reflected_ - centroid_);
        const double fc = evaluate(f, trial_);
        if (fc <= fr) {
          replace(worst, trial_, fc);
          continue;
        }
      } else {
        trial_ = centroid_ + settings.contraction * (vertices_.col(worst) - centroid_);
        const double fc = evaluate(f, trial_);
        if (fc < values_[worst]) {
          replace(worst, trial_, fc);
          continue;
        }
      }
      // Contraction failed: shrink every vertex towards the best one.
      for (int i = 0; i <= n; ++i) {
        if (i == best) continue;
        vertices_.col(i) =
            vertices_.col(best) + settings.shrink * (vertices_.col(i) - vertices_.col(best));
        values_[i] = evaluate(f, vertices_.col(i));
      }
    }
    int best = 0;
    for (int i = 1; i <= n; ++i) {
      if (values_[i] < values_[best]) best = i;
    }
    x = vertices_.col(best);
    return values_[best];
  }

 private:
  void resize(int n) {
    if (vertices_.rows() == n && vertices_.cols() == n + 1) return;
    vertices_.resize(n, n + 1);
    values_.resize(n + 1);
    centroid_.resize(n);
    reflected_.resize(n);
    trial_.resize(n);
    point_.resize(n);
  }

  template <class F, class Point>
  double evaluate(F& f, const Point& point) {
    point_ = point;  // f takes a VectorXd; copying into a sized buffer does not allocate
    ++evaluations_;
    return f(point_);
  }

  void replace(int index, const Eigen::VectorXd& point, double value) {
    vertices_.col(index) = point;
    values_[index] = value;
  }

  bool converged(int best, int worst, const SimplexSettings& settings) const {
    if (values_[worst] - values_[best] > settings.fTolerance) return false;
    for (Eigen::Index i = 0; i < vertices_.cols(); ++i) {
      if ((vertices_.col(i) - vertices_.col(best)).cwiseAbs().maxCoeff() > settings.xTolerance) {
        return false;
      }
    }
    return true;
  }

  Eigen::MatrixXd vertices_;  // n x (n + 1)
  Eigen::VectorXd values_;
  Eigen::VectorXd centroid_, reflected_, trial_, point_;
  int evaluations_ = 0;
  int iterations_ = 0;
};

}  // namespace clm3d
