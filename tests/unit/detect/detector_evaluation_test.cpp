// Tests of core/detect/detector_evaluation (`clm3d detect`): the box calibration measured on
// renders of a procedural head with known points matches the boxes and the render-measured
// figures; found / wrong face / no face are counted as defined (a head pasted into a larger
// image, a background without a face, a truth pointing elsewhere); the start error; the JSON
// report read back as a calibration; errors name the file.
#include "core/detect/detector_evaluation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "core/common/image_list.hpp"
#include "core/scheme/landmark_file.hpp"
#include "core/scheme/scheme.hpp"
#include "core/viz/image_file.hpp"
#include "tests/support/fit_fixture.hpp"
#include "tests/support/test_support.hpp"
#include "tests/unit/detect/detect_scenes.hpp"

namespace clm3d {
namespace {

namespace fs = std::filesystem;

void writeTruth(const fs::path& path, const Eigen::Matrix2Xd& points) {
  LandmarkSet set(static_cast<int>(points.cols()), 2);
  for (int i = 0; i < points.cols(); ++i) set.set(i, Eigen::Vector2d(points.col(i)));
  writeLandmarks(path, set, Scheme::thesis25());
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// Frontal renders of the held-out procedural head (eye distances 50-90 px, positions across the
// frame) written as PNG + STEM.pts.
std::vector<test::Scene> writeFrontalScenes(const test::TempDir& dir) {
  const SynthHead& head = test::fitTestHeads()[test::kHeldOutHead];
  OffscreenRenderer renderer(head.mesh);
  std::vector<test::Scene> scenes;
  int k = 0;
  for (const double iod : {50.0, 65.0, 80.0}) {
    for (const double x : {250.0, 380.0}) {
      test::Scene scene = test::renderScene(renderer, head.landmarks, test::sceneCamera(), 0.0, 0.0,
                                            0.0, {x, 230.0}, iod, 100 + k);
      const std::string stem = "scene" + std::to_string(k++);
      writeImage(dir / (stem + ".png"), scene.bgr);
      writeTruth(dir / (stem + ".pts"), scene.truth);
      scenes.push_back(std::move(scene));
    }
  }
  return scenes;
}

struct Expected {
  DetectorKind kind;
  FaceDetectorSettings settings;
  double ratio, offsetX, offsetY;  // the render-measured figures (P) of docs/initialisation.md
};

TEST(DetectorEvaluation, CalibrationOfFrontalRendersMatchesTheBoxesAndTheRenderFigures) {
  test::TempDir dir;
  const std::vector<test::Scene> scenes = writeFrontalScenes(dir);
  const std::vector<fs::path> images = listImages(dir.path());
  ASSERT_EQ(images.size(), scenes.size());
  const std::vector<fs::path> truths = findTruthFiles(images, {});

  std::vector<Expected> cases{{DetectorKind::Cascade, {}, 0.395, -0.010, -0.106}};
  if (FaceDetector::available(DetectorKind::DlibHog)) {
    FaceDetectorSettings fast;
    fast.minFaceSize = 80;  // no image doubling
    cases.push_back({DetectorKind::DlibHog, fast, 0.469, 0.002, -0.273});
  }
  for (const Expected& c : cases) {
    DetectorEvaluationSettings settings;
    settings.detector = c.settings;
    const DetectorEvaluationReport report = evaluateDetectors(images, truths, {c.kind}, settings);
    ASSERT_EQ(report.detectors.size(), 1u);
    const DetectorEvaluation& e = report.detectors.front();
    const char* name = detectorKindName(c.kind);
    EXPECT_EQ(e.images.size(), scenes.size());
    EXPECT_GE(e.found, 3) << name;  // the cascade misses some stylised heads
    EXPECT_EQ(e.noFace + e.found, static_cast<int>(scenes.size())) << name;  // nothing else there

    // The same figures straight from the detector's boxes.
    FaceDetector detector(c.kind, c.settings);
    std::vector<double> ratio, x, y;
    for (std::size_t i = 0; i < scenes.size(); ++i) {
      const test::Scene& s = scenes[i];
      for (const FaceBox& box : detector.detect(s.bgr)) {
        if (box.profile || !box.box.contains({s.eyeMid.x(), s.eyeMid.y()})) continue;
        ratio.push_back(s.iodPixels / box.box.width);
        x.push_back((s.eyeMid.x() - (box.box.x + 0.5 * box.box.width)) / box.box.width);
        y.push_back((s.eyeMid.y() - (box.box.y + 0.5 * box.box.height)) / box.box.width);
        break;
      }
    }
    ASSERT_EQ(e.frontal.faces, static_cast<int>(ratio.size())) << name;
    ASSERT_GE(e.frontal.faces, 3) << name;
    EXPECT_NEAR(e.frontal.median.iodPerWidth, median(ratio), 1e-9) << name;
    EXPECT_NEAR(e.frontal.median.eyeOffsetX, median(x), 1e-9) << name;
    EXPECT_NEAR(e.frontal.median.eyeOffsetY, median(y), 1e-9) << name;
    // And close to what the 396 calibration renders of other procedural heads gave.
    EXPECT_NEAR(e.frontal.median.iodPerWidth, c.ratio, 0.05) << name;
    EXPECT_NEAR(e.frontal.median.eyeOffsetX, c.offsetX, 0.05) << name;
    EXPECT_NEAR(e.frontal.median.eyeOffsetY, c.offsetY, 0.05) << name;

    // The report as JSON reads back as a calibration set of the measured medians.
    const fs::path json = dir / "report.json";
    test::writeFile(json, formatDetectorEvaluationJson(report, true));
    const CalibrationSet set = readCalibrationSet(json);
    const BoxCalibration read = set.get(c.kind, false);
    EXPECT_NEAR(read.iodPerWidth, e.frontal.median.iodPerWidth, 1e-9) << name;
    EXPECT_NEAR(read.eyeOffsetY, e.frontal.median.eyeOffsetY, 1e-9) << name;
    EXPECT_DOUBLE_EQ(set.get(c.kind, true).iodPerWidth, boxCalibration(c.kind, true).iodPerWidth);
    const std::string text = formatDetectorEvaluationText(report, true);
    EXPECT_NE(text.find("iodPerWidth"), std::string::npos) << text;
  }
}

TEST(DetectorEvaluation, MeanShapeCalibrationPlacesTheMeanShapeAtLeastAsWell) {
  test::TempDir dir;
  const std::vector<test::Scene> scenes = writeFrontalScenes(dir);
  const std::vector<fs::path> images = listImages(dir.path());
  const std::vector<fs::path> truths = findTruthFiles(images, {});
  const ClmModel& model = test::fitTestModel();
  DetectorEvaluationSettings settings;
  settings.detector.profiles = false;
  settings.calibrationTarget = CalibrationTarget::MeanShape;
  const DetectorEvaluationReport measured =
      evaluateDetectors(images, truths, {DetectorKind::Cascade}, settings, &model);
  const CalibrationEstimate& frontal = measured.detectors.front().frontal;
  ASSERT_GE(frontal.faces, 3);
  // The head is frontal and the model was trained on its siblings: the mean shape fitted to its
  // points has about its eye distance and eye midpoint.
  EXPECT_NEAR(frontal.median.iodPerWidth, 0.395, 0.06);
  test::writeFile(dir / "measured.json", formatDetectorEvaluationJson(measured, true));
  const CalibrationSet set = readCalibrationSet(dir / "measured.json");
  const DetectorEvaluationReport compared = evaluateDetectors(
      images, truths, {DetectorKind::Cascade}, settings, &model, {CalibrationSet{}, set});
  const std::vector<StartErrorSummary>& errors = compared.detectors.front().startErrors;
  ASSERT_EQ(errors.size(), 2u);
  EXPECT_EQ(errors[1].calibration, "measured.json");
  // Calibrated on these very scenes, the start is at least about as near as the built-in one.
  EXPECT_LT(errors[1].mean, errors[0].mean + 0.01);
  EXPECT_LT(errors[1].mean, 0.2);
}

TEST(DetectorEvaluation, CountsFoundWrongAndNoFace) {
  test::TempDir dir;
  const SynthHead& head = test::fitTestHeads()[test::kHeldOutHead];
  OffscreenRenderer renderer(head.mesh);
  const test::Scene scene = test::renderScene(renderer, head.landmarks, test::sceneCamera(), 0.0,
                                              0.0, 0.0, {330.0, 220.0}, 60.0, 7);
  // The render pasted into a larger photo at (300, 200).
  cv::Mat large = test::sceneBackground(1100, 800, 3);
  scene.bgr.copyTo(large(cv::Rect(300, 200, scene.bgr.cols, scene.bgr.rows)));
  Eigen::Matrix2Xd truth = scene.truth;
  truth.row(0).array() += 300.0;
  truth.row(1).array() += 200.0;
  writeImage(dir / "a_face.png", large);
  writeTruth(dir / "a_face.pts", truth);
  // A background without a face: no box at all.
  writeImage(dir / "b_empty.png", test::sceneBackground(1100, 800, 4));
  writeTruth(dir / "b_empty.pts", truth);
  // The same photo annotated somewhere else: the box found is not the annotated face.
  writeImage(dir / "c_other.png", large);
  Eigen::Matrix2Xd elsewhere = truth;
  elsewhere.row(0).array() -= truth(0, 0) - 100.0;
  elsewhere.row(1).array() -= truth(1, 0) - 100.0;
  writeTruth(dir / "c_other.pts", elsewhere);

  const std::vector<fs::path> images = listImages(dir.path());
  ASSERT_EQ(images.size(), 3u);
  DetectorEvaluationSettings settings;
  settings.detector.profiles = false;
  const ClmModel& model = test::fitTestModel();
  CalibrationSet wide;
  wide.label = "wide";
  BoxCalibration bad = boxCalibration(DetectorKind::Cascade, false);
  bad.iodPerWidth *= 1.5;
  wide.overrides[{DetectorKind::Cascade, false}] = bad;
  int progressCalls = 0;
  const DetectorEvaluationReport report = evaluateDetectors(
      images, findTruthFiles(images, {}), {DetectorKind::Cascade}, settings, &model,
      {CalibrationSet{}, wide}, [&](double, std::string_view) { ++progressCalls; });
  EXPECT_EQ(progressCalls, 3);
  const DetectorEvaluation& e = report.detectors.front();
  ASSERT_EQ(e.images.size(), 3u);
  EXPECT_TRUE(e.images[0].found());
  EXPECT_FALSE(e.images[0].wrongFace());
  EXPECT_TRUE(e.images[1].noFace());
  EXPECT_FALSE(e.images[2].found());
  EXPECT_TRUE(e.images[2].wrongFace());
  EXPECT_EQ(e.found, 1);
  EXPECT_EQ(e.noFace, 1);
  EXPECT_EQ(e.wrongFace, 1);
  EXPECT_GT(e.medianMilliseconds, 0.0);
  EXPECT_GE(e.p90Milliseconds, e.medianMilliseconds);
  // The start error in the found face's box: near with the built-in calibration, worse with a
  // box calibration 50% off.
  ASSERT_EQ(e.startErrors.size(), 2u);
  EXPECT_EQ(e.startErrors[0].faces, 1);
  EXPECT_LT(e.startErrors[0].mean, 0.2);
  EXPECT_GT(e.startErrors[1].mean, e.startErrors[0].mean + 0.05);
  // A frontal face of known yaw 0: the model's pose of the truth says so.
  EXPECT_NEAR(e.images[0].yawDeg, 0.0, 6.0);
  EXPECT_NEAR(e.images[0].iod, scene.iodFrontal, 0.1 * scene.iodFrontal);
}

TEST(DetectorEvaluation, ErrorsNameTheFile) {
  test::TempDir dir;
  writeImage(dir / "face.png", test::sceneBackground(200, 150, 1));
  // No truth beside the image.
  try {
    findTruthFiles({dir / "face.png"}, {});
    FAIL() << "no error for a missing truth file";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("face.png"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("no truth"), std::string::npos) << e.what();
  }
  EXPECT_THROW(findTruthFiles({dir / "face.png"}, dir / "nowhere"), InputError);
  // An unreadable image.
  test::writeFile(dir / "broken.png", "not an image");
  Eigen::Matrix2Xd points = Eigen::Matrix2Xd::Zero(2, 25);
  for (int i = 0; i < 25; ++i) points.col(i) = Eigen::Vector2d(50.0 + 3 * i, 60.0 + (i % 5));
  writeTruth(dir / "broken.pts", points);
  try {
    evaluateDetectors({dir / "broken.png"}, {dir / "broken.pts"}, {DetectorKind::Cascade}, {});
    FAIL() << "no error for an unreadable image";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("broken.png"), std::string::npos) << e.what();
  }
  // A truth of another scheme (AFLW's "-1 -1" marks an invisible point) with one visible point:
  // no box to hold.
  test::writeFile(dir / "few.pts", "version: 1\nn_points: 3\n{\n1 1\n-1 -1\n-1 -1\n}\n");
  try {
    readTruthFace(dir / "few.pts");
    FAIL() << "no error for a truth with one visible point";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("few.pts"), std::string::npos) << e.what();
  }
  // A calibration file that is not a report.
  test::writeFile(dir / "calib.json", "{\"x\": 1}");
  try {
    readCalibrationSet(dir / "calib.json");
    FAIL() << "no error for a bad calibration file";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("calib.json"), std::string::npos) << e.what();
  }
}

// A `clm3d detect --calibrate` report as the command writes it, with `extra` spliced into the
// object named by `where` ("root", "detector", "frontal").
std::string calibrationReport(const std::string& where, const std::string& extra) {
  const auto at = [&](const char* place) { return where == place ? extra : std::string(); };
  return "{" + at("root") +
         "\"settings\": {\"min_face_size\": 40, \"max_image_side\": 1600, "
         "\"cascade_profiles\": true, \"frontal_yaw_deg\": 20.0, \"calibration_target\": "
         "\"eyes\", \"vertical_fov_deg\": 40.0, \"with_model\": false},"
         "\"detectors\": [{" +
         at("detector") +
         "\"detector\": \"cascade\", \"images\": 4, \"found\": 4, \"no_face\": 0, "
         "\"wrong_face\": 0, \"median_ms\": 3.5, \"p90_ms\": 4.0, \"calibration\": {"
         "\"frontal\": {" +
         at("frontal") +
         "\"faces\": 4, \"iod_per_width\": 0.41, \"eye_offset_x\": 0.01, "
         "\"eye_offset_y\": -0.12, \"sd_iod_per_width\": 0.01, \"sd_eye_offset_x\": 0.0, "
         "\"sd_eye_offset_y\": 0.02},"
         "\"profile\": {\"faces\": 0, \"iod_per_width\": null, \"eye_offset_x\": null, "
         "\"eye_offset_y\": null, \"sd_iod_per_width\": null, \"sd_eye_offset_x\": null, "
         "\"sd_eye_offset_y\": null, \"yaw_deg\": null}}}]}";
}

// An AFLW truth (21 points, the turned-away eye's "-1 -1") is mapped to thesis25 points, which
// place the mean shape for `--calibrate-to mean-shape` at profile, while its face stays the box of
// its visible points (no eye centres to anchor it).
TEST(DetectorEvaluation, AflwTruthWithAHiddenEyeKeepsItsBoxAndGivesThesisPoints) {
  test::TempDir dir;
  std::string text = "version: 1\nn_points: 21\n{\n";
  for (int a = 0; a < 21; ++a) {
    const bool hidden = a == 9 || a == 10 || a == 11;  // AFLW 10-12: one eye's corners and centre
    text += hidden ? "-1 -1\n" : std::to_string(40 + 2 * a) + " " + std::to_string(50 + a) + "\n";
  }
  test::writeFile(dir / "profile.pts", text + "}\n");
  const TruthFace face = readTruthFace(dir / "profile.pts");
  EXPECT_FALSE(face.hasEyes());
  ASSERT_EQ(face.points.size(), 25);
  EXPECT_GE(face.points.presentCount(), 10);
  EXPECT_NEAR(face.anchor().x(), face.visibleBox.x + 0.5 * face.visibleBox.width, 1e-9);
  EXPECT_NEAR(face.anchor().y(), face.visibleBox.y + 0.5 * face.visibleBox.height, 1e-9);
}

TEST(DetectorEvaluation, CalibrationReportRejectsAnUnknownKeyNamingFileAndKey) {
  test::TempDir dir;
  test::writeFile(dir / "report.json", calibrationReport("", ""));
  const CalibrationSet set = readCalibrationSet(dir / "report.json");
  EXPECT_EQ(set.label, "report.json");
  ASSERT_EQ(set.overrides.size(), 1u);  // the profile boxes measured no face
  EXPECT_DOUBLE_EQ(set.get(DetectorKind::Cascade, false).iodPerWidth, 0.41);
  EXPECT_DOUBLE_EQ(set.get(DetectorKind::Cascade, false).eyeOffsetY, -0.12);
  EXPECT_DOUBLE_EQ(set.get(DetectorKind::Cascade, true).iodPerWidth,
                   boxCalibration(DetectorKind::Cascade, true).iodPerWidth);

  for (const auto& [where, key] : std::vector<std::pair<std::string, std::string>>{
           {"root", "detectorz"}, {"detector", "founds"}, {"frontal", "iod_per_widht"}}) {
    const fs::path file = dir / ("misspelt-" + where + ".json");
    test::writeFile(file, calibrationReport(where, "\"" + key + "\": 1, "));
    try {
      readCalibrationSet(file);
      FAIL() << "no error for the unknown key " << key;
    } catch (const InputError& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find(file.string()), std::string::npos) << message;
      EXPECT_NE(message.find(key), std::string::npos) << message;
      EXPECT_NE(message.find("unknown field"), std::string::npos) << message;
    }
  }
}

TEST(DetectorEvaluation, LfpwPhotosWhenPresent) {
  CLM3D_REQUIRE_SHARED_DATA(data);
  const fs::path folder = data / "photos/lfpw/test";
  if (!fs::is_directory(folder)) GTEST_SKIP() << folder << " not found";
  std::vector<fs::path> images = listImages(folder);
  images.resize(std::min<std::size_t>(images.size(), 4));
  DetectorEvaluationSettings settings;
  settings.detector.profiles = false;
  const DetectorEvaluationReport report =
      evaluateDetectors(images, findTruthFiles(images, {}), {DetectorKind::Cascade}, settings);
  EXPECT_GE(report.detectors.front().found, 3);
  EXPECT_EQ(report.detectors.front().frontal.faces, report.detectors.front().found);
}

}  // namespace
}  // namespace clm3d
