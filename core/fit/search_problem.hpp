// One step of the search (thesis figure 3.16) as a problem the optimisers solve: one view's
// texture model at one pyramid scale, with the synthetic templates fixed. The fitter calls
// synthesiseTemplates at the current parameters (sample the image's patches, project them into
// the view's PCA model, reconstruct, apply the alpha masks), then lets an optimiser move the
// parameters to maximise the match between those templates and the image. Nothing allocates
// after configure(): the optimisers call these in their inner loops.
//
// Conventions shared by every optimiser:
// - Patches are patchSize x patchSize, row-major, sampled bilinearly at the projected landmark
//   (core/image samplePatch), so a landmark at pixel x has sample (r, c) at
//   x + (c - (n-1)/2, r - (n-1)/2).
// - A masked, normalised patch is normalisePatch(alpha .* normalisePatch(patch)), the chain the
//   templates are built with (they mask a reconstruction of normalised patches): zero mean, unit
//   (population) variance; the NCC of two such patches is their dot product divided by patchSize^2,
//   in [-1, 1].
// - The objective is the mean NCC over the active landmarks (those of the view's model).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <vector>

#include "core/fit/shape_projector.hpp"
#include "core/fit/working_image.hpp"
#include "core/model/shape_model.hpp"
#include "core/model/texture_model.hpp"

namespace clm3d {

class SearchProblem {
 public:
  SearchProblem(const ShapeModel& shape, const Camera& camera);

  // The view's patch model at `level` of `image`. alphaMask false: masks of ones (the experiment
  // without background masking).
  void configure(const PatchModel& patches, const WorkingImage& image, int level, bool alphaMask,
                 double depth);
  // Synthesise with at most this many texture modes (0 = all of the model's). Fewer modes keep
  // the templates closer to a typical face, so a misplaced patch is not reproduced as it is.
  void setTextureModeLimit(int modes) { textureModeLimit_ = modes; }
  // Samples the image at p, projects into the PCA model (coefficients clamped to +-3 SD),
  // reconstructs and masks: the templates the optimisers match against until the next call.
  void synthesiseTemplates(const Eigen::Ref<const Eigen::VectorXd>& p);
  // Increments with every synthesiseTemplates, so optimisers can cache per-template work.
  std::uint64_t templateVersion() const { return templateVersion_; }

  int paramCount() const { return projector_.paramCount(); }
  int landmarkCount() const { return projector_.landmarkCount(); }
  int patchSize() const { return patchSize_; }
  int patchPixels() const { return patchSize_ * patchSize_; }
  const ShapeProjector& projector() const { return projector_; }
  const cv::Mat& image() const { return *image_; }  // the level's grey image, CV_32F
  const PatchModel& patchModel() const { return *patches_; }  // the configured view and scale
  int level() const { return level_; }

  // Masked, normalised template of active landmark k (patchPixels() values).
  Eigen::Ref<const Eigen::VectorXf> templ(int k) const;
  // The unmasked template in the model's normalised units (for drawing).
  Eigen::Ref<const Eigen::VectorXf> synthetic(int k) const;
  // Alpha mask of active landmark k (ones when masking is off).
  Eigen::Ref<const Eigen::VectorXf> mask(int k) const;
  // The masked, normalised image patch of landmark k centred at `centre` (level pixels) into
  // out (patchPixels() values): normalised, masked, normalised again. sampleRaw: the raw
  // bilinear samples, neither masked nor normalised.
  void sampleMasked(int k, const Eigen::Vector2d& centre, Eigen::Ref<Eigen::VectorXf> out) const;
  void sampleRaw(const Eigen::Vector2d& centre, Eigen::Ref<Eigen::VectorXf> out) const;

  // NCC of each active landmark at p into out (landmarkCount() values); returns their mean.
  double landmarkNcc(const Eigen::Ref<const Eigen::VectorXd>& p,
                     Eigen::Ref<Eigen::VectorXd> out) const;
  // The objective: mean NCC of the active landmarks at p.
  double meanNcc(const Eigen::Ref<const Eigen::VectorXd>& p) const;

  // Shape-prior weights per parameter: 0 for pose, 1 / variance for shape coefficients (in the
  // units of p). Gauss-Newton style updates may add lambda * diag(prior) to their Hessian.
  const Eigen::VectorXd& prior() const { return prior_; }
  void clamp(Eigen::Ref<Eigen::VectorXd> p) const { projector_.clamp(p); }

 private:
  const ShapeModel* shape_;
  ShapeProjector projector_;
  const PatchModel* patches_ = nullptr;
  const cv::Mat* image_ = nullptr;
  int level_ = 0;
  int patchSize_ = 0;
  std::uint64_t templateVersion_ = 0;
  bool alphaMask_ = true;
  int textureModeLimit_ = 0;
  Eigen::MatrixXf templates_;  // patchPixels x m, masked and normalised
  Eigen::MatrixXf synthetic_;  // patchPixels x m, unmasked
  Eigen::MatrixXf masks_;      // patchPixels x m
  Eigen::VectorXd prior_;
  // Scratch (mutable: the const queries reuse it instead of allocating).
  mutable Eigen::Matrix2Xd points_;
  mutable Eigen::VectorXf sample_;
  mutable Eigen::VectorXf concatenated_;
  mutable Eigen::VectorXf coefficients_;
  mutable Eigen::VectorXd ncc_;
};

}  // namespace clm3d
