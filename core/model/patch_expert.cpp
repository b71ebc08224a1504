#include "core/model/patch_expert.hpp"

#include <cmath>

#include "core/model/texture_model.hpp"

namespace clm3d {

float PatchExpert::response(float score) const {
  return 1.0f / (1.0f + std::exp(-(gain * score + bias)));
}

PatchExpert flipExpert(const PatchExpert& expert, int patchSize) {
  PatchExpert flipped = expert;
  if (!expert.empty()) flipped.weights = flipPatch(expert.weights, patchSize);
  return flipped;
}

}  // namespace clm3d
