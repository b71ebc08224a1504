// A SearchProblem with exactly known answers for the tests of the inverse optimisers (gauss-newton,
// fastncc): a smooth random image (a sum of Gaussian blobs), a small 3D shape model, and a texture
// model whose PCA mean is the image's own normalised patches at the true parameters (no modes), so
// the synthesised templates are the image at the truth. Derivatives can be checked against finite
// differences of the image itself, and a step from a perturbed start must head for the truth.
#pragma once

#include <Eigen/Core>
#include <Eigen/QR>
#include <cmath>
#include <memory>
#include <opencv2/core.hpp>
#include <random>

#include "core/fit/fit_state.hpp"
#include "core/fit/search_problem.hpp"
#include "core/fit/working_image.hpp"
#include "core/geometry/camera.hpp"
#include "core/image/patch_sampling.hpp"
#include "core/model/shape_model.hpp"
#include "core/model/texture_model.hpp"

namespace clm3d::test {

struct SyntheticProblem {
  ShapeModel shape;
  Camera camera;
  WorkingImage working;
  PatchModel patches;
  std::unique_ptr<SearchProblem> problem;
  Eigen::VectorXd truth;
  double depth = -275.0;

  SyntheticProblem() = default;
  SyntheticProblem(const SyntheticProblem&) = delete;
  SyntheticProblem& operator=(const SyntheticProblem&) = delete;

  Eigen::Matrix2Xd points(const Eigen::VectorXd& p) const {
    Eigen::Matrix2Xd out(2, problem->landmarkCount());
    problem->projector().project(p, out);
    return out;
  }
  double meanError(const Eigen::VectorXd& p) const {
    return (points(p) - points(truth)).colwise().norm().mean();
  }
};

// A smooth grey image: mid-grey plus `blobs` Gaussian blobs of minSd-maxSd pixels SD.
inline cv::Mat smoothImage(int width, int height, int blobs, unsigned seed, double minSd = 2.5,
                           double maxSd = 5.0) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> x(0.0, width), y(0.0, height), sd(minSd, maxSd),
      amplitude(-0.25, 0.25);
  cv::Mat image(height, width, CV_32F, cv::Scalar(0.5));
  for (int b = 0; b < blobs; ++b) {
    const double cx = x(random), cy = y(random), s = sd(random), a = amplitude(random);
    for (int r = 0; r < height; ++r) {
      for (int c = 0; c < width; ++c) {
        const double d2 = (c - cx) * (c - cx) + (r - cy) * (r - cy);
        image.at<float>(r, c) += static_cast<float>(a * std::exp(-d2 / (2.0 * s * s)));
      }
    }
  }
  return image;
}

// 0.5 + 0.002 (x - 100) - 0.001 (y - 100) + 0.00005 (x - 100)(y - 100).
inline cv::Mat bilinearImage(int width, int height) {
  cv::Mat image(height, width, CV_32F);
  for (int r = 0; r < height; ++r) {
    for (int c = 0; c < width; ++c) {
      const double x = c - 100.0, y = r - 100.0;
      image.at<float>(r, c) = static_cast<float>(0.5 + 0.002 * x - 0.001 * y + 0.00005 * x * y);
    }
  }
  return image;
}

struct SyntheticOptions {
  bool planar = false;     // the 2D single-view form (dims 2, z = 0, pitch and yaw fixed at 0)
  bool alphaMask = false;  // a smooth radial mask per landmark instead of ones
  int patchSize = 11;
  int landmarks = 6;  // 6: a face-like layout; more: random points over the face
  int modes = 2;
  bool smoother = false;  // blobs of 5-9 pixels SD instead of 2.5-5 (finite-difference checks)
  // Instead of blobs, I = a + b x + c y + d x y: bilinear interpolation and the 5-tap gradient
  // are both exact on it, so derivatives must match finite differences to rounding.
  bool bilinear = false;
  unsigned seed = 7;
};

// The size of a real model's search: 25 landmarks of 20x20, 20 shape modes (26 parameters),
// alpha masks. The inverse optimisers' allocation test and step benchmark use it.
inline SyntheticOptions modelSizedOptions() {
  SyntheticOptions options;
  options.landmarks = 25;
  options.modes = 20;
  options.patchSize = 20;
  options.alphaMask = true;
  return options;
}

inline std::unique_ptr<SyntheticProblem> makeSyntheticProblem(const SyntheticOptions& options) {
  auto s = std::make_unique<SyntheticProblem>();
  const bool planar = options.planar;
  const int patchSize = options.patchSize;
  std::mt19937 random(options.seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  const int n = options.landmarks;
  s->shape.meanShape.resize(3, n);
  if (n == 6) {
    s->shape.meanShape << 30, -30, 0, 25, -25, 0,  //
        20, 20, 0, -30, -30, -45,                  //
        0, 0, 10, 0, 0, 5;
  } else {
    for (int j = 0; j < n; ++j) {
      s->shape.meanShape.col(j) << 45 * uniform(random), 55 * uniform(random), 10 * uniform(random);
    }
  }
  s->shape.dims = planar ? 2 : 3;
  if (planar) s->shape.meanShape.row(2).setZero();
  const int modeCount = options.modes;
  Eigen::MatrixXd modes(3 * n, modeCount);
  for (Eigen::Index i = 0; i < modes.size(); ++i) modes.data()[i] = normal(random);
  if (planar) {
    for (int j = 0; j < n; ++j) modes.row(3 * j + 2).setZero();
  }
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(modes);
  s->shape.modes = qr.householderQ() * Eigen::MatrixXd::Identity(3 * n, modeCount);
  s->shape.variances.resize(modeCount);
  for (int k = 0; k < modeCount; ++k) s->shape.variances[k] = 9.0 / (1.0 + k);
  s->camera = Camera::fromVerticalFov(200, 200, 40.0);
  s->working.levels = {options.bilinear   ? bilinearImage(200, 200)
                       : options.smoother ? smoothImage(200, 200, 120, options.seed, 5.0, 9.0)
                                          : smoothImage(200, 200, 220, options.seed)};
  s->problem = std::make_unique<SearchProblem>(s->shape, s->camera);

  s->truth = Eigen::VectorXd::Zero(kPoseParamCount + modeCount);
  s->truth[kParamTx] = 1.0;
  s->truth[kParamTy] = -2.0;
  s->truth[kParamScale] = 1.0;
  s->truth[kParamPitch] = planar ? 0.0 : 0.1;
  s->truth[kParamYaw] = planar ? 0.0 : -0.15;
  s->truth[kParamRoll] = 0.05;
  for (int k = 0; k < modeCount; ++k) s->truth[shapeParam(k)] = (k % 2 == 0 ? 2.0 : -1.0) / (1 + k);

  // The texture model: the image's normalised patches at the truth as the mean, no modes.
  PatchModel& patches = s->patches;
  patches.patchSize = patchSize;
  for (int j = 0; j < n; ++j) patches.landmarks.push_back(j);
  const int pixels = patchSize * patchSize;
  Eigen::Matrix2Xd at(2, n);
  ShapeProjector projector(s->shape, s->camera);
  projector.setDepth(s->depth);
  projector.project(s->truth, at);
  patches.pca.mean.resize(Eigen::Index(n) * pixels);
  patches.pca.components.resize(Eigen::Index(n) * pixels, 0);
  patches.pca.variances.resize(0);
  const double half = (patchSize - 1) / 2.0;
  for (int j = 0; j < n; ++j) {
    auto segment = patches.pca.mean.segment(Eigen::Index(j) * pixels, pixels);
    samplePatch(s->working.levels[0], at.col(j), patchSize, segment);
    normalisePatch(segment);
    Eigen::VectorXf alpha(pixels);
    for (int r = 0; r < patchSize; ++r) {
      for (int c = 0; c < patchSize; ++c) {
        const double shift = 0.3 * (j % 6);
        const double d2 = (r - half) * (r - half) + (c - half + shift) * (c - half + shift);
        alpha[r * patchSize + c] =
            static_cast<float>(0.15 + 0.85 * std::exp(-d2 * 8.0 / (patchSize * patchSize)));
      }
    }
    patches.alpha.push_back(alpha);
  }
  s->problem->configure(patches, s->working, 0, options.alphaMask, s->depth);
  s->problem->synthesiseTemplates(s->truth);
  return s;
}

inline std::unique_ptr<SyntheticProblem> makeSyntheticProblem(bool planar, bool alphaMask,
                                                              int patchSize = 11,
                                                              bool smoother = false) {
  SyntheticOptions options;
  options.smoother = smoother;
  options.planar = planar;
  options.alphaMask = alphaMask;
  options.patchSize = patchSize;
  return makeSyntheticProblem(options);
}

}  // namespace clm3d::test
