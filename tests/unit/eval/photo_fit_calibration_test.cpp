// The point check calibrated on photo fits (calibratePhotoFits, `clm3d calibrate`): the whole photo
// pipeline fits annotated renders of a head it did not learn from; where a truth file puts the
// face elsewhere the fit counts as wrong, and the curve learnt for the fits' view gives about the
// share of right fits, where the check alone called them all right.
#include "core/eval/photo_fit_calibration.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/common/error.hpp"
#include "core/refine/descent_check.hpp"
#include "core/scheme/landmark_file.hpp"
#include "tests/support/fit_fixture.hpp"
#include "tests/support/refiner_fixture.hpp"
#include "tests/support/test_support.hpp"
#include "tests/support/tiny_model.hpp"

namespace clm3d {
namespace {

namespace fs = std::filesystem;

TEST(PhotoFitCalibration, LearnsTheShareOfRightFitsPerViewFromThePipelinesOwnFits) {
  ClmModel model = test::fitTestModel();
  model.refiner = test::photoRefiner();
  const test::TempDir dir;
  std::vector<fs::path> images, truths;
  constexpr int kPhotos = 8;
  for (int k = 0; k < kPhotos; ++k) {
    const std::string name = "face" + std::to_string(k);
    const test::FitScene scene =
        test::makeFitScene(model, 0.0, -7.0 + 2.0 * k, test::kHeldOutHead, 70.0);
    test::savePhoto(dir.path(), name, scene);
    images.push_back(dir / (name + ".png"));
    truths.push_back(dir / (name + ".pts"));
    if (k % 4 == 1) {  // a truth that puts the face a face width to the right: the fit is wrong
      LandmarkSet moved = readLandmarks(truths.back(), &Scheme::thesis25());
      for (int i = 0; i < moved.size(); ++i) {
        moved.set(i, Eigen::Vector2d(moved.point(i).head<2>() +
                                     Eigen::Vector2d(2.0 * scene.interOcular, 0.0)));
      }
      writeLandmarks(truths.back(), moved, Scheme::thesis25());
    }
  }
  PhotoFitCalibrationSettings settings;
  settings.minEach = 2;
  settings.threads = 2;
  const PhotoFitCalibration calibration = calibratePhotoFits(model, images, truths, settings);
  EXPECT_EQ(calibration.photos, kPhotos);
  EXPECT_EQ(calibration.judged, kPhotos);
  ASSERT_EQ(calibration.rows.size(), 1u);
  const PhotoFitCalibrationRow& row = calibration.rows.front();
  EXPECT_EQ(row.viewYawDeg, 0.0);
  EXPECT_EQ(row.right, 6);
  EXPECT_EQ(row.wrong, 2);
  EXPECT_TRUE(row.curve);
  EXPECT_EQ(row.rightKeptBefore, 6);
  EXPECT_EQ(row.wrongAcceptedBefore, 2) << "the check cannot know the truth was moved";
  ASSERT_EQ(calibration.curves.size(), 1u);
  // A logistic curve fitted by maximum likelihood with an offset gives its sample's fits
  // probabilities that sum to the right ones: over the same fits (the pipeline is deterministic),
  // the calibrated probabilities average 6 of 8.
  EXPECT_FALSE(calibration.curves.front().hasImageTerm()) << "8 fits are fewer than 100";
  ImageFitter fitter(model, settings.fit);  // the calibration's own pipeline
  double sum = 0.0;
  for (const fs::path& image : images) {
    const ImageFitOutcome outcome = fitter.fitFile(image);
    ASSERT_TRUE(outcome.fit) << outcome.message;
    sum += photoFitProbability(calibration.curves.front(), outcome.fit->probability);
  }
  EXPECT_NEAR(sum / kPhotos, 6.0 / kPhotos, 0.03);
}

TEST(PhotoFitCalibration, AModelWithoutACheckIsAClearError) {
  const ClmModel model = test::makeTinyModel();
  try {
    calibratePhotoFits(model, {"a.png"}, {"a.pts"}, PhotoFitCalibrationSettings{});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no point check"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace clm3d
