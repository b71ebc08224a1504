// The CLM objective in the coordinates the derivative-free optimisers (powell, nelder-mead) work
// in: y, one entry per parameter that moves the points, with p = clamp(p0 + U y) where U holds
// ShapeProjector::unitSteps at p0. A unit move along any coordinate then moves the projected
// points by about one pixel of the current pyramid level, so one step size, one tolerance and one
// simplex size suit translation, scale, angles and shape alike. The value is -meanNcc, to be
// minimised; clamping inside the evaluation makes the shape limits hard constraints. Allocates
// nothing once sized.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/fit/search_problem.hpp"

namespace clm3d {

class UnitStepObjective {
 public:
  // New origin p0 (already valid) and unit steps for the problem's current level and view.
  void reset(const SearchProblem& problem, const Eigen::Ref<const Eigen::VectorXd>& p0) {
    problem_ = &problem;
    origin_ = p0;
    problem.projector().unitSteps(p0, steps_);
    active_.clear();
    for (Eigen::Index k = 0; k < steps_.size(); ++k) {
      if (steps_[k] > 0.0) active_.push_back(static_cast<int>(k));
    }
    point_.resize(p0.size());
    evaluations_ = 0;
  }

  // Number of free coordinates (parameters with a non-zero unit step).
  int dimension() const { return static_cast<int>(active_.size()); }
  const std::vector<int>& active() const { return active_; }
  const Eigen::VectorXd& steps() const { return steps_; }
  int evaluations() const { return evaluations_; }

  // -meanNcc at clamp(p0 + U y).
  double operator()(const Eigen::VectorXd& y) {
    toParams(y, point_);
    ++evaluations_;
    return -problem_->meanNcc(point_);
  }

  // p = clamp(p0 + U y). p must have the problem's paramCount() entries.
  void toParams(const Eigen::VectorXd& y, Eigen::VectorXd& p) const {
    p = origin_;
    for (int i = 0; i < dimension(); ++i) {
      const int k = active_[static_cast<std::size_t>(i)];
      p[k] += steps_[k] * y[i];
    }
    problem_->clamp(p);
  }

  // Moves y onto the feasible set: the coordinates of clamp(p0 + U y).
  void project(Eigen::VectorXd& y) {
    toParams(y, point_);
    for (int i = 0; i < dimension(); ++i) {
      const int k = active_[static_cast<std::size_t>(i)];
      y[i] = (point_[k] - origin_[k]) / steps_[k];
    }
  }

 private:
  const SearchProblem* problem_ = nullptr;
  Eigen::VectorXd origin_;
  Eigen::VectorXd steps_;
  Eigen::VectorXd point_;
  std::vector<int> active_;
  int evaluations_ = 0;
};

}  // namespace clm3d
