// A discriminative patch expert (issue 12): for one landmark, view and scale, a small neural field
// on the normalised patch, trained on patches at the true position against displaced ones
// (core/train/detail/expert_training.hpp). Evaluated at every offset of a search window it gives a
// response map that peaks where the landmark lies; the RLMS optimiser (core/fit/rlms_optimiser.cpp)
// fits the shape model to those maps. Unlike the thesis's PCA templates matched by NCC, the
// filters learn which pixels tell the landmark from its surroundings, so they do not reproduce
// whatever lies under a misplaced point.
//
// The response is sum_k alpha_k sigmoid(w_k . n(x) + b_k) over K units. K = 1 with alpha 1 is a
// linear filter with a logistic output (model format 2's expert, and `--expert-units 1`); more
// units, as the vertex features of OpenFace's local neural fields, let the expert say "any of
// these appearances" rather than one average appearance.
#pragma once

#include <Eigen/Core>

namespace clm3d {

struct PatchExpert {
  // patchSize^2 x K: one filter per unit on the normalised patch (normalisePatch), row-major
  // pixels, each column zero mean, so a score w_k . n(x) does not depend on the patch's
  // brightness or contrast.
  Eigen::MatrixXf weights;
  Eigen::VectorXf bias;   // K
  Eigen::VectorXf alpha;  // K: each unit's weight in the response

  bool empty() const { return weights.size() == 0; }
  int units() const { return static_cast<int>(weights.cols()); }
  // The response for the K scores w_k . n(x).
  float response(const float* scores) const;
  // A linear filter with a logistic output: one unit, alpha 1.
  static PatchExpert logistic(const Eigen::VectorXf& filter, float gain, float bias);
};

// The expert of the mirrored landmark in the mirrored view: every filter flipped left-right.
PatchExpert flipExpert(const PatchExpert& expert, int patchSize);

}  // namespace clm3d
