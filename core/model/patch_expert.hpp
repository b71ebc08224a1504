// A discriminative patch expert (issue 12): for one landmark, view and scale, a linear filter on
// the normalised patch followed by a logistic unit, trained on patches at the true position
// against displaced ones (core/train/expert_training.hpp). Evaluated at every offset of a search
// window it gives a response map, the probability that the landmark lies there; the RLMS optimiser
// (core/fit/rlms_optimiser.cpp) fits the shape model to those maps. Unlike the thesis's PCA
// templates matched by NCC, the filter learns which pixels tell the landmark from its
// surroundings, so it does not reproduce whatever lies under a misplaced point.
#pragma once

#include <Eigen/Core>

namespace clm3d {

struct PatchExpert {
  // patchSize^2 weights on the normalised patch (normalisePatch), row-major, zero mean, so the
  // score w . n(x) does not depend on the patch's brightness or contrast.
  Eigen::VectorXf weights;
  float gain = 1.0f;  // response = 1 / (1 + exp(-(gain * score + bias)))
  float bias = 0.0f;

  bool empty() const { return weights.size() == 0; }
  // The logistic response for a score w . n(x).
  float response(float score) const;
};

// The expert of the mirrored landmark in the mirrored view: the weights flipped left-right.
PatchExpert flipExpert(const PatchExpert& expert, int patchSize);

}  // namespace clm3d
