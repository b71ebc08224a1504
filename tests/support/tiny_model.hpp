// A tiny, valid, deterministic ClmModel for tests that need a model file without training one:
// a 5-point scheme (mid-line, left/right eye, nose, mouth), a 3D shape model, three views
// (yaw -30, 0, +30; the +30 view is the mirror of the -30 one, which hides the right eye) at two
// scales of 4x4 patches. Header-only so any test executable linked with clm3d::model can use it.
#pragma once

#include <Eigen/Core>
#include <random>
#include <string>

#include "core/model/clm_model.hpp"
#include "core/model/pca.hpp"
#include "core/model/texture_model.hpp"

namespace clm3d::test {

inline const char* tinySchemeJson() {
  return R"({"name": "tiny5",
  "landmarks": [{"id": "mid"}, {"id": "left_eye"}, {"id": "right_eye"}, {"id": "nose"},
                {"id": "mouth"}],
  "mirror_pairs": [["left_eye", "right_eye"]],
  "normalisation": ["left_eye", "right_eye"]})";
}

// A patch model of the given landmarks fitted to random (normalised) patches.
inline PatchModel makeTinyPatchModel(const std::vector<int>& landmarks, int patchSize,
                                     std::mt19937& random) {
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  PatchModel patch;
  patch.patchSize = patchSize;
  patch.landmarks = landmarks;
  const int pixels = patchSize * patchSize;
  const int samples = 6;
  Eigen::MatrixXf data(static_cast<Eigen::Index>(landmarks.size()) * pixels, samples);
  for (int s = 0; s < samples; ++s) {
    for (Eigen::Index i = 0; i < data.rows(); ++i) data(i, s) = uniform(random);
    for (std::size_t e = 0; e < landmarks.size(); ++e) {
      normalisePatch(data.col(s).segment(static_cast<Eigen::Index>(e) * pixels, pixels));
    }
  }
  patch.pca = fitPca(data, 0.9);
  for (std::size_t e = 0; e < landmarks.size(); ++e) {
    Eigen::VectorXf alpha(pixels);
    for (int p = 0; p < pixels; ++p) alpha[p] = uniform(random);
    patch.alpha.push_back(alpha);
  }
  return patch;
}

inline ClmModel makeTinyModel(unsigned seed = 1) {
  std::mt19937 random(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  ClmModel model;
  model.schemeJson = tinySchemeJson();
  const Scheme scheme = model.scheme();

  model.shape.meanShape.resize(3, 5);
  model.shape.meanShape << 0, 30, -30, 0, 0,  //
      0, -2, -2, -35, -60,                    //
      0, -10, -10, 25, 5;
  Eigen::MatrixXd deviations(15, 8);
  for (Eigen::Index i = 0; i < deviations.size(); ++i) deviations.data()[i] = normal(random);
  const PcaBasis basis = principalAxes(deviations.colwise() - deviations.rowwise().mean(), 0.95);
  model.shape.modes = basis.components;
  model.shape.variances = basis.variances;

  ViewModel left;
  left.yawDeg = -30;
  left.visible = {true, true, false, true, true};
  ViewModel front;
  front.visible = {true, true, true, true, true};
  for (int s = 0; s < 2; ++s) {
    left.scales.push_back(makeTinyPatchModel({0, 1, 3, 4}, 4, random));
    front.scales.push_back(makeTinyPatchModel({0, 1, 2, 3, 4}, 4, random));
  }
  model.views = {left, front, mirrorView(left, scheme)};
  model.settingsJson = R"({"patchSize": 4, "scales": 2})";
  model.provenance = {"tiny.json", "2024-01-02T03:04:05Z", "0.0.0-test", seed, "made by a test"};
  return model;
}

}  // namespace clm3d::test
