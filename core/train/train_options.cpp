#include "core/train/train_options.hpp"

#include <cstdint>
#include <limits>
#include <string>

namespace clm3d {
namespace {

using S = TrainSettings;

OptionSpec spec(std::string name, std::string label, std::string group, std::string help,
                double minimum = 0.0, double maximum = 0.0, int decimals = 2) {
  return {std::move(name),  std::move(label), std::move(group),
          OptionKind::Real, std::move(help),  minimum,
          maximum,          decimals,         {}};
}

std::vector<TrainOption> buildOptions() {
  std::vector<TrainOption> o;
  const std::string views = "Views";
  o.push_back(realListOption<S>(
      spec("views-yaw", "Yaws (deg)", views,
           "yaw centres of the views in degrees (left/right head turn), separated by commas; each "
           "pitch x yaw pair is one view of the model",
           -90, 90),
      [](S& s) -> std::vector<double>& { return s.yawsDeg; }));
  o.push_back(realListOption<S>(
      spec("views-pitch", "Pitches (deg)", views,
           "pitch centres of the views in degrees (head up/down), separated by commas", -60, 60),
      [](S& s) -> std::vector<double>& { return s.pitchesDeg; }));
  o.push_back(flagOption<S>(
      spec("single-view", "Single-view 2D baseline", views,
           "train the single-view 2D baseline instead: one frontal view and a 2D shape model (the "
           "view lists are then ignored)"),
      [](S& s) -> bool& { return s.singleView; }));
  o.push_back(flagOption<S>(
      spec("no-mirror", "Render right-side views", views,
           "render the views with yaw > 0 instead of building them by mirroring the yaw < 0 ones "
           "(twice the rendering)"),
      [](S& s) -> bool& { return s.mirrorRightViews; }, true));

  const std::string patches = "Patches";
  o.push_back(integerOption<S>(
      spec("scales", "Scales", patches,
           "pyramid scales per view: scale s samples the image at 1/2^s; coarse scales widen the "
           "search, the finest gives the accuracy",
           1, 5),
      [](S& s) -> int& { return s.scales; }));
  o.push_back(integerOption<S>(
      spec("patch-size", "Patch size (px)", patches,
           "side of the square patch around each landmark in pixels, at every scale; larger "
           "patches see more context and train slower",
           4, 64),
      [](S& s) -> int& { return s.patchSize; }));
  o.push_back(realOption<S>(
      spec("patch-ratio", "Patch / eye distance", patches,
           "patch size / inter-ocular distance at the finest scale: fixes how large the face is "
           "rendered (a smaller ratio: a larger face and finer detail)",
           0.05, 1.0, 3),
      [](S& s) -> double& { return s.patchRatio; }));
  o.push_back(integerOption<S>(
      spec("samples", "Samples per view", patches,
           "perturbed renders per subject and view; more give the patch PCA more variation and "
           "take longer",
           1, 100),
      [](S& s) -> int& { return s.samplesPerView; }));
  o.push_back(realOption<S>(
      spec("hidden-share", "Hidden share", patches,
           "a landmark hidden in more than this share of a view's renders is left out of the view "
           "(1 = keep every landmark: hidden-point removal off)",
           0.0, 1.0),
      [](S& s) -> double& { return s.hiddenShare; }));
  o.push_back(integerOption<S>(
      spec("supersample", "Supersampling", patches,
           "anti-aliasing of the training renders: each pixel is the mean of n x n samples", 1, 4),
      [](S& s) -> int& { return s.supersample; }));

  const std::string experts = "Experts";
  o.push_back(integerOption<S>(
      spec("expert-radius", "Expert radius (px)", experts,
           "train a discriminative patch expert per landmark, view and scale from displacements "
           "of up to this many pixels (0 = none: a model for the template optimisers only; rlms "
           "needs experts)",
           0, 16),
      [](S& s) -> int& { return s.expertRadius; }));
  o.push_back(realOption<S>(
      spec("expert-ridge", "Expert ridge", experts,
           "ridge weight of the experts' regression, relative to the data's mean variance", 1e-4,
           100.0, 4),
      [](S& s) -> double& { return s.expertRidge; }));
  o.push_back(integerOption<S>(
      spec("expert-units", "Expert units", experts,
           "units of each patch expert: 1 = a linear filter with a logistic output, more = a small "
           "neural field (the units' sigmoid responses summed; slower to train and to search)",
           1, 16),
      [](S& s) -> int& { return s.expertUnits; }));
  o.push_back(integerOption<S>(
      spec("photo-jitter", "Photo jitter", experts,
           "perturbed placements (scale, roll, shift) of each training photo beside its exact one",
           0, 20),
      [](S& s) -> int& { return s.photoJitter; }));
  o.push_back(integerOption<S>(
      spec("refiner-stages", "Refiner stages", experts,
           "stages of the point refiner learnt from the annotated photos (a cascade of regressions "
           "from the image around the fitted points to their corrections); 0 = none",
           0, 8),
      [](S& s) -> int& { return s.refinerStages; }));
  o.push_back(integerOption<S>(
      spec("refiner-starts", "Refiner starts", experts,
           "perturbed starts per photo (and per mirrored photo) the refiner learns from", 1, 50),
      [](S& s) -> int& { return s.refinerStarts; }));
  o.push_back(flagOption<S>(
      spec("calibrate-views", "Calibrate the views", experts,
           "with photos: calibrate each view's search confidence into the probability that a fit "
           "is right, on photos the experts did not learn from (for --view-search)"),
      [](S& s) -> bool& { return s.calibrateViews; }));

  const std::string pca = "Variance kept";
  o.push_back(realOption<S>(
      spec("texture-variance", "Texture variance", pca,
           "share of the variance each view/scale patch PCA keeps; higher keeps more texture modes",
           0.01, 1.0, 3),
      [](S& s) -> double& { return s.textureVariance; }));
  o.push_back(integerOption<S>(
      spec("texture-max-modes", "Texture max modes", pca,
           "at most this many modes per patch PCA (0 = no cap: a model trained with photos grows "
           "several times larger); a cap makes smaller, faster models",
           0, 1000),
      [](S& s) -> int& { return s.textureMaxModes; }));
  o.push_back(realOption<S>(spec("shape-variance", "Shape variance", pca,
                                 "share of the shape variance the shape PCA keeps", 0.01, 1.0, 3),
                            [](S& s) -> double& { return s.shape.varianceKept; }));
  o.push_back(integerOption<S>(spec("shape-max-modes", "Shape max modes", pca,
                                    "at most this many shape modes (0 = no cap)", 0, 1000),
                               [](S& s) -> int& { return s.shape.maxModes; }));
  o.push_back(realOption<S>(
      spec("shape-limit", "Shape limit (SD)", pca,
           "the fitter keeps each shape parameter within this many standard deviations", 0.5, 10.0,
           1),
      [](S& s) -> double& { return s.shape.limitSd; }));
  o.push_back(flagOption<S>(
      spec("mirror-shapes", "Mirror training shapes", pca,
           "add a left/right mirrored copy of every training shape to the shape model"),
      [](S& s) -> bool& { return s.shape.mirror; }));

  const std::string jitter = "Perturbations (+-range)";
  o.push_back(realOption<S>(
      spec("rotation-jitter", "Rotation (deg)", jitter,
           "pitch, yaw and roll jitter of each render around its view centre, in degrees", 0.0,
           20.0, 1),
      [](S& s) -> double& { return s.perturbation.rotationDeg; }));
  o.push_back(realOption<S>(
      spec("view-coverage", "View coverage", jitter,
           "share of half the distance to the nearest other view centre that the pitch/yaw jitter "
           "of each view's renders covers (never below the rotation jitter), so each view's "
           "patches cover the poses the search uses the view for (0 = the rotation jitter only)",
           0.0, 1.5),
      [](S& s) -> double& { return s.perturbation.viewCoverage; }));
  o.push_back(realOption<S>(spec("scale-jitter", "Scale", jitter,
                                 "relative face size jitter (0.05 = +-5 %)", 0.0, 0.3, 3),
                            [](S& s) -> double& { return s.perturbation.scale; }));
  o.push_back(
      realOption<S>(spec("shift-jitter", "Shift (px)", jitter,
                         "sub-pixel shift of the face at the finest scale, in pixels", 0.0, 4.0),
                    [](S& s) -> double& { return s.perturbation.shiftPixels; }));
  o.push_back(realOption<S>(spec("light-jitter", "Light direction", jitter,
                                 "jitter of each component of the light direction", 0.0, 1.0),
                            [](S& s) -> double& { return s.perturbation.lightDirection; }));
  o.push_back(realOption<S>(spec("ambient-jitter", "Ambient", jitter,
                                 "jitter of the ambient light term (the term is 0.45)", 0.0, 0.4),
                            [](S& s) -> double& { return s.perturbation.ambient; }));
  o.push_back(realOption<S>(spec("diffuse-jitter", "Diffuse", jitter,
                                 "jitter of the diffuse light term (the term is 0.65)", 0.0, 0.6),
                            [](S& s) -> double& { return s.perturbation.diffuse; }));

  const std::string run = "Run";
  o.push_back(flagOption<S>(
      spec("no-augmentation", "No augmentation", run,
           "switch off all appearance augmentation for this run, the default cluttered background "
           "included: renders on flat black (the manifest's augmentation is ignored)"),
      [](S& s) -> bool& { return s.augmentationFromManifest; }, true));
  o.push_back(integerOption<S>(
      spec("seed", "Seed", run,
           "random seed of the perturbations and shape samples: the same seed and data give the "
           "same model",
           0, std::numeric_limits<std::int32_t>::max()),
      [](S& s) -> std::uint64_t& { return s.seed; }));
  o.push_back(integerOption<S>(
      spec("threads", "Threads", run,
           "worker threads for loading and rendering (0 = one per core; the studio leaves one "
           "core free). The model does not depend on it",
           0, 64),
      [](S& s) -> int& { return s.threads; }));
  for (TrainOption& option : o) option.commands = only(OptionCommand::Train);  // and its form
  return o;
}

}  // namespace

const std::vector<TrainOption>& trainOptions() {
  static const std::vector<TrainOption> options = buildOptions();
  return options;
}

const TrainOption* findTrainOption(std::string_view name) {
  return findOption(trainOptions(), name);
}

}  // namespace clm3d
