// The texture (patch) models of the multi-view CLM (thesis section 3.3): for each view (a range of
// head pitch/yaw) and pyramid scale, a PCA model of the concatenated, normalised greyscale patches
// around the landmarks visible from that view, plus each landmark's mean alpha patch (face versus
// background) that masks patches before comparison. normalisePatch is the one normalisation the
// trainer and the fitter share.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "core/common/logistic_curve.hpp"
#include "core/model/patch_expert.hpp"
#include "core/model/pca.hpp"
#include "core/model/view_check.hpp"
#include "core/scheme/scheme.hpp"

namespace clm3d {

struct PatchModel {                    // one view at one scale
  int patchSize = 20;                  // square patches, greyscale, row-major
  std::vector<int> landmarks;          // the visible landmarks of the view, ascending
  PcaModel pca;                        // D = landmarks.size() * patchSize^2
  std::vector<Eigen::VectorXf> alpha;  // per entry of `landmarks`: mean alpha patch, in [0, 1]
  // Per entry of `landmarks`: the discriminative expert (empty vector: a model without experts,
  // as every model before format version 2; only the template optimisers can use it).
  std::vector<PatchExpert> experts;

  int patchPixels() const { return patchSize * patchSize; }
  // The slice of a concatenated vector (pca.mean, a component, a sample) for landmarks[entry].
  Eigen::Index offsetOf(int entry) const { return Eigen::Index(entry) * patchPixels(); }
  // Index into `landmarks` of scheme landmark i, -1 if this model does not hold it.
  int entryOf(int landmark) const;
  bool hasExperts() const { return !experts.empty(); }
};

struct ViewModel {
  double pitchDeg = 0;  // view centre
  double yawDeg = 0;
  std::vector<bool> visible;       // per scheme landmark: visible in >= 50% of the view's samples
  std::vector<PatchModel> scales;  // index 0 = finest; scale s samples at 1/2^s resolution
  bool mirrored = false;           // built by mirroring the opposite-yaw view
  // The probability that a search which ends in this view is right, from its confidence (the
  // patch experts' mean response, rlms): fitted at training on faces the experts did not learn
  // from (core/train/view_calibration.hpp), so that fits in different views compare on one scale.
  // Absent in models trained without photos and in files before format 7.
  std::optional<LogisticCurve> calibration;
  // Whether the model's point refiner learnt from faces in this view (format 7; before, every
  // view): where it did not (profiles, for a refiner learnt from near-frontal photos), a fit's
  // points are left as the search gives them and it is judged on the view's calibration.
  bool refined = true;
  // The view's own check of a search's points (format 8; empty before, and where training had too
  // few faces in the view): core/model/view_check.hpp.
  ViewCheck check;
};

// Zero mean, unit variance (population) in place; a constant (or empty) patch becomes zeros.
void normalisePatch(Eigen::Ref<Eigen::VectorXf> patch);

// Flips a row-major size x size patch left-right.
Eigen::VectorXf flipPatch(const Eigen::Ref<const Eigen::VectorXf>& patch, int size);

// The view at -yaw: landmarks swapped by scheme.mirrorOf, each patch (mean, components, alpha)
// flipped left-right, visibility swapped, entries re-sorted so `landmarks` stays ascending;
// `mirrored` is toggled. Mirroring twice gives the original. Throws Error if the view does not
// match the scheme.
ViewModel mirrorView(const ViewModel& source, const Scheme& scheme);

}  // namespace clm3d
