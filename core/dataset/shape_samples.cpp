// sampleShapeOnlyLandmarks (declared in training_subjects.hpp): ICT-FaceKit samples brought into
// model coordinates like the scans.
#include <Eigen/Core>
#include <algorithm>

#include "core/common/error.hpp"
#include "core/dataset/detail/model_frame.hpp"
#include "core/dataset/ict_facekit.hpp"
#include "core/dataset/training_subjects.hpp"
#include "core/scheme/scheme.hpp"

namespace clm3d {

std::vector<LandmarkSet> sampleShapeOnlyLandmarks(const DatasetManifest& manifest,
                                                  std::uint64_t seed,
                                                  const ProgressCallback& progress,
                                                  const CancelToken* cancel) {
  const Scheme scheme = Scheme::byNameOrPath(manifest.scheme);
  std::vector<LandmarkSet> samples;
  const double sources = static_cast<double>(std::max<std::size_t>(1, manifest.ict.size()));
  for (std::size_t s = 0; s < manifest.ict.size(); ++s) {
    const IctSource& source = manifest.ict[s];
    const std::string field = "field ict_facekit[" + std::to_string(s) + "]";
    const std::vector<int> indices =
        readLandmarkVertexTable(source.vertices, scheme.name(), scheme.size());
    if (indices.empty() || indices[0] < 0) {
      throwInputError(source.vertices, "landmark 1, the model's origin, has no vertex");
    }
    ProgressCallback sourceProgress;
    if (progress) {
      sourceProgress = [&](double fraction, std::string_view stage) {
        progress((static_cast<double>(s) + 0.95 * fraction) / sources, stage);
      };
    }
    const IctLandmarkBasis basis =
        loadIctLandmarkBasis(source.model, indices, sourceProgress, cancel);

    // Level on the eyes like the scans when the scheme says where the eyes are.
    const bool levelEyes = scheme.name() == "thesis25" || scheme.name() == "ibug68";
    IctSampling sampling;
    sampling.identityWeightSd = source.identityWeightSd;
    sampling.expressionsPerSample = source.expressionsPerSample;
    if (source.expressions.empty()) {
      for (std::size_t e = 0; e < basis.expressions.size(); ++e) {
        sampling.expressionPool.push_back(static_cast<int>(e));
      }
    }
    for (std::size_t k = 0; k < source.expressions.size(); ++k) {
      const auto& names = basis.expressionNames;
      const auto it = std::find(names.begin(), names.end(), source.expressions[k]);
      if (it == names.end()) {
        throwInputError(manifest.file, field + ".expressions[" + std::to_string(k) +
                                           "]: the model " + source.model.string() +
                                           " has no blendshape '" + source.expressions[k] + "'");
      }
      sampling.expressionPool.push_back(static_cast<int>(it - names.begin()));
    }

    for (int i = 0; i < source.identities; ++i) {
      if (cancel) cancel->throwIfCancelled();
      const Eigen::Matrix3Xd points = sampleIctLandmarks(basis, sampling, seed + source.seedOffset,
                                                         static_cast<std::uint64_t>(i));
      LandmarkSet raw(scheme.size(), 3);
      for (int p = 0; p < scheme.size(); ++p) {
        if (indices[static_cast<std::size_t>(p)] >= 0) raw.set(p, Eigen::Vector3d(points.col(p)));
      }
      std::string why;
      const auto frame = modelFrame(raw, scheme, Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ(),
                                    levelEyes, why);
      if (!frame) throwInputError(source.vertices, why);
      samples.push_back(applyFrame(*frame, raw));
    }
    if (progress) progress(static_cast<double>(s + 1) / sources, "sampling ICT-FaceKit shapes");
  }
  return samples;
}

}  // namespace clm3d
