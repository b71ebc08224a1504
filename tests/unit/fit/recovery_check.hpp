// The recovery check both inverse optimisers' tests run (gauss-newton, fastncc): the Fitter's whole
// search, with a named optimiser, from a start a few pixels, degrees and a shape offset away from
// the truth of a rendered head of the fit fixture (tests/support/fit_fixture.hpp).
#pragma once

#include <gtest/gtest.h>

#include <iostream>
#include <string>

#include "core/fit/fitter.hpp"
#include "tests/support/fit_fixture.hpp"

namespace clm3d::test {

struct RecoveryResult {
  double before = 0.0;  // mean point error of the start, pixels, over the visible landmarks
  double after = 0.0;   // of the result
  double floor = 0.0;   // of the truth state (about what the shape model can reach)
  double interOcular = 0.0;
  FitResult fit;
};

// From the truth moved by 3.5 px right, 3 px up, 3 degrees in roll (and yaw, 3D), 3 % in scale and
// 0.5 SD in every shape mode: about 5 px (0.09 inter-ocular) off for the 3D model, 7.5 px for the
// planar one.
inline RecoveryResult runRecovery(const ClmModel& model, const std::string& optimiser,
                                  double yawDeg, int head = 0) {
  const FitScene scene = makeFitScene(model, 0.0, yawDeg, head);
  FitSettings settings;
  settings.optimiser = optimiser;
  Fitter fitter(model, scene.camera, settings);
  const FitState start = perturbState(scene, model, 3.5, -3.0, 3.0, 1.03, 0.5);
  RecoveryResult r;
  r.before = meanPointError(fitter.project(start), scene.truthPoints, scene.visible);
  r.fit = fitter.fit(scene.image, start);
  r.after = meanPointError(r.fit.points, scene.truthPoints, scene.visible);
  r.floor = meanPointError(fitter.project(scene.truth), scene.truthPoints, scene.visible);
  r.interOcular = scene.interOcular;
  return r;
}

// The expectations both tests hold their optimiser to (measured: 3D frontal 0.43 px, 3D at yaw 20
// about 1 px (the texture model of 3 renders per view limits it: powell ends there too), planar
// 0.25 px above the planar model's own floor of 3.3 px).
inline void expectRecovery(const ClmModel& model, const std::string& optimiser, double yawDeg) {
  const RecoveryResult r = runRecovery(model, optimiser, yawDeg);
  const bool planar = model.shape.dims == 2;
  const std::string label = optimiser + (planar ? " planar" : " 3D") + " yaw " +
                            std::to_string(static_cast<int>(yawDeg)) + ": start " +
                            std::to_string(r.before) + " px, end " + std::to_string(r.after) +
                            " px, model floor " + std::to_string(r.floor) + " px";
  std::cout << "[ " << label << ", " << r.fit.iterations << " iterations ]\n";
  EXPECT_GT(r.before, 0.08 * r.interOcular) << label;
  if (planar) {
    EXPECT_LT(r.after, r.floor + 0.75) << label;
    EXPECT_LT(r.after, 0.6 * r.before) << label;
  } else {
    EXPECT_LT(r.after, yawDeg == 0.0 ? 0.75 : 1.5) << label;  // 0.0125 / 0.025 inter-ocular
    EXPECT_LT(r.after, 0.3 * r.before) << label;
  }
  EXPECT_GT(r.fit.searchScore, 0.55) << label;
}

}  // namespace clm3d::test
