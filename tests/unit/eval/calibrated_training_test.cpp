// Training that ends in the manifest's photo-fit calibration (trainAndCalibrate, what `clm3d
// train`, the studio and `clm3d demo --real` run): the calibration photos are every n-th of their
// folder from an offset, with their truths; photos the point refiner learnt from are refused before
// any training; a model trained with them has its check calibrated and says so, and a model
// without a check is kept, with the reason.
#include "core/eval/calibrated_training.hpp"

#include <gtest/gtest.h>

#include "core/common/error.hpp"
#include "core/model/model_file.hpp"
#include "core/scheme/landmark_file.hpp"
#include "tests/support/fit_fixture.hpp"
#include "tests/support/refiner_fixture.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

namespace fs = std::filesystem;

// DIR/NAME/k.png with k.pts beside, for k < count (empty files: only listed, never read).
void writeListedPhotos(const fs::path& dir, int count) {
  fs::create_directories(dir);
  for (int k = 0; k < count; ++k) {
    test::writeFile(dir / (std::to_string(k) + ".png"), "");
    test::writeFile(dir / (std::to_string(k) + ".pts"), "");
  }
}

std::string inputError(const std::function<void()>& run) {
  try {
    run();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(CalibrationPhotoFiles, EveryNthFromTheOffsetWithTheirTruthsAndNoRefinerPhoto) {
  const test::TempDir dir;
  writeListedPhotos(dir / "cal", 7);
  writeListedPhotos(dir / "train", 2);
  test::writeFile(dir / "m.json", R"({"version": 1, "procedural": [{"seeds": "1"}],
      "photos": [{"folder": "train"}, {"folder": "cal", "refiner": false}],
      "calibration_photos": {"folder": "cal", "every": 3, "offset": 1}})");
  const CalibrationPhotoFiles files = calibrationPhotoFiles(loadManifest(dir / "m.json"));
  ASSERT_EQ(files.images.size(), 2u);
  EXPECT_EQ(files.images[0].filename(), "1.png");
  EXPECT_EQ(files.images[1].filename(), "4.png");
  ASSERT_EQ(files.truths.size(), 2u);
  EXPECT_EQ(files.truths[1].filename(), "4.pts");

  // The same photos also training the refiner (and so its check) are refused, naming one.
  test::writeFile(dir / "r.json", R"({"version": 1, "procedural": [{"seeds": "1"}],
      "photos": [{"folder": "cal"}], "calibration_photos": {"folder": "cal", "every": 3}})");
  const std::string refused =
      inputError([&] { calibrationPhotoFiles(loadManifest(dir / "r.json")); });
  EXPECT_NE(refused.find("0.png also trains the point refiner"), std::string::npos) << refused;

  // A photo without its truth file is named.
  fs::remove(dir / "cal" / "4.pts");
  const std::string noTruth =
      inputError([&] { calibrationPhotoFiles(loadManifest(dir / "m.json")); });
  EXPECT_NE(noTruth.find("4.png"), std::string::npos) << noTruth;
}

TEST(CalibrationPhotoFiles, AnOffsetBeyondTheListIsAClearErrorBeforeAnyTraining) {
  const test::TempDir dir;
  writeListedPhotos(dir / "cal", 2);
  test::writeFile(dir / "m.json", R"({"version": 1, "procedural": [{"seeds": "1"}],
      "calibration_photos": {"folder": "cal", "every": 5, "offset": 3}})");
  const std::string message = inputError([&] {
    trainAndCalibrate(dir / "m.json", TrainSettings{}, "test",
                      [](double, std::string_view) { ADD_FAILURE() << "training started"; });
  });
  EXPECT_NE(message.find("gives no calibration photo at offset 3 (of 2 images)"), std::string::npos)
      << message;
}

TrainSettings calibrationTrainSettings() {
  TrainSettings s = test::fitTestSettings(false);
  s.samplesPerView = 2;
  s.textureMaxModes = 8;
  s.refinerStages = 3;
  s.refinerStarts = 12;
  return s;
}

// Renders of the four fixture heads as training photos (24: enough for the refiner's check) and of
// the held-out head as calibration photos, two of whose truths put the face a face width away.
struct CalibratedTrainingFixture {
  test::TempDir dir;
  fs::path manifest;
  CalibratedTrainingFixture(bool withCheck) {
    const ClmModel& scenes = test::fitTestModel();
    fs::create_directories(dir / "photos");
    const int heads = withCheck ? 4 : 1;
    for (int head = 0; head < heads; ++head) {
      for (const double yaw : {-8.0, 0.0, 6.0, 12.0, -3.0, -12.0}) {
        test::savePhoto(dir / "photos",
                        "h" + std::to_string(head) + "y" + std::to_string(static_cast<int>(yaw)),
                        test::makeFitScene(scenes, 0.0, yaw, head));
      }
    }
    fs::create_directories(dir / "cal");
    for (int k = 0; k < 8; ++k) {
      const test::FitScene scene =
          test::makeFitScene(scenes, 0.0, -7.0 + 2.0 * k, test::kHeldOutHead, 70.0);
      const std::string name = "c" + std::to_string(k);
      test::savePhoto(dir / "cal", name, scene);
      if (k % 4 == 1) {
        const fs::path truth = dir / "cal" / (name + ".pts");
        LandmarkSet moved = readLandmarks(truth, &Scheme::thesis25());
        for (int i = 0; i < moved.size(); ++i) {
          moved.set(i, Eigen::Vector2d(moved.point(i).head<2>() +
                                       Eigen::Vector2d(2.0 * scene.interOcular, 0.0)));
        }
        writeLandmarks(truth, moved, Scheme::thesis25());
      }
    }
    manifest = dir / "m.json";
    test::writeFile(manifest, R"({"version": 1, "procedural": [{"seeds": "1-2"}],
        "photos": [{"folder": "photos"}],
        "calibration_photos": {"folder": "cal", "right_below": 0.3, "min_each": 2,
                               "image_min_fits": 8}})");
  }
};

TEST(CalibratedTraining, TheTrainedModelsCheckIsCalibratedOnTheManifestsPhotos) {
  const CalibratedTrainingFixture fixture(/*withCheck=*/true);
  std::vector<std::string> stages;
  double last = 0.0;
  const CalibratedTraining trained =
      trainAndCalibrate(fixture.manifest, calibrationTrainSettings(), "test",
                        [&](double fraction, std::string_view stage) {
                          last = fraction;
                          if (stages.empty() || stages.back() != stage) stages.emplace_back(stage);
                        });
  ASSERT_FALSE(trained.model.refiner.check.empty()) << "24 photos teach the refiner a check";
  ASSERT_TRUE(trained.calibration) << trained.calibrationSkipped;
  EXPECT_TRUE(trained.calibrationSkipped.empty());
  EXPECT_EQ(trained.calibration->photos, 8);
  ASSERT_FALSE(trained.calibration->rows.empty());
  int right = 0, wrong = 0;
  for (const PhotoFitCalibrationRow& row : trained.calibration->rows) {
    right += row.right;
    wrong += row.wrong;
  }
  EXPECT_EQ(wrong, 2) << "the two moved truths";
  EXPECT_EQ(right + wrong, trained.calibration->judged);
  const std::vector<PhotoFitCurve>& curves = trained.model.refiner.check.photoFitCurves;
  ASSERT_EQ(curves.size(), trained.calibration->curves.size());
  for (std::size_t i = 0; i < curves.size(); ++i) {
    EXPECT_EQ(curves[i].viewYawDeg, trained.calibration->curves[i].viewYawDeg);
    EXPECT_EQ(curves[i].slope, trained.calibration->curves[i].slope);
  }
  EXPECT_EQ(trained.calibrationSettings.rightBelow, 0.3);
  EXPECT_EQ(trained.calibrationSettings.imageMinFits, 8);
  // 8 fits (at least image_min_fits) are read for the image term; whether it is kept is the
  // cross-validation's call (tests/unit/eval/photo_fit_judge_test.cpp), and a kept one matches the
  // frontal view's layout. The model survives its file either way.
  ASSERT_EQ(curves.size(), 1u);
  if (curves[0].hasImageTerm()) {
    const int frontal = trained.model.photoFitLayoutView(0.0);
    ASSERT_GE(frontal, 0);
    const auto& visible = trained.model.views[static_cast<std::size_t>(frontal)].visible;
    EXPECT_EQ(curves[0].imageWeights.size(),
              std::count(visible.begin(), visible.end(), true) * kDescentFeaturesPerPoint);
  }
  EXPECT_EQ(
      parseModel(serializeModel(trained.model), "m.clm3d").refiner.check.photoFitCurves[0].slope,
      curves[0].slope);
  EXPECT_NE(trained.model.provenance.notes.find("calibrated on the photo pipeline's fits of 8"),
            std::string::npos)
      << trained.model.provenance.notes;
  EXPECT_EQ(stages.back(), "photo-fit calibration");
  EXPECT_DOUBLE_EQ(last, 1.0);
}

TEST(CalibratedTraining, AModelWithoutACheckIsKeptAndSaysWhy) {
  const CalibratedTrainingFixture fixture(/*withCheck=*/false);
  const CalibratedTraining trained =
      trainAndCalibrate(fixture.manifest, calibrationTrainSettings(), "test");
  EXPECT_TRUE(trained.model.refiner.check.empty()) << "6 photos are too few for a check";
  EXPECT_FALSE(trained.model.views.empty());
  EXPECT_FALSE(trained.calibration);
  EXPECT_NE(trained.calibrationSkipped.find("no point check"), std::string::npos)
      << trained.calibrationSkipped;
}

}  // namespace
}  // namespace clm3d
