// Tests of the cascade detector working with dlib's HOG detector (core/detect/face_detector):
// the ranking by agreement (faces both detectors find first, then the largest; a cascade box on
// part of a face that dlib finds whole goes), and dlib searching where the cascade finds nothing.
#include <gtest/gtest.h>

#include "core/detect/face_detector.hpp"
#include "tests/support/fit_fixture.hpp"
#include "tests/unit/detect/detect_scenes.hpp"

namespace clm3d {
namespace {

FaceBox makeBox(cv::Rect2d box, double score, DetectorKind detector) {
  FaceBox face;
  face.box = box;
  face.score = score;
  face.detector = detector;
  return face;
}

TEST(FaceBoxes, AgreementRanksConfirmedFacesFirstThenTheLargest) {
  constexpr auto kCascade = DetectorKind::Cascade;
  constexpr auto kDlib = DetectorKind::DlibHog;
  // Cascade boxes as rankAndSuppress leaves them (by score): a false box on part of a face, a
  // small face that dlib confirms, a large face dlib does not see.
  const std::vector<FaceBox> cascade = {makeBox({100, 100, 50, 50}, 30, kCascade),
                                        makeBox({400, 50, 60, 60}, 5, kCascade),
                                        makeBox({600, 300, 150, 150}, 4, kCascade)};
  const std::vector<FaceBox> hog = {
      makeBox({60, 80, 160, 160}, 0.5, kDlib),  // the whole face around the first cascade box
      makeBox({405, 58, 52, 52}, 1.5, kDlib),   // the small face, confirmed (IoU 0.75)
      makeBox({900, 0, 90, 90}, 0.2, kDlib)};   // a face dlib alone finds
  const std::vector<FaceBox> ranked = rankByAgreement(cascade, hog, 0.3);
  ASSERT_EQ(ranked.size(), 4u);
  // The confirmed face keeps the cascade's box and comes first, although it is small.
  EXPECT_EQ(ranked[0].box, cascade[1].box);
  EXPECT_EQ(ranked[0].detector, kCascade);
  // Then the unconfirmed faces, largest first; dlib's whole face replaces the cascade's part of it.
  EXPECT_EQ(ranked[1].box, hog[0].box);
  EXPECT_EQ(ranked[1].detector, kDlib);
  EXPECT_EQ(ranked[2].box, cascade[2].box);
  EXPECT_EQ(ranked[3].box, hog[2].box);
  // Without dlib's boxes the cascade's order is only re-sorted by size.
  const std::vector<FaceBox> alone = rankByAgreement(cascade, {}, 0.3);
  ASSERT_EQ(alone.size(), 3u);
  EXPECT_EQ(alone[0].box, cascade[2].box);
}

// The held-out procedural head, frontal, in a 640x480 frame.
test::Scene frontalScene() {
  const SynthHead& head = test::fitTestHeads()[test::kHeldOutHead];
  OffscreenRenderer renderer(head.mesh);
  return test::renderScene(renderer, head.landmarks, test::sceneCamera(), 0.0, 0.0, 0.0,
                           {330.0, 220.0}, 55.0, 7);
}

TEST(FaceDetector, DlibSearchesWhereTheCascadeFindsNothing) {
  if (!FaceDetector::available(DetectorKind::DlibHog)) {
    GTEST_SKIP() << "clm3d was built without dlib";
  }
  const test::Scene scene = frontalScene();
  const cv::Point2d eyes(scene.eyeMid.x(), scene.eyeMid.y());
  // A "frontal" cascade that finds no face: the licence plate one.
  FaceDetectorSettings settings;
  settings.frontalCascade = "haarcascades/haarcascade_russian_plate_number.xml";
  settings.profiles = false;
  settings.dlibFallback = false;
  ASSERT_TRUE(FaceDetector(DetectorKind::Cascade, settings).detect(scene.bgr).empty());
  settings.dlibFallback = true;
  const std::vector<FaceBox> faces =
      FaceDetector(DetectorKind::Cascade, settings).detect(scene.bgr);
  ASSERT_FALSE(faces.empty());
  EXPECT_TRUE(faces.front().box.contains(eyes));
  EXPECT_EQ(faces.front().detector, DetectorKind::DlibHog);  // its own calibration applies

  // The real cascade finds the head and dlib confirms it: the cascade's box stays first.
  FaceDetector both;
  const std::vector<FaceBox> confirmed = both.detect(scene.bgr);
  ASSERT_FALSE(confirmed.empty());
  EXPECT_TRUE(confirmed.front().box.contains(eyes));
  EXPECT_EQ(confirmed.front().detector, DetectorKind::Cascade);
  EXPECT_TRUE(both.detect(cv::Mat(240, 320, CV_8UC1, cv::Scalar(90))).empty());
}

}  // namespace
}  // namespace clm3d
