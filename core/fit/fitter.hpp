// The CLM search (thesis figure 3.16): from a starting pose and shape, coarse to fine over the
// model's pyramid scales, repeatedly choose the view, synthesise the templates from the image and
// let the chosen optimiser update pose and shape, until the points stop moving. One Fitter per
// thread; it keeps its buffers between frames so that tracking allocates nothing per iteration.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <limits>
#include <memory>
#include <opencv2/core/mat.hpp>
#include <string>
#include <utility>
#include <vector>

#include "core/fit/fit_probability.hpp"
#include "core/fit/fit_state.hpp"
#include "core/fit/optimiser.hpp"
#include "core/fit/search_problem.hpp"
#include "core/fit/view_selector.hpp"
#include "core/fit/working_image.hpp"
#include "core/geometry/camera.hpp"
#include "core/model/clm_model.hpp"

namespace clm3d {

struct FitSettings {
  std::string optimiser{kAutoOptimiser};  // a name of optimiserChoices(); the Fitter resolves it
  OptimiserSettings optimiserSettings;
  int scales = 0;                // pyramid scales searched, finest n; 0 = all of the model's
  int maxIterations = 4;         // per scale (the thesis used at most 4)
  double tolerancePixels = 0.1;  // converged when no point moves more (level pixels)
  bool alphaMask = true;         // alpha masking of template and image patches
  int textureModes = 0;          // texture modes used to synthesise the templates (0 = all)
  double viewHysteresisDeg = 5.0;

  void validate(const ClmModel& model) const;  // InputError naming the bad setting

  bool operator==(const FitSettings&) const = default;
};

// Where a search read the image: the box of the input image it cut (input pixels), the scale it
// brought that box to and the depth it configured the patches for. Fitter::templates makes the
// same working image again from it, so a result can be drawn without the search's state.
struct SearchRegion {
  Eigen::Vector2d low{0.0, 0.0};
  Eigen::Vector2d high{0.0, 0.0};
  double scale = 0.0;  // 0: no search made this result
  double depth = 0.0;
};

// A fit's synthetic templates at its final estimate and finest scale, unmasked: per landmark of
// its view (in `modelled` order), patchSize^2 values each in the model's normalised units, and the
// size of one template pixel in input pixels (for drawing).
struct FitTemplates {
  std::vector<Eigen::VectorXf> values;
  double pixelSize = 1.0;
};

struct FitResult {
  FitState state;
  Eigen::Matrix2Xd points;     // every scheme landmark, input pixels
  std::vector<bool> modelled;  // landmarks the final view's model holds (the others are hidden)
  int view = -1;
  // The search's own score at its final points, finest scale: for the template optimisers the
  // mean NCC, in [-1, 1]; for rlms the experts' mean response, in (0, 1). On its optimiser's scale
  // (and for rlms its view's): fits are judged and compared by `probability`.
  double searchScore = 0.0;
  // The probability that the fit's points are right, in [0, 1], on one scale for every optimiser
  // and view (core/fit/fit_probability.hpp): the Fitter sets it from searchScore, refineFit
  // (core/refine/refined_fit.hpp) replaces it by the point refiner's check of the refined points.
  double probability = 0.0;
  ProbabilitySource probabilitySource = ProbabilitySource::BuiltInNccCurve;
  // The search's score per scheme landmark (the NCC of its patch, or its expert's response); NaN
  // for the landmarks the final view does not model. Their mean over the modelled ones is
  // `searchScore`.
  std::vector<double> landmarkConfidence;
  // The final view's own check (ViewModel::check) of the search's points, set by refineFit; NaN
  // when the view has none.
  double viewProbability = std::numeric_limits<double>::quiet_NaN();
  bool refined = false;    // the model's point refiner moved the points (refineFit)
  bool converged = false;  // the finest scale met the tolerance within maxIterations
  int iterations = 0;      // over all scales
  SearchRegion region;     // where the search read the image (Fitter::templates)
};

class Fitter {
 public:
  // camera: the camera of the input images (its size must match them). Throws InputError for
  // settings the model cannot honour.
  Fitter(const ClmModel& model, const Camera& camera, const FitSettings& settings = {});
  ~Fitter();
  Fitter(const Fitter&) = delete;
  Fitter& operator=(const Fitter&) = delete;

  // Searches `image` (CV_8UC1/3/4, or CV_32FC1 grey in [0, 1]) from `start`. `currentView` is the
  // view used so far (tracking), -1 for none. Throws InputError for an image of the wrong size.
  FitResult fit(const cv::Mat& image, const FitState& start, int currentView = -1);

  // Points of every landmark at `state` in input pixels.
  Eigen::Matrix2Xd project(const FitState& state) const;
  // The templates of `fit` (a result of a search of `image` by a fitter of this model, camera and
  // settings), made from the image again where that search read it: the overlay's patches. Only
  // the overlay needs them (rlms's confidence does not), so a search does not make them. Empty for
  // a result no search made (its region's scale 0) or without a view. InputError for an image of
  // the wrong size. Reuses the fitter's buffers, as a search does.
  FitTemplates templates(const cv::Mat& image, const FitResult& fit);

  const ClmModel& model() const { return *model_; }
  const Camera& camera() const { return camera_; }
  const FitSettings& settings() const { return settings_; }
  // A fresh FitState at the mean shape with the given pose.
  FitState meanState(const Pose& pose) const;

 private:
  void checkImageSize(const cv::Mat& image) const;  // InputError unless the camera's size
  const ClmModel* model_;
  Camera camera_;
  FitSettings settings_;
  int scales_ = 1;
  ViewSelector selector_;
  std::unique_ptr<Optimiser> optimiser_;
  SearchProblem problem_;
  WorkingImage working_;
  std::pair<int, int> eyes_;        // the scheme's normalisation pair
  double targetInterOcular_ = 0.0;  // pixels at the finest scale, as in training
};

}  // namespace clm3d
