// The point refiner in the fit of still images: trained by the trainer's photo path
// (trainPhotoRefiner) from renders of the fixture's procedural heads saved as annotated photos, it
// refines every landmark they all mark, brings starts moved off a held-out head closer to its
// truth, and ImageFitter and the Tracker apply it to the search's points unless told not to (not
// to the state the next frame starts from). Its check, learnt from the same photos, gives a fit's
// confidence: high on the held-out head, low on points moved off it, and the tracker fails a
// frame that has no face on it.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <complex>
#include <opencv2/core.hpp>
#include <random>

#include "core/detect/initialisation.hpp"
#include "core/detect/start_search.hpp"
#include "core/refine/descent_check.hpp"
#include "core/refine/descent_refinement.hpp"
#include "core/refine/refined_fit.hpp"
#include "core/refine/view_check.hpp"
#include "core/scheme/landmark_file.hpp"
#include "core/track/batch_fit.hpp"
#include "core/track/detail/unrefined_landmarks.hpp"
#include "core/track/tracker.hpp"
#include "core/train/refiner_training.hpp"
#include "core/viz/image_file.hpp"
#include "tests/support/calibrated_fixture.hpp"
#include "tests/support/fit_fixture.hpp"
#include "tests/support/refiner_fixture.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

namespace fs = std::filesystem;
using test::FitScene;
using test::fitTestModel;
using test::kHeldOutHead;
using test::makeFitScene;
using test::meanPointError;

using test::savePhoto;

// A refiner whose output is known by construction, so that tests of who applies it need not call
// the code under test for their expected points: one stage with no image weights and shape
// weights -I, so that it moves the points' normalised shape onto its mean shape, i.e. replaces the
// points with the mean shape placed on them by the least-squares similarity (written out below
// with complex numbers, independent of the project's own alignment); from several starts (shifted
// and scaled copies whose mean is the start) the placements average to the same. Its check scores
// every fit alike: probability 0.8.
constexpr double kKnownCheckProbability = 0.8;
DescentRefiner knownRefiner(const std::vector<int>& without = {}) {
  DescentRefiner refiner;
  const DescentRefiner& trained = test::photoRefiner();
  std::vector<Eigen::Index> kept;
  for (std::size_t i = 0; i < trained.landmarks.size(); ++i) {
    if (std::find(without.begin(), without.end(), trained.landmarks[i]) != without.end()) continue;
    refiner.landmarks.push_back(trained.landmarks[i]);
    kept.push_back(static_cast<Eigen::Index>(i));
  }
  refiner.leftEye = trained.leftEye;
  refiner.rightEye = trained.rightEye;
  refiner.meanShape = trained.meanShape(Eigen::all, kept);
  const auto n = static_cast<Eigen::Index>(refiner.landmarks.size());
  const Eigen::Index d = n * kDescentFeaturesPerPoint;
  DescentStage stage;
  stage.featureMean = Eigen::VectorXf::Zero(d);
  stage.weights = Eigen::MatrixXf::Zero(2 * n, d);
  stage.bias = Eigen::VectorXf::Zero(2 * n);
  stage.shapeWeights = -Eigen::MatrixXf::Identity(2 * n, 2 * n);
  refiner.stages.push_back(stage);
  refiner.check.featureMean = Eigen::VectorXf::Zero(d);
  refiner.check.weights = Eigen::VectorXf::Zero(d);
  refiner.check.offset = std::log(kKnownCheckProbability / (1.0 - kKnownCheckProbability));
  refiner.validate(25);
  return refiner;
}

// What knownRefiner makes of `points`: its mean shape placed on them (every landmark is refined).
Eigen::Matrix2Xd placedMeanShape(const DescentRefiner& refiner, const Eigen::Matrix2Xd& points) {
  Eigen::Matrix2Xd chosen(2, static_cast<Eigen::Index>(refiner.landmarks.size()));
  for (std::size_t i = 0; i < refiner.landmarks.size(); ++i)
    chosen.col(static_cast<Eigen::Index>(i)) = points.col(refiner.landmarks[i]);
  // The similarity z -> a z + b minimising sum |a s_i + b - t_i|^2 over complex points: b moves
  // the centroids together, a = sum conj(s_i - s) (t_i - t) / sum |s_i - s|^2.
  const Eigen::Vector2d sourceMean = refiner.meanShape.rowwise().mean();
  const Eigen::Vector2d targetMean = chosen.rowwise().mean();
  std::complex<double> numerator = 0.0;
  double denominator = 0.0;
  for (Eigen::Index i = 0; i < chosen.cols(); ++i) {
    const Eigen::Vector2d a = refiner.meanShape.col(i) - sourceMean;
    const Eigen::Vector2d b = chosen.col(i) - targetMean;
    numerator += std::conj(std::complex<double>(a.x(), a.y())) * std::complex<double>(b.x(), b.y());
    denominator += a.squaredNorm();
  }
  const std::complex<double> factor = numerator / denominator;
  Eigen::Matrix2Xd placed(2, chosen.cols());
  for (Eigen::Index i = 0; i < chosen.cols(); ++i) {
    const Eigen::Vector2d a = refiner.meanShape.col(i) - sourceMean;
    const std::complex<double> z = factor * std::complex<double>(a.x(), a.y());
    placed.col(i) = targetMean + Eigen::Vector2d(z.real(), z.imag());
  }
  Eigen::Matrix2Xd out = points;
  for (std::size_t i = 0; i < refiner.landmarks.size(); ++i)
    out.col(refiner.landmarks[i]) = placed.col(static_cast<Eigen::Index>(i));
  return out;
}

TEST(ImageFitRefiner, TrainedFromPhotosItBringsStartsCloserOnAHeldOutHead) {
  const DescentRefiner& refiner = test::photoRefiner();
  ASSERT_EQ(refiner.stages.size(), 3u);
  EXPECT_EQ(refiner.landmarks.size(), 25u);  // every point is marked in every photo
  EXPECT_EQ(refiner.landmarks[static_cast<std::size_t>(refiner.leftEye)], 7);
  EXPECT_EQ(refiner.landmarks[static_cast<std::size_t>(refiner.rightEye)], 10);

  std::mt19937_64 random(3);
  std::normal_distribution<double> normal(0.0, 1.0);
  double before = 0.0, after = 0.0;
  for (const double yaw : {-4.0, 3.0, 9.0}) {
    const FitScene scene = makeFitScene(fitTestModel(), 2.0, yaw, kHeldOutHead);
    for (int k = 0; k < 4; ++k) {
      const Eigen::Vector2d shift =
          0.1 * scene.interOcular * Eigen::Vector2d(normal(random), normal(random));
      const Eigen::Matrix2Xd start = scene.truthPoints.colwise() + shift;
      before += meanPointError(start, scene.truthPoints) / scene.interOcular;
      after += meanPointError(refinePoints(refiner, scene.image, start), scene.truthPoints) /
               scene.interOcular;
    }
  }
  EXPECT_LT(after, 0.6 * before) << "before " << before / 12 << ", after " << after / 12;
}

TEST(ImageFitRefiner, ImageFitterAppliesTheModelsRefinerUnlessToldNotTo) {
  ClmModel model = fitTestModel();
  model.refiner = knownRefiner();
  const FitScene scene = makeFitScene(model, 0.0, 4.0, kHeldOutHead);
  const test::TempDir dir;
  savePhoto(dir.path(), "face", scene);  // face.png, and its true points in face.pts: the start

  ImageFitSettings plain;
  plain.refine = false;
  plain.minProbability = 0.0;  // the fixture's experts, uncalibrated: the search's points kept
  ImageFitter unrefined(model, plain);
  const ImageFitOutcome searched = unrefined.fitFile(dir / "face.png", dir / "face.pts");
  ASSERT_EQ(searched.status, ImageFitStatus::Ok) << searched.message;

  // The search's points refined (from the default 9 starts) by the known refiner: its mean shape
  // placed on them.
  ImageFitter refining(model, ImageFitSettings{});
  const ImageFitOutcome refined =
      refining.fitFile(dir / "face.png", dir / "face.pts", dir / "out.pts");
  ASSERT_EQ(refined.status, ImageFitStatus::Ok) << refined.message;
  const Eigen::Matrix2Xd expected = placedMeanShape(model.refiner, searched.fit->points);
  EXPECT_LT((refined.fit->points - expected).cwiseAbs().maxCoeff(), 1e-3);
  EXPECT_GT((refined.fit->points - searched.fit->points).norm(), 1.0);
  EXPECT_NEAR(refined.fit->probability, kKnownCheckProbability, 1e-6);  // the check's
  const LandmarkSet written = readLandmarks(dir / "out.pts", &Scheme::thesis25());
  for (int i = 0; i < 25; ++i)
    EXPECT_LT((written.point(i).head<2>() - expected.col(i)).norm(), 1e-3) << i;
  // From the search's points alone: the same placement.
  ImageFitSettings oneStart;
  oneStart.refineRuns = 1;
  const ImageFitOutcome single =
      ImageFitter(model, oneStart).fitFile(dir / "face.png", dir / "face.pts");
  ASSERT_EQ(single.status, ImageFitStatus::Ok) << single.message;
  EXPECT_LT((single.fit->points - expected).cwiseAbs().maxCoeff(), 1e-3);
}

// With a trained refiner, more starts average to other points than one start does (a linear
// stage from nearby starts is not the same stage from the start alone), and both stay on the face.
// The extra runs are made only for a fit whose check probability is below refineRunsBelow: just
// above the one-run fit's probability they run, at half of it they do not.
TEST(ImageFitRefiner, MoreStartsMoveTheTrainedRefinersPointsOnlyForAFitTheCheckDoubts) {
  ClmModel model = fitTestModel();
  model.refiner = test::photoRefiner();
  const FitScene scene = makeFitScene(model, 0.0, 4.0, kHeldOutHead);
  const test::TempDir dir;
  savePhoto(dir.path(), "face", scene);
  const auto fitWith = [&](int runs, double below) {
    ImageFitSettings settings;
    settings.refineRuns = runs;
    settings.refineRunsBelow = below;
    ImageFitOutcome outcome =
        ImageFitter(model, settings).fitFile(dir / "face.png", dir / "face.pts");
    EXPECT_EQ(outcome.status, ImageFitStatus::Ok) << outcome.message;
    return outcome;
  };
  const ImageFitOutcome single = fitWith(1, 0.0);
  const ImageFitOutcome always = fitWith(9, 0.0);
  ASSERT_TRUE(single.fit && always.fit);
  const double probability = single.fit->probability;
  ASSERT_GT(probability, 0.0);
  ASSERT_LT(probability, 1.0);
  ASSERT_GT((single.fit->points - always.fit->points).cwiseAbs().maxCoeff(), 1e-3);
  for (const ImageFitOutcome* fit : {&single, &always})  // the render: within 0.1 eye distances
    EXPECT_LT(meanPointError(fit->fit->points, scene.truthPoints) / scene.interOcular, 0.1);

  const ImageFitOutcome trusted = fitWith(9, 0.5 * probability);
  ASSERT_TRUE(trusted.fit);
  EXPECT_LT((trusted.fit->points - single.fit->points).cwiseAbs().maxCoeff(), 1e-9);
  const ImageFitOutcome doubted = fitWith(9, std::nextafter(probability, 1.0));
  ASSERT_TRUE(doubted.fit);
  EXPECT_LT((doubted.fit->points - always.fit->points).cwiseAbs().maxCoeff(), 1e-9);
}

TEST(ImageFitRefiner, TheTrackerRefinesATrackedFramesRowUnlessToldNotTo) {
  ClmModel model = fitTestModel();
  model.refiner = knownRefiner();
  const FitScene scene = makeFitScene(model, 0.0, 2.0, kHeldOutHead);
  const auto trackOnce = [&](bool refine) {
    TrackerSettings settings;
    settings.refine = refine;
    // Judged on the search's own confidence (NCC's, which this render passes) when unrefined, on
    // the known check's 0.8 when refined.
    settings.fit.optimiser = "fastncc";
    Tracker tracker(model, scene.camera, settings);
    tracker.setState(scene.truth, -1);
    return tracker.track(scene.image, 0, 0.0);
  };
  const TrackStep plain = trackOnce(false);
  const TrackStep refined = trackOnce(true);
  ASSERT_TRUE(plain.row.success && refined.row.success);
  EXPECT_TRUE(plain.row.points.isApprox(plain.fit->points, 1e-12));
  EXPECT_TRUE(refined.fit->state.pose.translation.isApprox(plain.fit->state.pose.translation));
  EXPECT_LT((refined.row.points - placedMeanShape(model.refiner, plain.fit->points))
                .cwiseAbs()
                .maxCoeff(),
            1e-3);
  EXPECT_GT((refined.row.points - plain.row.points).norm(), 1.0);
}

// With a refiner that leaves the ear lobes out, the tracker's row places them where the shape
// fitted to the refined points puts them (placeUnrefinedLandmarks), not where the search left
// them; the next frame's state is the search's as before.
TEST(ImageFitRefiner, TheTrackersRowOutlineFollowsTheRefinedPoints) {
  constexpr int kLeftLobe = 18, kRightLobe = 24;
  ClmModel model = fitTestModel();
  model.refiner = knownRefiner({kLeftLobe, kRightLobe});
  const FitScene scene = makeFitScene(model, 0.0, 2.0, kHeldOutHead);
  TrackerSettings settings;
  settings.fit.optimiser = "fastncc";
  Tracker tracker(model, scene.camera, settings);
  tracker.setState(scene.truth, -1);
  const TrackStep step = tracker.track(scene.image, 0, 0.0);
  ASSERT_TRUE(step.row.success && step.fit);
  const Eigen::Matrix2Xd searched = projectState(model, scene.camera, step.fit->state);
  FitResult again = *step.fit;
  for (const int lobe : {kLeftLobe, kRightLobe}) again.points.col(lobe) = searched.col(lobe);
  placeUnrefinedLandmarks(model, scene.camera, again);
  for (const int lobe : {kLeftLobe, kRightLobe}) {
    EXPECT_LT((step.row.points.col(lobe) - again.points.col(lobe)).norm(), 1e-9) << lobe;
    EXPECT_GT((step.row.points.col(lobe) - searched.col(lobe)).norm(), 0.5) << lobe;
  }
}

TEST(ImageFitRefiner, TheChecksProbabilityIsTheFitsConfidence) {
  ClmModel model = fitTestModel();
  model.refiner = test::photoRefiner();
  ASSERT_FALSE(model.refiner.check.empty()) << "48 faces learn a check";
  const FitScene scene = makeFitScene(model, 0.0, 4.0, kHeldOutHead);
  const test::TempDir dir;
  savePhoto(dir.path(), "face", scene);  // face.png, and its true points in face.pts: the start

  ImageFitter fitter(model, ImageFitSettings{});
  const ImageFitOutcome right = fitter.fitFile(dir / "face.png", dir / "face.pts");
  ASSERT_EQ(right.status, ImageFitStatus::Ok) << right.message;
  EXPECT_EQ(right.fit->probabilitySource, ProbabilitySource::Check);
  EXPECT_GT(right.fit->probability, 0.5);
  EXPECT_LE(right.fit->probability, 1.0);
  // The probability is the check's (a check of known output: the fit's probability is its 0.8,
  // the search's own score kept as searchScore).
  ClmModel known = model;
  known.refiner = knownRefiner();
  const ImageFitOutcome judged =
      ImageFitter(known, ImageFitSettings{}).fitFile(dir / "face.png", dir / "face.pts");
  ASSERT_EQ(judged.status, ImageFitStatus::Ok) << judged.message;
  EXPECT_NEAR(judged.fit->probability, kKnownCheckProbability, 1e-6);
  EXPECT_TRUE(std::isfinite(judged.fit->searchScore));
  EXPECT_GT(std::abs(judged.fit->searchScore - kKnownCheckProbability), 1e-3);
  // Points moved by most of an eye distance stay wrong after refining, and the check says so.
  for (const Eigen::Vector2d& share : {Eigen::Vector2d(0.7, 0.4), Eigen::Vector2d(-0.6, -0.6)}) {
    const Eigen::Matrix2Xd moved = scene.truthPoints.colwise() + share * scene.interOcular;
    const RefinedPoints refined = refineAndCheck(model.refiner, scene.image, moved);
    ASSERT_GT(meanPointError(refined.points, scene.truthPoints) / scene.interOcular, 0.2);
    EXPECT_LT(refined.rightProbability, 0.5) << share.transpose();
  }

  // The tracker judges a checked fit on the check's probability: a frame without the face fails.
  TrackerSettings settings;
  Tracker tracker(model, scene.camera, settings);
  tracker.setState(scene.truth, -1);
  const TrackStep tracked = tracker.track(scene.image, 0, 0.0);
  ASSERT_TRUE(tracked.row.success) << toString(tracked.failure);
  EXPECT_GT(tracked.row.confidence, 0.5);
  cv::Mat noise(scene.image.size(), scene.image.type());
  cv::randu(noise, 0, 255);
  tracker.setState(scene.truth, -1);
  const TrackStep lost = tracker.track(noise, 1, 0.04);
  EXPECT_FALSE(lost.row.success);
  ASSERT_TRUE(lost.fit.has_value());
  EXPECT_LT(lost.fit->probability, settings.minProbability);
}

// A still image whose fit the check rejects is reported as rejected, and its points are not
// written unless asked for: a photo of noise, searched from the face's points.
TEST(ImageFitRefiner, AFitTheCheckRejectsIsReportedAndNotWritten) {
  ClmModel model = fitTestModel();
  model.refiner = test::photoRefiner();
  const FitScene scene = makeFitScene(model, 0.0, 4.0, kHeldOutHead);
  const test::TempDir dir;
  savePhoto(dir.path(), "face", scene);
  cv::Mat noise(scene.image.size(), scene.image.type());
  cv::randu(noise, 0, 255);
  writeImage(dir / "noise.png", noise);

  ImageFitter fitter(model, ImageFitSettings{});
  const ImageFitOutcome right = fitter.fitFile(dir / "face.png", dir / "face.pts", dir / "a.pts");
  ASSERT_EQ(right.status, ImageFitStatus::Ok) << right.message;
  EXPECT_TRUE(fs::exists(dir / "a.pts"));
  const ImageFitOutcome wrong = fitter.fitFile(dir / "noise.png", dir / "face.pts", dir / "b.pts");
  ASSERT_EQ(wrong.status, ImageFitStatus::Rejected) << wrong.message;
  ASSERT_TRUE(wrong.fit.has_value());
  EXPECT_LT(wrong.fit->probability, ImageFitSettings{}.minProbability);
  EXPECT_NE(wrong.message.find("noise.png"), std::string::npos) << wrong.message;
  EXPECT_NE(wrong.message.find("rejects"), std::string::npos) << wrong.message;
  EXPECT_FALSE(fs::exists(dir / "b.pts"));
  EXPECT_TRUE(wrong.output.empty());
  EXPECT_STREQ(toString(wrong.status), "rejected");

  ImageFitSettings keep;
  keep.keepRejected = true;
  const ImageFitOutcome kept =
      ImageFitter(model, keep).fitFile(dir / "noise.png", dir / "face.pts", dir / "c.pts");
  EXPECT_EQ(kept.status, ImageFitStatus::Rejected);
  EXPECT_TRUE(fs::exists(dir / "c.pts"));
  EXPECT_EQ(kept.output, dir / "c.pts");
}

// A model calibrated on photo fits (`clm3d calibrate`) judges a photo's fit by the curve of its
// view's |yaw| applied to the check's log-odds (the nearest |yaw| when its own has none): the same
// fit, the known check's 0.8, is rejected under a curve that makes it 0.35 and kept under one that
// makes it 0.92, and its probability and source say so. The tracker's frames keep the check's.
TEST(ImageFitRefiner, APhotoFitCurveJudgesAPhotosFitByItsView) {
  DescentCheck check;
  EXPECT_EQ(nearestPhotoFitCurve(check.photoFitCurves, 10.0),
            nullptr);  // no curves: the check's own
  check.photoFitCurves = {{0.0, 1.0, -2.0, {}, {}}, {60.0, 1.0, 1.0, {}, {}}};
  const double logOddsOf08 = std::log(0.8 / 0.2);
  EXPECT_NEAR(photoFitProbability(*nearestPhotoFitCurve(check.photoFitCurves, -20.0), 0.8),
              1.0 / (1.0 + std::exp(-(logOddsOf08 - 2.0))), 1e-12);
  EXPECT_NEAR(photoFitProbability(*nearestPhotoFitCurve(check.photoFitCurves, 50.0), 0.8),
              1.0 / (1.0 + std::exp(-(logOddsOf08 + 1.0))), 1e-12);
  EXPECT_TRUE(std::isnan(photoFitProbability(check.photoFitCurves[0], std::nan(""))));

  ClmModel model = fitTestModel();
  model.refiner = knownRefiner();
  const FitScene scene = makeFitScene(model, 0.0, 2.0, kHeldOutHead, 70.0);
  const test::TempDir dir;
  savePhoto(dir.path(), "face", scene);
  const auto fitWithCurve = [&](double offset) {
    ClmModel calibrated = model;
    calibrated.refiner.check.photoFitCurves = {{0.0, 1.0, offset, {}, {}}};
    ImageFitSettings settings;
    settings.tiltSteps = 0;
    return ImageFitter(calibrated, settings).fitFile(dir / "face.png");
  };
  const ImageFitOutcome doubted = fitWithCurve(-2.0);
  EXPECT_EQ(doubted.status, ImageFitStatus::Rejected) << doubted.message;
  ASSERT_TRUE(doubted.fit);
  EXPECT_EQ(doubted.fit->probabilitySource, ProbabilitySource::PhotoFitCurve);
  EXPECT_NEAR(doubted.fit->probability, 1.0 / (1.0 + std::exp(-(logOddsOf08 - 2.0))), 1e-6);
  const ImageFitOutcome trusted = fitWithCurve(1.0);
  EXPECT_EQ(trusted.status, ImageFitStatus::Ok) << trusted.message;
  ASSERT_TRUE(trusted.fit);
  EXPECT_NEAR(trusted.fit->probability, 1.0 / (1.0 + std::exp(-(logOddsOf08 + 1.0))), 1e-6);

  ClmModel calibrated = model;
  calibrated.refiner.check.photoFitCurves = {{0.0, 1.0, -2.0, {}, {}}};
  Tracker tracker(calibrated, scene.camera, TrackerSettings{});
  tracker.setState(scene.truth, -1);
  const TrackStep frame = tracker.track(scene.image, 0, 0.0);
  ASSERT_TRUE(frame.row.success) << toString(frame.failure);
  EXPECT_NEAR(frame.row.confidence, kKnownCheckProbability, 1e-6);
}

// A still image's fit from one search and one refinement: the detector's start alone, no tilted
// copies, wider search, neighbouring views or second placements.
namespace {
ImageFitSettings oneSearch() {
  ImageFitSettings settings;
  settings.tiltSteps = 0;
  settings.startSearch.steps = 0;
  settings.widerSearchBelow = 0.0;
  settings.viewSearchBelow = 0.0;
  settings.turnedPlacements = false;
  settings.refineRuns = 1;
  return settings;
}
}  // namespace

// A curve's image term (model format 10) reads the photo at the fit's points with the layout of
// the views of its |yaw|: the same fit, whose check log-odds the curve's offset cancels (0.5),
// is kept when the image weights point along its features and rejected when they point away; a
// fit whose features cannot be read is given 0.
TEST(ImageFitRefiner, APhotoFitCurvesImageTermReadsThePhotoAtTheFitsPoints) {
  ClmModel model = fitTestModel();
  model.refiner = knownRefiner();
  const FitScene scene = makeFitScene(model, 0.0, 2.0, kHeldOutHead, 70.0);
  const test::TempDir dir;
  savePhoto(dir.path(), "face", scene);
  // One search, one refinement: the same points judged by each curve.
  const ImageFitSettings settings = oneSearch();
  const double logOddsOf08 = std::log(0.8 / 0.2);
  ClmModel calibrated = model;
  calibrated.refiner.check.photoFitCurves = {{0.0, 1.0, -logOddsOf08, {}, {}}};
  const ImageFitOutcome plain = ImageFitter(calibrated, settings).fitFile(dir / "face.png");
  ASSERT_TRUE(plain.fit);
  EXPECT_NEAR(plain.fit->probability, 0.5, 1e-6);
  ASSERT_GE(plain.fit->view, 0);
  const Eigen::VectorXf features =
      photoFitFeatures(model, plain.fit->view, readImage(dir / "face.png"), plain.fit->points);
  ASSERT_GT(features.size(), 0);
  const auto fitWithImageTerm = [&](float sign) {
    ClmModel judged = calibrated;
    PhotoFitCurve& curve = judged.refiner.check.photoFitCurves[0];
    curve.imageMean = Eigen::VectorXf::Zero(features.size());
    curve.imageWeights = sign * 2.0f * features / features.squaredNorm();  // a score of +-2
    return ImageFitter(judged, settings).fitFile(dir / "face.png");
  };
  const ImageFitOutcome kept = fitWithImageTerm(1.0f);
  ASSERT_TRUE(kept.fit);
  EXPECT_EQ(kept.status, ImageFitStatus::Ok) << kept.message;
  EXPECT_NEAR(kept.fit->probability, 1.0 / (1.0 + std::exp(-2.0)), 1e-4);
  EXPECT_EQ(kept.fit->probabilitySource, ProbabilitySource::PhotoFitCurve);
  const ImageFitOutcome rejected = fitWithImageTerm(-1.0f);
  ASSERT_TRUE(rejected.fit);
  EXPECT_EQ(rejected.status, ImageFitStatus::Rejected) << rejected.message;
  EXPECT_NEAR(rejected.fit->probability, 1.0 / (1.0 + std::exp(2.0)), 1e-4);

  PhotoFitCurve curve{0.0, 1.0, 0.0, Eigen::VectorXf::Zero(features.size()),
                      Eigen::VectorXf::Ones(features.size())};
  EXPECT_EQ(photoFitProbability(curve, 0.8, Eigen::VectorXf()), 0.0);
}

// The photo search compares its candidates (here the start grid's) on the photo-fit probability
// it judges with, not on the check's: an image term that scores the start's own fit down makes the
// search keep another start's fit, more probable by the curve.
TEST(ImageFitRefiner, ThePhotoSearchChoosesItsFitByThePhotoFitProbability) {
  ClmModel model = fitTestModel();
  model.refiner = knownRefiner();
  const FitScene scene = makeFitScene(model, 0.0, 2.0, kHeldOutHead, 70.0);
  const test::TempDir dir;
  savePhoto(dir.path(), "face", scene);
  const ImageFitSettings single = oneSearch();
  ClmModel calibrated = model;
  calibrated.refiner.check.photoFitCurves = {{0.0, 1.0, 0.0, {}, {}}};
  const ImageFitOutcome plain = ImageFitter(calibrated, single).fitFile(dir / "face.png");
  ASSERT_TRUE(plain.fit);
  const cv::Mat image = readImage(dir / "face.png");
  const Eigen::VectorXf features =
      photoFitFeatures(model, plain.fit->view, image, plain.fit->points);
  ASSERT_GT(features.size(), 0);
  PhotoFitCurve& curve = calibrated.refiner.check.photoFitCurves[0];
  curve.imageMean = features;  // the start's own fit reads exactly the mean: no image score
  curve.imageWeights = -4.0f * features / features.norm();

  ImageFitSettings grid = single;
  grid.startSearch.steps = 1;
  grid.startSearch.onlyBelow = 0.0;  // the whole grid
  const ImageFitOutcome chosen = ImageFitter(calibrated, grid).fitFile(dir / "face.png");
  ASSERT_TRUE(chosen.fit);
  EXPECT_EQ(chosen.fit->probabilitySource, ProbabilitySource::PhotoFitCurve);
  // The start's own fit by the curve with the term: its check's probability (the curve without
  // the term is the identity), its image score 0.
  const double startsOwnJudged = photoFitProbability(curve, plain.fit->probability, features);
  EXPECT_GT(chosen.fit->probability, startsOwnJudged + 0.01)
      << "the grid's kept fit is judged more probable than the start's own fit";
  EXPECT_GT((chosen.fit->points - plain.fit->points).cwiseAbs().maxCoeff(), 0.5)
      << "another start's fit is kept";
}

// A head tilted 40 degrees: the detectors find no upright face (or none whose fit passes the
// check), so `clm3d fit` detects in turned copies of the photo and searches from a tilted start.
TEST(ImageFitRefiner, ATiltedFaceIsFoundInATurnedCopyOfThePhoto) {
  ClmModel model = fitTestModel();
  model.refiner = test::photoRefiner();
  const FitScene scene = makeFitScene(model, 0.0, 0.0, kHeldOutHead, 60.0, 40.0);
  const test::TempDir dir;
  savePhoto(dir.path(), "tilted", scene);

  ImageFitter fitter(model, ImageFitSettings{});
  const ImageFitOutcome found = fitter.fitFile(dir / "tilted.png");
  ASSERT_EQ(found.status, ImageFitStatus::Ok) << found.message;
  EXPECT_GE(found.fit->probability, 0.5);
  EXPECT_LT(meanPointError(found.fit->points, scene.truthPoints) / scene.interOcular, 0.15)
      << "tilted search: error "
      << meanPointError(found.fit->points, scene.truthPoints) / scene.interOcular;
  EXPECT_GT(degrees(found.fit->state.pose.roll), 15.0);

  ImageFitSettings upright;
  upright.tiltSteps = 0;
  const ImageFitOutcome missed = ImageFitter(model, upright).fitFile(dir / "tilted.png");
  EXPECT_NE(missed.status, ImageFitStatus::Ok)
      << "found upright: error "
      << meanPointError(missed.fit->points, scene.truthPoints) / scene.interOcular;
}

// A checked frame that passes starts the next frame from the state of its refined points,
// whatever its search scored: the next frame is searched from there, not detected (issue 27: a
// frame whose search scored low but whose points passed used to send the next frame back to the
// detector, 50 of 60 frames re-detected in one real sequence).
TEST(ImageFitRefiner, APassingFrameContinuesFromItsRefinedPointsNotTheDetector) {
  ClmModel model = fitTestModel();
  model.refiner = test::photoRefiner();
  const FitScene scene = makeFitScene(model, 0.0, 3.0, kHeldOutHead);
  TrackerSettings settings;
  Tracker tracker(model, scene.camera, settings);
  tracker.setState(scene.truth, -1);
  const TrackStep first = tracker.track(scene.image, 0, 0.0);
  ASSERT_TRUE(first.row.success) << toString(first.failure);
  ASSERT_EQ(first.fit->probabilitySource, ProbabilitySource::Check);
  // The carried state reproduces the refined points the frame output closer than the search's own
  // state does. Not exactly: this fixture's refiner places a 2D mean shape that the 3D shape model
  // (modes clamped to +-3 SD) cannot reproduce (measured: 0.027 against the search's 0.029).
  const auto offPoints = [&](const FitState& state) {
    const Eigen::Matrix2Xd projected = projectState(model, scene.camera, state);
    double sum = 0.0;
    int count = 0;
    for (int i = 0; i < projected.cols(); ++i) {
      if (!first.fit->modelled[static_cast<std::size_t>(i)]) continue;
      sum += (projected.col(i) - first.row.points.col(i)).norm();
      ++count;
    }
    return sum / count / scene.interOcular;
  };
  const double carried = offPoints(tracker.nextStart());
  const double searched = offPoints(first.fit->state);
  EXPECT_LT(carried, 0.03);
  EXPECT_LT(carried, searched - 0.001) << "carried " << carried << ", the search's " << searched;
  const TrackStep second = tracker.track(scene.image, 1, 0.04);
  EXPECT_FALSE(second.detected);
  EXPECT_TRUE(second.row.success) << toString(second.failure);
  EXPECT_LT(meanPointError(second.row.points, scene.truthPoints) / scene.interOcular, 0.15);
}

// A face the detector cannot find (here smaller than its smallest box) is tracked frame to frame
// from a given start; once a frame without it loses the track, only the detector can find it.
TEST(ImageFitRefiner, AFaceTheDetectorMissesIsTrackedFromFrameToFrame) {
  ClmModel model = fitTestModel();
  model.refiner = test::photoRefiner();
  const FitScene scene = makeFitScene(model, 0.0, 3.0, kHeldOutHead, 17.0);
  FaceDetector detector;
  ASSERT_TRUE(detector.detect(scene.image).empty()) << "the premise: no face found";
  Tracker tracker(model, scene.camera, TrackerSettings{});
  tracker.setState(scene.truth, -1);
  for (int frame = 0; frame < 3; ++frame) {
    const TrackStep step = tracker.track(scene.image, frame, 0.04 * frame);
    EXPECT_FALSE(step.detected) << "frame " << frame;
    ASSERT_TRUE(step.row.success) << "frame " << frame << ": " << toString(step.failure);
    EXPECT_LT(meanPointError(step.row.points, scene.truthPoints) / scene.interOcular, 0.15);
  }
  cv::Mat blank(scene.image.size(), scene.image.type(), cv::Scalar::all(128));
  EXPECT_FALSE(tracker.track(blank, 3, 0.12).row.success);
  EXPECT_FALSE(tracker.track(scene.image, 4, 0.16).row.success);
}

// The face's box as the detector's calibration places it around the scene's eyes, its side
// `share` of the calibrated one.
FaceBox calibratedBox(const FitScene& scene, double share = 1.0) {
  const BoxCalibration calibration = boxCalibration(DetectorKind::Cascade, false);
  const Eigen::Vector2d eyes = 0.5 * (scene.truthPoints.col(7) + scene.truthPoints.col(10));
  const double width = share * scene.interOcular / calibration.iodPerWidth;
  FaceBox face;
  face.box = cv::Rect2d(eyes.x() - (0.5 + calibration.eyeOffsetX) * width,
                        eyes.y() - (0.5 + calibration.eyeOffsetY) * width, width, width);
  return face;
}

// A false detection ranked first costs a search, not the face: while the check rejects a face's
// fit the next face is searched, and the most confident fit is kept.
TEST(ImageFitRefiner, AFaceSearchTriesTheNextFaceWhileTheCheckRejectsTheFit) {
  ClmModel model = fitTestModel();
  model.refiner = test::photoRefiner();
  const FitScene scene = makeFitScene(model, 0.0, 3.0, kHeldOutHead);
  // The face's box as the detector's calibration places it, and a smaller one on the background.
  const FaceBox face = calibratedBox(scene);
  const double width = face.box.width;
  FaceBox background;
  background.box = cv::Rect2d(8.0, 90.0, 0.45 * width, 0.45 * width);
  ASSERT_LT(background.box.br().x, face.box.x) << "the two boxes must not overlap";

  Fitter fitter(model, scene.camera, FitSettings{});
  FaceSearch search;
  search.finish = [&](FitResult& fit) { refineFit(model, scene.image, fit); };
  search.accepted = [](const FitResult& fit) { return fit.probability >= 0.5; };
  const auto error = [&](const FitResult& fit) {
    return meanPointError(fit.points, scene.truthPoints) / scene.interOcular;
  };
  int tried = 0;
  search.maxFaces = 1;
  const FitResult first =
      fitFromBestFace(fitter, model, scene.image, {background, face}, search, &tried);
  EXPECT_EQ(tried, 1);
  EXPECT_LT(first.probability, 0.5);
  EXPECT_GT(error(first), 0.5);
  search.maxFaces = 3;
  const FitResult next =
      fitFromBestFace(fitter, model, scene.image, {background, face}, search, &tried);
  EXPECT_EQ(tried, 2) << "stops at the first fit accepted";
  EXPECT_GT(next.probability, 0.5);
  EXPECT_LT(error(next), 0.1);
  // The first accepted fit is kept, even when a fit before it was more confident (the tracker's
  // verdict is not the confidence alone): here a verdict that wants a low probability.
  search.accepted = [](const FitResult& fit) { return fit.probability < 0.5; };
  const FitResult accepted =
      fitFromBestFace(fitter, model, scene.image, {face, background}, search, &tried);
  EXPECT_EQ(tried, 2);
  EXPECT_LT(accepted.probability, 0.5);
  EXPECT_GT(error(accepted), 0.5);
  // A box whose start leaves the image is passed over; with nothing else, its error is thrown.
  search.accepted = [](const FitResult& fit) { return fit.probability >= 0.5; };
  FaceBox outside = face;
  outside.box.x += 20.0 * scene.image.cols;
  const FitResult afterOutside =
      fitFromBestFace(fitter, model, scene.image, {outside, face}, search, &tried);
  EXPECT_EQ(tried, 2);
  EXPECT_LT(error(afterOutside), 0.1);
  EXPECT_THROW(fitFromBestFace(fitter, model, scene.image, {outside}, search), InputError);
  // Without a verdict the first face's fit is kept.
  search.accepted = {};
  fitFromBestFace(fitter, model, scene.image, {face, background}, search, &tried);
  EXPECT_EQ(tried, 1);
  EXPECT_THROW(fitFromBestFace(fitter, model, scene.image, {}, search), InputError);
}

// The tracker's detections go through the same face loop: with the false box ranked first, one
// face tried loses the frame, three find the face.
TEST(ImageFitRefiner, TheTrackersDetectionsTryTheNextFaceToo) {
  ClmModel model = fitTestModel();
  model.refiner = test::photoRefiner();
  const FitScene scene = makeFitScene(model, 0.0, 3.0, kHeldOutHead);
  const FaceBox face = calibratedBox(scene);
  FaceBox background;
  background.box = cv::Rect2d(8.0, 90.0, 0.45 * face.box.width, 0.45 * face.box.width);
  const auto firstFrame = [&](int facesTried) {
    TrackerSettings settings;
    settings.facesTried = facesTried;
    Tracker tracker(model, scene.camera, settings);
    tracker.setFaceSource([&](const cv::Mat&) { return std::vector<FaceBox>{background, face}; });
    return tracker.track(scene.image, 0, 0.0);
  };
  const TrackStep one = firstFrame(1);
  EXPECT_TRUE(one.detected);
  EXPECT_FALSE(one.row.success);
  const TrackStep three = firstFrame(3);
  ASSERT_TRUE(three.row.success) << toString(three.failure);
  EXPECT_GT(three.searches, one.searches);
  EXPECT_LT(meanPointError(three.row.points, scene.truthPoints) / scene.interOcular, 0.1);
}

// A face the detector boxed too small: the fit from it is one the check doubts, and with
// widerBelow it is searched again from moved and rescaled copies of itself, which find the face.
TEST(ImageFitRefiner, AFitTheCheckDoubtsIsSearchedAgainFromRescaledStarts) {
  ClmModel model = fitTestModel();
  model.refiner = test::photoRefiner();
  const FitScene scene = makeFitScene(model, 0.0, 3.0, kHeldOutHead);
  const FaceBox face = calibratedBox(scene, 0.6);

  Fitter fitter(model, scene.camera, FitSettings{});
  FaceDetector detector;  // not used: the face is given and no tilted copy is searched
  FaceSearch search;
  search.finish = [&](FitResult& fit) { refineFit(model, scene.image, fit); };
  search.accepted = [](const FitResult& fit) { return fit.probability >= 0.5; };
  const auto error = [&](const FitResult& fit) {
    return meanPointError(fit.points, scene.truthPoints) / scene.interOcular;
  };
  const std::optional<FitResult> narrow =
      fitFromDetections(fitter, model, scene.image, detector, {face}, search);
  ASSERT_TRUE(narrow.has_value());
  ASSERT_LT(narrow->probability, 0.97) << "the premise: the check doubts the fit";
  ASSERT_GT(error(*narrow), 0.15) << "the premise: the fit is off";
  search.widerBelow = 0.97;
  const std::optional<FitResult> wider =
      fitFromDetections(fitter, model, scene.image, detector, {face}, search);
  ASSERT_TRUE(wider.has_value());
  EXPECT_GT(wider->probability, narrow->probability);
  EXPECT_LT(error(*wider), 0.1);
}

// In a view the point refiner did not learn (ViewModel::refined false: profiles, for a refiner
// learnt from near-frontal photos) a fit keeps the search's points and is judged on its view's
// probability (its check's, else its calibration's); in a view it learnt, the points are refined
// and checked as before.
TEST(ImageFitRefiner, AViewTheRefinerDidNotLearnKeepsTheSearchsPointsAndIsJudgedOnItsView) {
  ClmModel model = test::calibratedFitTestModel().model;
  model.refiner = test::photoRefiner();
  for (ViewModel& view : model.views) view.refined = view.yawDeg == 0.0;
  const FitScene side = makeFitScene(model, 0.0, -30.0, kHeldOutHead);
  Fitter fitter(model, side.camera, FitSettings{});
  FitResult searched = fitter.fit(side.image, side.truth);
  ASSERT_FALSE(model.views[static_cast<std::size_t>(searched.view)].refined);
  ASSERT_EQ(searched.probabilitySource, ProbabilitySource::ViewCalibration);
  FitResult finished = searched;
  refineFit(model, side.image, finished);
  EXPECT_EQ(finished.points, searched.points);
  // The fixture's views have checks: the view's probability is its check's, and it judges.
  const double checked = viewCheckProbability(model, searched.view, side.image, searched.points);
  ASSERT_TRUE(std::isfinite(checked));
  EXPECT_EQ(finished.viewProbability, checked);
  EXPECT_EQ(finished.probability, checked);
  EXPECT_EQ(finished.probabilitySource, ProbabilitySource::ViewCheck);
  EXPECT_EQ(finished.searchScore, searched.searchScore);

  const FitScene front = makeFitScene(model, 0.0, 3.0, kHeldOutHead);
  FitResult frontal = fitter.fit(front.image, front.truth);
  ASSERT_TRUE(model.views[static_cast<std::size_t>(frontal.view)].refined);
  const FitResult raw = frontal;
  refineFit(model, front.image, frontal);
  EXPECT_NE(frontal.points, raw.points);
  EXPECT_NE(frontal.probability, raw.probability) << "the check's probability";
  EXPECT_EQ(frontal.probabilitySource, ProbabilitySource::Check);
  EXPECT_EQ(frontal.searchScore, raw.searchScore);
}

}  // namespace
}  // namespace clm3d
