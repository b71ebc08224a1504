#include "core/model/texture_model.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/common/error.hpp"

namespace clm3d {

int PatchModel::entryOf(int landmark) const {
  const auto it = std::lower_bound(landmarks.begin(), landmarks.end(), landmark);
  if (it == landmarks.end() || *it != landmark) return -1;
  return static_cast<int>(it - landmarks.begin());
}

void normalisePatch(Eigen::Ref<Eigen::VectorXf> patch) {
  if (patch.size() == 0) return;
  // Accumulate in double (400 floats of 0..255 lose digits in a float sum), without allocating:
  // the fitter calls this for every landmark on every iteration.
  double sum = 0.0;
  for (const float value : patch) sum += value;
  const double mean = sum / static_cast<double>(patch.size());
  double squares = 0.0;
  for (const float value : patch) squares += (value - mean) * (value - mean);
  const double variance = squares / static_cast<double>(patch.size());
  if (!(variance > 1e-12) || !std::isfinite(variance)) {
    patch.setZero();
    return;
  }
  const double inverse = 1.0 / std::sqrt(variance);
  for (float& value : patch) value = static_cast<float>((value - mean) * inverse);
}

Eigen::VectorXf flipPatch(const Eigen::Ref<const Eigen::VectorXf>& patch, int size) {
  if (size < 0 || patch.size() != Eigen::Index(size) * size) {
    throw Error("flipPatch: a patch of " + std::to_string(patch.size()) + " values is not " +
                std::to_string(size) + " x " + std::to_string(size));
  }
  Eigen::VectorXf flipped(patch.size());
  for (int row = 0; row < size; ++row) {
    for (int col = 0; col < size; ++col) {
      flipped[row * size + col] = patch[row * size + (size - 1 - col)];
    }
  }
  return flipped;
}

namespace {

// Flips every patch-sized block of a concatenated vector, taking block j from source block
// sourceEntry[j].
Eigen::VectorXf permuteFlip(const Eigen::Ref<const Eigen::VectorXf>& source,
                            const std::vector<int>& sourceEntry, int size) {
  const Eigen::Index pixels = Eigen::Index(size) * size;
  Eigen::VectorXf result(source.size());
  for (std::size_t j = 0; j < sourceEntry.size(); ++j) {
    result.segment(Eigen::Index(j) * pixels, pixels) =
        flipPatch(source.segment(Eigen::Index(sourceEntry[j]) * pixels, pixels), size);
  }
  return result;
}

PatchModel mirrorPatchModel(const PatchModel& source, const Scheme& scheme,
                            const std::string& where) {
  const int n = scheme.size();
  const Eigen::Index pixels = Eigen::Index(source.patchSize) * source.patchSize;
  const Eigen::Index d = Eigen::Index(source.landmarks.size()) * pixels;
  if (source.pca.mean.size() != d || source.pca.components.rows() != d ||
      source.alpha.size() != source.landmarks.size()) {
    throw Error(where + ": patch model sizes do not match its landmarks");
  }
  PatchModel mirrored;
  mirrored.patchSize = source.patchSize;
  for (const int landmark : source.landmarks) {
    if (landmark < 0 || landmark >= n) throw Error(where + ": landmark index out of range");
    mirrored.landmarks.push_back(scheme.mirrorOf(landmark));
  }
  std::sort(mirrored.landmarks.begin(), mirrored.landmarks.end());
  std::vector<int> sourceEntry;
  for (const int landmark : mirrored.landmarks) {
    const int entry = source.entryOf(scheme.mirrorOf(landmark));
    if (entry < 0) throw Error(where + ": landmarks are not ascending and unique");
    sourceEntry.push_back(entry);
  }
  mirrored.pca.mean = permuteFlip(source.pca.mean, sourceEntry, source.patchSize);
  mirrored.pca.components.resize(d, source.pca.components.cols());
  for (Eigen::Index k = 0; k < source.pca.components.cols(); ++k) {
    mirrored.pca.components.col(k) =
        permuteFlip(source.pca.components.col(k), sourceEntry, source.patchSize);
  }
  mirrored.pca.variances = source.pca.variances;
  for (const int entry : sourceEntry) {
    const auto& alpha = source.alpha[static_cast<std::size_t>(entry)];
    if (alpha.size() != pixels) throw Error(where + ": alpha patch of the wrong size");
    mirrored.alpha.push_back(flipPatch(alpha, source.patchSize));
  }
  if (!source.experts.empty()) {
    if (source.experts.size() != source.landmarks.size()) {
      throw Error(where + ": expert count does not match its landmarks");
    }
    for (const int entry : sourceEntry) {
      mirrored.experts.push_back(
          flipExpert(source.experts[static_cast<std::size_t>(entry)], source.patchSize));
    }
  }
  return mirrored;
}

}  // namespace

ViewModel mirrorView(const ViewModel& source, const Scheme& scheme) {
  const int n = scheme.size();
  if (static_cast<int>(source.visible.size()) != n) {
    throw Error("mirrorView: the view has " + std::to_string(source.visible.size()) +
                " visibility flags for a scheme of " + std::to_string(n) + " landmarks");
  }
  ViewModel mirrored;
  mirrored.pitchDeg = source.pitchDeg;
  mirrored.yawDeg = -source.yawDeg;
  mirrored.mirrored = !source.mirrored;
  mirrored.calibration = source.calibration;
  mirrored.refined = source.refined;
  mirrored.check = source.check;  // read through a flip into the non-mirrored view's frame
  mirrored.visible.resize(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    mirrored.visible[static_cast<std::size_t>(i)] =
        source.visible[static_cast<std::size_t>(scheme.mirrorOf(i))];
  }
  for (std::size_t s = 0; s < source.scales.size(); ++s) {
    mirrored.scales.push_back(
        mirrorPatchModel(source.scales[s], scheme, "mirrorView: scale " + std::to_string(s)));
  }
  return mirrored;
}

}  // namespace clm3d
