#include "core/fit/search_problem.hpp"

#include <algorithm>
#include <cmath>

#include "core/common/error.hpp"
#include "core/image/patch_sampling.hpp"

namespace clm3d {

SearchProblem::SearchProblem(const ShapeModel& shape, const Camera& camera)
    : shape_(&shape), projector_(shape, camera) {
  prior_ = Eigen::VectorXd::Zero(projector_.paramCount());
  for (int k = 0; k < shape.modeCount(); ++k) {
    const double variance = shape.variances[k];
    prior_[shapeParam(k)] = variance > 0.0 ? 1.0 / variance : 0.0;
  }
}

void SearchProblem::configure(const PatchModel& patches, const WorkingImage& image, int level,
                              bool alphaMask, double depth) {
  if (level < 0 || level >= static_cast<int>(image.levels.size())) {
    throw Error("fit: pyramid level out of range");
  }
  const bool sameModel = patches_ == &patches && alphaMask_ == alphaMask;
  alphaMask_ = alphaMask;
  patches_ = &patches;
  image_ = &image.levels[static_cast<std::size_t>(level)];
  level_ = level;
  patchSize_ = patches.patchSize;
  projector_.setLandmarks(patches.landmarks);
  projector_.setLevel(image, level);
  projector_.setDepth(depth);

  const int m = landmarkCount();
  const int n = patchPixels();
  if (!sameModel || masks_.cols() != m || masks_.rows() != n) {
    templates_.setZero(n, m);
    synthetic_.setZero(n, m);
    masks_.resize(n, m);
    points_.resize(2, m);
    sample_.resize(n);
    concatenated_.resize(Eigen::Index(n) * m);
    coefficients_.resize(patches.pca.modeCount());
    ncc_.resize(m);
    for (int k = 0; k < m; ++k) {
      if (alphaMask && static_cast<std::size_t>(k) < patches.alpha.size()) {
        masks_.col(k) = patches.alpha[static_cast<std::size_t>(k)];
      } else {
        masks_.col(k).setOnes();
      }
    }
  }
}

void SearchProblem::synthesiseTemplates(const Eigen::Ref<const Eigen::VectorXd>& p) {
  const int m = landmarkCount();
  const int n = patchPixels();
  projector_.project(p, points_);
  // Sample and normalise each patch as training did (unmasked), then project the concatenation
  // into the view's PCA model with the coefficients kept within +-3 SD.
  for (int k = 0; k < m; ++k) {
    auto patch = concatenated_.segment(Eigen::Index(k) * n, n);
    samplePatch(*image_, points_.col(k), patchSize_, patch);
    normalisePatch(patch);
  }
  const PcaModel& pca = patches_->pca;
  concatenated_ -= pca.mean;
  const Eigen::Index modes = textureModeLimit_ > 0
                                 ? std::min<Eigen::Index>(textureModeLimit_, pca.modeCount())
                                 : pca.modeCount();
  auto used = coefficients_.head(modes);
  used.noalias() = pca.components.leftCols(modes).transpose() * concatenated_;
  for (Eigen::Index i = 0; i < modes; ++i) {
    const float limit = 3.0f * std::sqrt(std::max(pca.variances[i], 0.0f));
    used[i] = std::clamp(used[i], -limit, limit);
  }
  concatenated_ = pca.mean;
  concatenated_.noalias() += pca.components.leftCols(modes) * used;
  for (int k = 0; k < m; ++k) {
    synthetic_.col(k) = concatenated_.segment(Eigen::Index(k) * n, n);
    templates_.col(k) = synthetic_.col(k).cwiseProduct(masks_.col(k));
    normalisePatch(templates_.col(k));
  }
  ++templateVersion_;
}

Eigen::Ref<const Eigen::VectorXf> SearchProblem::templ(int k) const {
  return templates_.col(k);
}

Eigen::Ref<const Eigen::VectorXf> SearchProblem::synthetic(int k) const {
  return synthetic_.col(k);
}

Eigen::Ref<const Eigen::VectorXf> SearchProblem::mask(int k) const {
  return masks_.col(k);
}

void SearchProblem::sampleRaw(const Eigen::Vector2d& centre,
                              Eigen::Ref<Eigen::VectorXf> out) const {
  samplePatch(*image_, centre, patchSize_, out);
}

void SearchProblem::sampleMasked(int k, const Eigen::Vector2d& centre,
                                 Eigen::Ref<Eigen::VectorXf> out) const {
  // Normalise before masking, as the templates are: they mask the reconstruction of normalised
  // patches. Masking raw intensities would add the mask's own shape times the patch mean.
  samplePatch(*image_, centre, patchSize_, out);
  normalisePatch(out);
  out.array() *= masks_.col(k).array();
  normalisePatch(out);
}

double SearchProblem::landmarkNcc(const Eigen::Ref<const Eigen::VectorXd>& p,
                                  Eigen::Ref<Eigen::VectorXd> out) const {
  const int m = landmarkCount();
  if (m == 0) return 0.0;
  projector_.project(p, points_);
  const double inverse = 1.0 / patchPixels();
  double sum = 0.0;
  for (int k = 0; k < m; ++k) {
    sampleMasked(k, points_.col(k), sample_);
    out[k] = static_cast<double>(sample_.dot(templates_.col(k))) * inverse;
    sum += out[k];
  }
  return sum / m;
}

double SearchProblem::meanNcc(const Eigen::Ref<const Eigen::VectorXd>& p) const {
  return landmarkNcc(p, ncc_);
}

}  // namespace clm3d
