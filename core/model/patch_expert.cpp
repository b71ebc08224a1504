#include "core/model/patch_expert.hpp"

#include <algorithm>
#include <cmath>

#include "core/model/texture_model.hpp"

namespace clm3d {

float PatchExpert::response(const float* scores) const {
  float sum = 0.0f;
  for (Eigen::Index k = 0; k < weights.cols(); ++k) {
    sum += alpha[k] / (1.0f + std::exp(-(scores[k] + bias[k])));
  }
  return std::max(sum, 0.0f);  // a non-negative weight for the mean-shift, whatever the file says
}

PatchExpert PatchExpert::logistic(const Eigen::VectorXf& filter, float gain, float bias) {
  PatchExpert expert;
  expert.weights = gain * filter;
  expert.bias = Eigen::VectorXf::Constant(1, bias);
  expert.alpha = Eigen::VectorXf::Ones(1);
  return expert;
}

PatchExpert flipExpert(const PatchExpert& expert, int patchSize) {
  PatchExpert flipped = expert;
  for (Eigen::Index k = 0; k < expert.weights.cols(); ++k) {
    flipped.weights.col(k) = flipPatch(expert.weights.col(k), patchSize);
  }
  return flipped;
}

}  // namespace clm3d
