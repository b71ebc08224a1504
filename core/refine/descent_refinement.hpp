// Supervised descent refinement of a fit's 2D points (after the search of the 3D model has placed
// them): applying and training the cascade of core/model/descent_refiner.hpp, each stage
// predicting the points' corrections from the gradient-orientation features around them
// (detail/descent_features.hpp). Trained on annotated photos from perturbed starts, it learns what
// real faces look like around each point, where the patch experts of one view and scale see too
// little (docs/real-faces.md). A model trained with photos carries one (ClmModel::refiner); the fit
// of a still image applies it unless asked not to.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <limits>
#include <opencv2/core/mat.hpp>
#include <vector>

#include "core/common/progress.hpp"
#include "core/model/descent_refiner.hpp"
#include "core/refine/training_starts.hpp"

namespace clm3d {

// A face's part of an image in grey (CV_32FC1), scaled so that the eye distance of the points it
// was cut around is kDescentEyeDistance pixels: the features then sample a prefiltered image at
// any face size. region = scale * (image - offset).
struct DescentRegion {
  cv::Mat grey;
  double scale = 1.0;
  Eigen::Vector2d offset = Eigen::Vector2d::Zero();

  Eigen::Matrix2Xd toRegion(const Eigen::Matrix2Xd& image) const;
  Eigen::Matrix2Xd toImage(const Eigen::Matrix2Xd& region) const;
};
inline constexpr double kDescentEyeDistance = 40.0;

// The part of `image` (CV_8UC1/3/4 or CV_32FC1) within `margin` pixels of `points`' box (2 x N,
// finite), in grey, scaled by about `scale` (the exact factor in the result). InputError for an
// empty image or an unsupported type. The refiner's regions and the views' checks cut by it.
DescentRegion greyRegion(const cv::Mat& image, const Eigen::Matrix2Xd& points, double margin,
                         double scale);

// The region of `image` (CV_8UC1/3/4 or CV_32FC1) around `points` (2 x N, finite) whose columns
// leftEye and rightEye are the eye centres. InputError for an empty image or coinciding eyes.
DescentRegion descentRegion(const cv::Mat& image, const Eigen::Matrix2Xd& points, int leftEye,
                            int rightEye);

struct RefinedPoints {
  Eigen::Matrix2Xd points;  // every scheme landmark (2 x L, image pixels)
  // The refiner's check (core/refine/descent_check.hpp): the probability that the refined points
  // are right. NaN when the refiner has no check, was not asked to check or did not refine.
  double rightProbability = std::numeric_limits<double>::quiet_NaN();
};

// Refining from several starts and averaging (test-time averaging): the cascade also runs from
// `extra` copies of the start, each moved `spread` eye distances in one of `extra` evenly spaced
// directions (the first to the right, turning from x towards y) and scaled about the points'
// centroid by 1 + spread (even copies) or 1 - spread (odd ones); the refined points are the mean
// of all the runs. The linear stages' errors from nearby starts partly cancel: on 100 LFPW
// training photos held out of the model, refining every search's fit from 8 extra starts took the
// mean error from 0.0458 to 0.0452 from the detector and from 0.0455 to 0.0452 from the truth's 5
// points (docs/fitting.md), for about 1 ms per start. extra 0 = the start alone.
struct RefinerStarts {
  int extra = 0;
  double spread = 0.04;
};

// Every scheme landmark of `points` with the refiner's points moved by every stage (from the
// starts of `starts`, averaged) and, when `check` is set and the refiner has one, checked; `image`
// as descentRegion takes it. The points are returned unchanged when the refiner is empty or one of
// its points is not finite.
RefinedPoints refineAndCheck(const DescentRefiner& refiner, const cv::Mat& image,
                             const Eigen::Matrix2Xd& points, bool check = true,
                             const RefinerStarts& starts = {});
inline Eigen::Matrix2Xd refinePoints(const DescentRefiner& refiner, const cv::Mat& image,
                                     const Eigen::Matrix2Xd& points) {
  return refineAndCheck(refiner, image, points, false).points;
}
// The refiner's points only (2 x N, region pixels) after every stage, from `start`.
Eigen::Matrix2Xd refineInRegion(const DescentRefiner& refiner, const cv::Mat& regionGrey,
                                const Eigen::Matrix2Xd& start);
// The mean of refineInRegion from `start` and from the moved copies of `starts`.
Eigen::Matrix2Xd refineInRegion(const DescentRefiner& refiner, const cv::Mat& regionGrey,
                                const Eigen::Matrix2Xd& start, const RefinerStarts& starts);

// One annotated face to train from: its region and true points (2 x N, region pixels).
struct DescentPhoto {
  DescentRegion region;
  Eigen::Matrix2Xd truth;
};

// The stages' feature windows, in eye distances, widest first: `stages` of them, the last `last`
// wide and each `growth` times the next: wide first (a start that is far off), narrower as the
// points close in. Five stages from 1.0 to 0.35 were better than four from 0.8 (0.0504 against
// 0.0526 from the detector on 100 held-out LFPW training photos; from the 5-point start 0.0417
// against 0.0425).
std::vector<double> descentWindows(int stages, double last = 0.35, double growth = 1.3);

// The defaults are those `clm3d train` learns a model's refiner with (core/train/
// refiner_training), the stages from TrainSettings::refinerStages.
struct DescentTrainSettings {
  std::vector<double> windows = descentWindows(5);  // one stage per window
  // Ridge regularisation, as a share of the features' mean variance. 0.2 against 0.05 took the
  // same held-out photos from 0.0425 to 0.0415 (5-point start), 0.0526 to 0.0528 (detector).
  double ridge = 0.2;
  // Starts per photo: the true points moved as a search typically misplaces them.
  int startsPerPhoto = 10;
  StartPerturbation start;
  // Each start's shape is the photo's own moved towards another photo's (aligned by a similarity)
  // by a share drawn uniformly from [0, otherShape]: a search leaves the shape model's idea of the
  // face, not only a misplaced copy of the true one. 0 = the true shape, moved only. Up to
  // half-way, on 100 held-out LFPW training photos from the detector (rlms): mean 0.0634 ->
  // 0.0603, median 0.0453 -> 0.0410 (1.0: 0.0608, 0.0402); from the 5-point start 0.0479 -> 0.0473
  // (1.0: 0.0480).
  double otherShape = 0.5;
  // Each stage also regresses from the points' departure from the mean shape
  // (DescentStage::shapeWeights), not only from the image.
  bool shapeTerms = true;
  std::uint64_t seed = 1;
  int threads = 0;
};

// Trains the cascade on `photos` (each stage learns from the starts the stages before it moved);
// the result does not depend on the thread count. `landmarks`, `leftEye` and `rightEye` are
// stored as given. InputError when there are no photos; Cancelled when `cancel` fires.
DescentRefiner trainDescentRefiner(const std::vector<DescentPhoto>& photos,
                                   const std::vector<int>& landmarks, int leftEye, int rightEye,
                                   const DescentTrainSettings& settings,
                                   const CancelToken* cancel = nullptr);

// Adapting a trained cascade to the faces of one video (`clm3d adapt`, issue 29): each stage, in
// turn, keeps the general stage and adds what a regression of the general stage's residual on
// these photos learns, from starts drawn as in training and moved by the stages adapted before it.
// The general stage is the prior: it weighs as `prior` photos (the residual's regression has the
// ridge prior / photos in the training ridge's unit, its mean is shrunk by photos / (photos +
// prior)), so a few frames nudge the cascade, and a systematic offset of the video's mark-up from
// the general one (another tool's chin or brow, say) is learnt. The mean shape, the windows and
// the check stay the general refiner's.
struct DescentAdaptSettings {
  double prior = 30.0;  // photos (a frame and its mirror image are two)
  int startsPerPhoto = 10;
  StartPerturbation start;
  double otherShape = 0.5;
  std::uint64_t seed = 1;
  int threads = 0;
};
// `general` adapted to `photos` (their regions and true points, as trainDescentRefiner takes
// them); an empty refiner is returned as it is. Deterministic for a seed whatever the thread
// count. InputError when there are no photos or the prior is not positive; Cancelled on `cancel`.
DescentRefiner adaptDescentRefiner(const DescentRefiner& general,
                                   const std::vector<DescentPhoto>& photos,
                                   const DescentAdaptSettings& settings,
                                   const CancelToken* cancel = nullptr);

// A face to train or adapt a refiner from, and its left-right mirror image: `image` (as
// descentRegion takes it) cut around `truth` (2 x N, the refiner's points in image pixels), and
// flipped with the points swapped by `mirror` (position of each point's mirror image). Empty when
// the image is empty, a point is not finite or the eyes (`leftEye`, `rightEye`) coincide; Error
// when `mirror` does not give a position of the points for each point.
std::vector<DescentPhoto> descentPhotoAndMirror(const cv::Mat& image, const Eigen::Matrix2Xd& truth,
                                                const std::vector<int>& mirror, int leftEye,
                                                int rightEye);

}  // namespace clm3d
