// The settings of a training run (views, scales, patch size, samples, perturbations, PCA
// variances, mirroring, seed, threads): one struct the CLI fills, the trainer reads and the model
// file keeps as JSON, so every trained model records how it was made.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/dataset/augmentation_settings.hpp"
#include "core/model/shape_model.hpp"

namespace clm3d {

// Random perturbations of each training render around its view centre (uniform in +-range).
struct PerturbationSettings {
  double rotationDeg = 5.0;  // pitch, yaw and roll jitter
  // Pitch and yaw jitter widened to this share of half the distance to the nearest other view
  // centre (never below rotationDeg), so that each view's patches have seen the whole range of
  // poses the search will use the view for; 0 keeps +-rotationDeg.
  double viewCoverage = 1.0;
  double scale = 0.05;          // relative face size jitter
  double shiftPixels = 0.5;     // sub-pixel shift of the face at the finest scale
  double lightDirection = 0.3;  // jitter of each component of the light direction
  double ambient = 0.1;         // jitter of the ambient term (default 0.45)
  double diffuse = 0.15;        // jitter of the diffuse term (default 0.65)
};

struct ViewCentre {
  double pitchDeg = 0;
  double yawDeg = 0;
};

struct TrainSettings {
  std::vector<double> yawsDeg{-60, -30, 0, 30, 60};
  std::vector<double> pitchesDeg{-30, 0, 30};
  int scales = 3;            // pyramid scales per view, 0 = finest
  int patchSize = 20;        // pixels, at every scale
  double patchRatio = 0.24;  // patchSize / inter-ocular distance at the finest scale
  int samplesPerView = 5;    // perturbed renders per subject and view
  PerturbationSettings perturbation;
  double textureVariance = 0.95;  // variance kept by each view/scale patch PCA
  // > 0: at most this many texture modes per patch PCA; 0 = as many as textureVariance keeps. 16
  // by default: the real-face model (resources/datasets/real.json) is about 18.6 MB instead of
  // 142 MB, where photos give the frontal view 300-400 modes (docs/training.md).
  int textureMaxModes = 16;
  ShapeModelSettings shape;      // the shape model (dims forced to 2 for singleView)
  bool mirrorRightViews = true;  // build yaw > 0 views by mirroring yaw < 0 ones
  bool singleView = false;       // the 2D baseline: one frontal view, 2D shape model
  double hiddenShare = 0.5;      // hidden in more than this share of samples -> left out
  // Discriminative patch experts (core/train/detail/expert_training.hpp): trained from
  // displacements of up to this many pixels at every scale; 0 trains none (a model for the template
  // optimisers).
  int expertRadius = 6;
  double expertRidge = 0.1;  // ridge weight of the experts' regression
  // Units per expert: 1 a linear filter with a logistic output, more a neural field
  // (core/model/patch_expert.hpp).
  int expertUnits = 1;
  // Perturbed placements of each training photo beside its exact one (scale, roll and shift
  // drawn within `perturbation`'s ranges, as the renders'). Off by default: 2 tripled the photo
  // samples and the training time and left the error on 100 held-out LFPW training photos where it
  // was (0.0578 against 0.0583 from a 5-point start).
  int photoJitter = 0;
  // The point refiner trained from the photos (core/train/refiner_training.hpp): its stages (0 =
  // none) and the perturbed starts per photo and side it learns from. 20 starts against 10, on
  // 100 LFPW training photos held out of the model, with clm3d fit's defaults: from the detector
  // 0.0456 -> 0.0449 (seed 2: 0.0470 -> 0.0458), from the truth's 5 points 0.0452 -> 0.0451
  // (0.0451 -> 0.0447), for 28 s more training on 705 photos (docs/real-faces.md).
  int refinerStages = 5;
  int refinerStarts = 20;
  // Calibrate each view's search confidence on held-out photos (core/train/view_calibration.hpp;
  // ViewModel::calibration), for `--view-search`. Off by default, as that search is:
  // it made fits on turned LFPW photos worse (docs/fitting.md#views-on-one-scale). Cheap: 8 s
  // more of a 207 s training from the real-faces dataset.
  bool calibrateViews = false;
  int supersample = 2;  // renderer anti-aliasing
  // Appearance augmentation of the renders (docs/training.md); trainFromManifest takes it from
  // the manifest unless augmentationFromManifest is false (clm3d train --no-augmentation).
  AugmentationSettings augmentation;
  bool augmentationFromManifest = true;  // not stored: the stored `augmentation` says what was used
  std::uint64_t seed = 1;
  int threads = 0;  // 0 = one per core (not stored: the model does not depend on it)

  // Throws InputError naming the setting that is out of range.
  void validate() const;
  // The views of the model, pitch-major (pitch ascending, then yaw ascending); one frontal view
  // for singleView.
  std::vector<ViewCentre> views() const;
  // Inter-ocular distance in pixels at the finest scale: patchSize / patchRatio.
  double interOcularPixels() const { return patchSize / patchRatio; }
  // Side of the square training renders (pixels): the face and the coarsest patches fit.
  int renderSize() const;
  // Everything that determines the model, as a JSON object.
  std::string toJson() const;
};

}  // namespace clm3d
