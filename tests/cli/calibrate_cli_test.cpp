// clm3d calibrate through the real binary: a model without a point check is refused with a clear
// message; a model with one, calibrated on annotated renders, is written with its curve, and
// `clm3d info` and `clm3d fit` say where a photo fit's probability then comes from.
#include <gtest/gtest.h>

#include "core/model/model_file.hpp"
#include "core/scheme/landmark_file.hpp"
#include "tests/support/fit_fixture.hpp"
#include "tests/support/refiner_fixture.hpp"
#include "tests/support/test_support.hpp"
#include "tests/support/tiny_model.hpp"

namespace clm3d {
namespace {

using test::runClm3d;

TEST(CalibrateCli, AModelWithoutACheckIsRefused) {
  const test::TempDir dir;
  saveModel(test::makeTinyModel(), dir / "tiny.clm3d");
  test::writeFile(dir / "list.txt", (dir / "a.png").string() + "\n");
  const auto result =
      runClm3d("calibrate --model " + (dir / "tiny.clm3d").string() + " --images " +
               (dir / "list.txt").string() + " --out " + (dir / "out.clm3d").string());
  EXPECT_EQ(result.exitCode, 1) << result.output;
  EXPECT_TRUE(test::contains(result.output, "no point check")) << result.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.clm3d"));
}

TEST(CalibrateCli, WritesTheCalibratedModelThatFitAndInfoUse) {
  const test::TempDir dir;
  ClmModel model = test::fitTestModel();
  model.refiner = test::photoRefiner();
  saveModel(model, dir / "model.clm3d");
  const auto photos = dir / "photos";
  std::filesystem::create_directories(photos);
  for (int k = 0; k < 6; ++k) {
    const std::string name = "face" + std::to_string(k);
    const test::FitScene scene =
        test::makeFitScene(model, 0.0, -5.0 + 2.0 * k, test::kHeldOutHead, 70.0);
    test::savePhoto(photos, name, scene);
    if (k % 3 == 1) {  // the truth a face width off: the fit counts as wrong
      LandmarkSet moved = readLandmarks(photos / (name + ".pts"), &Scheme::thesis25());
      for (int i = 0; i < moved.size(); ++i) {
        moved.set(i, Eigen::Vector2d(moved.point(i).head<2>() +
                                     Eigen::Vector2d(2.0 * scene.interOcular, 0.0)));
      }
      writeLandmarks(photos / (name + ".pts"), moved, Scheme::thesis25());
    }
  }
  const std::string out = (dir / "calibrated.clm3d").string();
  const auto result =
      runClm3d("calibrate --model " + (dir / "model.clm3d").string() + " --images " +
               photos.string() + " --out " + out + " --min-each 2 --quiet");
  ASSERT_EQ(result.exitCode, 0) << result.output;
  EXPECT_TRUE(test::contains(result.output, "| 0 | 6 | 4 | 2 | own |")) << result.output;
  const ClmModel calibrated = loadModel(out);
  ASSERT_EQ(calibrated.refiner.check.photoFitCurves.size(), 1u);
  EXPECT_EQ(calibrated.refiner.check.photoFitCurves[0].viewYawDeg, 0.0);

  const auto info = runClm3d("info " + out);
  ASSERT_EQ(info.exitCode, 0) << info.output;
  EXPECT_TRUE(test::contains(info.output, "photo fits: the check through the curves"))
      << info.output;
  const auto fit = runClm3d("fit --model " + out + " --image " + (photos / "face0.png").string() +
                            " --out " + (dir / "face0.fit.pts").string());
  EXPECT_TRUE(test::contains(fit.output, "check on photo fits")) << fit.output;
}

}  // namespace
}  // namespace clm3d
