// The step check both inverse optimisers' tests run (gauss-newton, fastncc) on the synthetic
// problem: with templates at the truth, one step from a start off in translation, rotation and
// shape must remove most of the point error (with the wrong sign of the inverse update it would
// double it), a few more all of it, and the planar model's pitch and yaw must stay 0.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "core/fit/optimiser.hpp"
#include "tests/unit/fit/synthetic_problem.hpp"

namespace clm3d::test {

inline void expectStepsTowardsTheTruth(const std::string& optimiserName) {
  for (const bool planar : {false, true}) {
    for (const bool masked : {false, true}) {
      const auto s = makeSyntheticProblem(planar, masked);
      OptimiserSettings settings;
      settings.shapePrior = 0.0;  // the exact answer is the truth
      auto optimiser = makeOptimiser(optimiserName, settings);
      Eigen::VectorXd p = s->truth;
      p[kParamTx] += 1.5;
      p[kParamTy] -= 1.0;
      p[kParamRoll] += 0.02;
      p[shapeParam(0)] += 1.0;
      const double start = s->meanError(p);
      optimiser->beginFit(p);
      optimiser->step(*s->problem, p);
      s->problem->clamp(p);
      EXPECT_LT(s->meanError(p), 0.4 * start) << "planar " << planar << " masked " << masked;
      for (int i = 0; i < 5; ++i) {
        optimiser->step(*s->problem, p);
        s->problem->clamp(p);
      }
      EXPECT_LT(s->meanError(p), 0.01) << "planar " << planar << " masked " << masked;
      if (planar) {
        EXPECT_EQ(p[kParamPitch], 0.0);
        EXPECT_EQ(p[kParamYaw], 0.0);
      }
    }
  }
}

}  // namespace clm3d::test
