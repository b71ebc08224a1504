// clm3d detect through the real binary: the table for a folder (an image without a face counted
// as no face), the JSON report, errors naming the file (missing truth, unreadable image), usage
// errors; and, when ../shared/data is present, a few LFPW photos with both detectors.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string>

#include "core/common/data_paths.hpp"
#include "core/detect/face_detector.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

namespace fs = std::filesystem;
using test::runClm3d;

// A 25-point truth with eye centres (points 8 and 11) 40 pixels apart.
std::string truth25() {
  std::string text = "version: 1\nn_points: 25\n{\n";
  for (int i = 0; i < 25; ++i) {
    text += std::to_string(60 + 2 * i) + " " + std::to_string(70 + (i % 4)) + "\n";
  }
  return text + "}\n";
}

TEST(DetectCli, CountsAnImageWithoutAFaceAndWritesJson) {
  test::TempDir dir;
  cv::imwrite((dir / "grey.png").string(), cv::Mat(240, 320, CV_8UC3, cv::Scalar(120, 120, 120)));
  test::writeFile(dir / "grey.pts", truth25());
  const fs::path out = dir / "report.json";
  const auto result = runClm3d("detect --images " + dir.path().string() +
                               " --detector cascade --calibrate --quiet --out " + out.string());
  ASSERT_EQ(result.exitCode, 0) << result.output;
  EXPECT_TRUE(test::contains(result.output, "cascade | 1 | 0 | 1 | 0 |")) << result.output;
  const nlohmann::json report = nlohmann::json::parse(test::readFile(out));
  ASSERT_EQ(report["detectors"].size(), 1u);
  EXPECT_EQ(report["detectors"][0]["no_face"], 1);
  EXPECT_EQ(report["detectors"][0]["calibration"]["frontal"]["faces"], 0);
  EXPECT_EQ(report["settings"]["cascade_profiles_everywhere"], false);
  EXPECT_TRUE(test::contains(result.output, "profiles on, around frontal faces")) << result.output;

  // --profiles-everywhere: the profile passes over the whole image, recorded in the report.
  const auto everywhere =
      runClm3d("detect --images " + dir.path().string() +
               " --detector cascade --profiles-everywhere --quiet --out " + out.string());
  ASSERT_EQ(everywhere.exitCode, 0) << everywhere.output;
  EXPECT_TRUE(test::contains(everywhere.output, "profiles on, everywhere")) << everywhere.output;
  EXPECT_EQ(nlohmann::json::parse(test::readFile(out))["settings"]["cascade_profiles_everywhere"],
            true);
  EXPECT_EQ(
      runClm3d("detect --images " + dir.path().string() + " --no-profiles --profiles-everywhere")
          .exitCode,
      2);

  // dlib's fallback and agreement are on when the build has dlib; the flags turn them off.
  const bool dlib = report["settings"]["cascade_dlib_fallback"].get<bool>();
  EXPECT_EQ(report["settings"]["cascade_dlib_agreement"], dlib);
  const auto cascadeOnly = runClm3d("detect --images " + dir.path().string() +
                                    " --detector cascade --no-dlib-fallback --no-dlib-agreement "
                                    "--dlib-threshold -0.2 --quiet --out " +
                                    out.string());
  ASSERT_EQ(cascadeOnly.exitCode, 0) << cascadeOnly.output;
  EXPECT_TRUE(test::contains(cascadeOnly.output, "cascade with dlib: fallback off, agreement off"))
      << cascadeOnly.output;
  const nlohmann::json settings = nlohmann::json::parse(test::readFile(out))["settings"];
  EXPECT_EQ(settings["cascade_dlib_fallback"], false);
  EXPECT_EQ(settings["cascade_dlib_agreement"], false);
  EXPECT_DOUBLE_EQ(settings["dlib_threshold"].get<double>(), -0.2);
}

TEST(DetectCli, ErrorsNameTheFile) {
  test::TempDir dir;
  cv::imwrite((dir / "lonely.png").string(), cv::Mat(100, 100, CV_8UC3, cv::Scalar(0, 0, 0)));
  auto result = runClm3d("detect --images " + dir.path().string() + " --detector cascade");
  EXPECT_EQ(result.exitCode, 1) << result.output;
  EXPECT_TRUE(test::contains(result.output, "lonely.png")) << result.output;
  EXPECT_TRUE(test::contains(result.output, "no truth")) << result.output;

  fs::remove(dir / "lonely.png");
  test::writeFile(dir / "broken.png", "not an image");
  test::writeFile(dir / "broken.pts", truth25());
  result = runClm3d("detect --images " + dir.path().string() + " --detector cascade --quiet");
  EXPECT_EQ(result.exitCode, 1) << result.output;
  EXPECT_TRUE(test::contains(result.output, "broken.png")) << result.output;

  // Usage: the start error needs a model; an unknown detector is bad input.
  result = runClm3d("detect --images " + dir.path().string() + " --start-error");
  EXPECT_EQ(result.exitCode, 2) << result.output;
  result = runClm3d("detect --images " + dir.path().string() + " --calibrate-to mean-shape");
  EXPECT_EQ(result.exitCode, 2) << result.output;
  result = runClm3d("detect --images " + dir.path().string() + " --detector hog");
  EXPECT_EQ(result.exitCode, 1) << result.output;
  EXPECT_TRUE(test::contains(result.output, "hog")) << result.output;
}

TEST(DetectCli, LfpwPhotosWhenPresent) {
  const auto data = sharedDataDir();
  if (!data || !fs::is_directory(*data / "photos/lfpw/test")) {
    GTEST_SKIP() << "../shared/data/photos/lfpw not found (set CLM3D_DATA to run this test)";
  }
  test::TempDir dir;
  std::string list;
  for (const char* name : {"image_0001.jpg", "image_0002.jpg", "image_0004.jpg"}) {
    list += (*data / "photos/lfpw/test" / name).string() + "\n";
  }
  test::writeFile(dir / "list.txt", list);
  const fs::path out = dir / "report.json";
  const auto result = runClm3d("detect --images " + (dir / "list.txt").string() +
                               " --detector all --min-face 80 --calibrate --out " + out.string());
  ASSERT_EQ(result.exitCode, 0) << result.output;
  EXPECT_TRUE(test::contains(result.output, "detect 3/3 image_0004.jpg"))
      << result.output;  // progress
  const nlohmann::json report = nlohmann::json::parse(test::readFile(out));
  // "all": the cascade, and dlib's HOG detector where it is built in.
  ASSERT_EQ(report["detectors"].size(), FaceDetector::available(DetectorKind::DlibHog) ? 2u : 1u)
      << report.dump();
  for (const auto& detector : report["detectors"]) {
    EXPECT_EQ(detector["images"], 3);
    EXPECT_GE(detector["found"].get<int>(), 2) << detector.dump();
  }
}

}  // namespace
}  // namespace clm3d
