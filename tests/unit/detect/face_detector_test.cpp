// Tests of core/detect/face_detector and initialiseFromImage: box overlap and suppression, cascade
// files that are missing, blank images, a rendered procedural head found (frontal and profile, the
// profile's side from `mirrored`) with stateFromBox's points near the truth, the profile passes
// around each frontal face, and dlib's detector when the build has it.
#include "core/detect/face_detector.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "core/detect/initialisation.hpp"
#include "tests/support/fit_fixture.hpp"
#include "tests/support/test_support.hpp"
#include "tests/unit/detect/detect_scenes.hpp"

namespace clm3d {
namespace {

TEST(FaceBoxes, IouAndSuppression) {
  EXPECT_DOUBLE_EQ(boxIou({0, 0, 10, 10}, {0, 0, 10, 10}), 1.0);
  EXPECT_DOUBLE_EQ(boxIou({0, 0, 10, 10}, {5, 0, 10, 10}), 50.0 / 150.0);
  EXPECT_DOUBLE_EQ(boxIou({0, 0, 10, 10}, {20, 20, 5, 5}), 0.0);
  EXPECT_DOUBLE_EQ(boxIou({0, 0, 0, 0}, {0, 0, 0, 0}), 0.0);

  std::vector<FaceBox> boxes(4);
  boxes[0].box = {0, 0, 100, 100};
  boxes[0].score = 3;
  boxes[1].box = {10, 5, 100, 100};  // overlaps 0 (IoU 0.75) with a better score
  boxes[1].score = 9;
  boxes[2].box = {300, 0, 50, 50};  // apart from the others
  boxes[2].score = 9;
  boxes[3].box = {40, 40, 30, 30};  // inside 0 and 1 (small IoU) with the best score
  boxes[3].score = 20;
  const std::vector<FaceBox> kept = suppressOverlaps(boxes, 0.3);
  ASSERT_EQ(kept.size(), 2u);
  EXPECT_EQ(kept[0].box, boxes[3].box);  // best score first; the boxes around it go
  EXPECT_EQ(kept[1].box, boxes[2].box);
  // At equal scores the larger box ranks first.
  std::vector<FaceBox> tie = {boxes[2], boxes[1]};
  EXPECT_EQ(suppressOverlaps(tie, 0.3).front().box, boxes[1].box);
}

TEST(FaceBoxes, TheFacesAtAPointComeFirstInTheirOrder) {
  std::vector<FaceBox> faces(4);
  faces[0].box = {0, 0, 100, 100};    // elsewhere
  faces[1].box = {200, 0, 100, 100};  // holds the point
  faces[2].box = {400, 0, 100, 100};  // elsewhere
  faces[3].box = {180, 20, 60, 60};   // holds it too
  const std::vector<FaceBox> ranked = preferFacesAt(faces, cv::Point2d(220, 50));
  ASSERT_EQ(ranked.size(), 4u);
  EXPECT_EQ(ranked[0].box, faces[1].box);
  EXPECT_EQ(ranked[1].box, faces[3].box);
  EXPECT_EQ(ranked[2].box, faces[0].box);
  EXPECT_EQ(ranked[3].box, faces[2].box);
  // No face there: the detector's order stands.
  const std::vector<FaceBox> unchanged = preferFacesAt(faces, cv::Point2d(700, 700));
  for (std::size_t i = 0; i < faces.size(); ++i) EXPECT_EQ(unchanged[i].box, faces[i].box);
}

TEST(FaceDetector, MissingCascadeNamesTheFileAndThePackage) {
  const test::TempDir empty;
  try {
    FaceDetector detector(DetectorKind::Cascade, {}, empty.path());
    FAIL() << "no cascade files, but no error";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("haarcascade_frontalface_alt2.xml"), std::string::npos) << message;
    EXPECT_NE(message.find("install opencv-data"), std::string::npos) << message;
  }
  test::writeFile(empty / "broken.xml", "<opencv_storage>nothing</opencv_storage>\n");
  FaceDetectorSettings settings;
  settings.frontalCascade = (empty / "broken.xml").string();
  settings.profiles = false;
  EXPECT_THROW(FaceDetector(DetectorKind::Cascade, settings), InputError);
  settings = {};
  settings.minNeighbours = 0;
  EXPECT_THROW(FaceDetector(DetectorKind::Cascade, settings), InputError);
  EXPECT_EQ(parseDetectorKind("dlib"), DetectorKind::DlibHog);
  EXPECT_THROW(parseDetectorKind("hog"), InputError);
}

// The registry (core/detect/face_detector.cpp) is the one list: every name parses back to a kind
// that has that name, the unknown name's error lists them all, and the detectors this build can
// make are the registered ones FaceDetector::available says yes to, the cascade always among them.
TEST(FaceDetector, TheRegistryNamesParsesAndListsTheDetectors) {
  ASSERT_EQ(detectorNames(), (std::vector<std::string>{"cascade", "dlib"}));
  for (const std::string& name : detectorNames()) {
    EXPECT_EQ(detectorKindName(parseDetectorKind(name)), name);
  }
  try {
    parseDetectorKind("hog");
    ADD_FAILURE() << "no error";
  } catch (const InputError& error) {
    for (const std::string& name : detectorNames()) {
      EXPECT_TRUE(test::contains(error.what(), name)) << error.what();
    }
  }
  const std::vector<DetectorKind> available = availableDetectors();
  ASSERT_FALSE(available.empty());
  EXPECT_EQ(available.front(), DetectorKind::Cascade);
  for (const std::string& name : detectorNames()) {
    const DetectorKind kind = parseDetectorKind(name);
    EXPECT_EQ(std::count(available.begin(), available.end(), kind) == 1,
              FaceDetector::available(kind))
        << name;
  }
}

TEST(FaceDetector, BlankImageHasNoFace) {
  FaceDetector detector;
  const cv::Mat blank(240, 320, CV_8UC3, cv::Scalar(128, 128, 128));
  EXPECT_TRUE(detector.detect(blank).empty());
  const Camera camera = Camera::fromVerticalFov(320, 240, 45.0);
  try {
    initialiseFromImage(test::fitTestModel(), camera, blank, detector);
    FAIL() << "no NoFaceFound";
  } catch (const NoFaceFound& e) {
    EXPECT_NE(std::string(e.what()).find("no face found"), std::string::npos) << e.what();
  }
  EXPECT_THROW(detector.detect(cv::Mat()), InputError);
  EXPECT_THROW(detector.detect(cv::Mat(240, 320, CV_32FC1, cv::Scalar(0.5))), InputError);
  // The camera must describe the image.
  EXPECT_THROW(initialiseFromImage(test::fitTestModel(), Camera::fromVerticalFov(640, 480, 45.0),
                                   blank, detector),
               InputError);
}

// The held-out procedural head (no fixture model saw it) in a 640x480 frame.
test::Scene heldOutScene(double yawDeg) {
  const SynthHead& head = test::fitTestHeads()[test::kHeldOutHead];
  OffscreenRenderer renderer(head.mesh);
  return test::renderScene(renderer, head.landmarks, test::sceneCamera(), 0.0, yawDeg, 0.0,
                           {330.0, 220.0}, 55.0, 7);
}

// Mean distance of the start's points to the truth over the landmarks a detector box can place
// (all but the earlobes), in units of the frontal eye distance.
double startError(const ClmModel& model, const test::Scene& scene, const FitState& start) {
  const Eigen::Matrix2Xd points = projectState(model, test::sceneCamera(), start);
  std::vector<bool> use(25, true);
  use[18] = use[24] = false;
  return test::meanPointError(points, scene.truth, use) / scene.iodFrontal;
}

TEST(FaceDetector, CascadeFindsARenderedHeadAndTheStartIsNear) {
  const ClmModel& model = test::fitTestModel();
  const test::Scene scene = heldOutScene(0.0);
  FaceDetector detector;
  const std::vector<FaceBox> faces = detector.detect(scene.bgr);
  ASSERT_FALSE(faces.empty());
  const FaceBox& best = faces.front();
  EXPECT_TRUE(best.box.contains({scene.eyeMid.x(), scene.eyeMid.y()}));
  EXPECT_FALSE(best.profile);
  EXPECT_EQ(best.detector, DetectorKind::Cascade);
  const FitState start = initialiseFromImage(model, test::sceneCamera(), scene.bgr, detector);
  EXPECT_LT(startError(model, scene, start), 0.2);

  // Searched at half size, the box comes back in input pixels, about where it was.
  FaceDetectorSettings settings;
  settings.maxImageSide = 320;
  settings.profiles = false;
  FaceDetector reduced(DetectorKind::Cascade, settings);
  const std::vector<FaceBox> halved = reduced.detect(scene.bgr);
  ASSERT_FALSE(halved.empty());
  EXPECT_GT(boxIou(halved.front().box, best.box), 0.7) << halved.front().box << " vs " << best.box;
  settings.maxImageSide = 10;
  EXPECT_THROW(FaceDetector(DetectorKind::Cascade, settings), InputError);
}

// A head tilted 35 degrees, beyond what the detectors find upright, is found in a copy of the
// frame turned upright; the box comes back around the face with its tilt, and the start placed
// from it is tilted too and near the truth.
TEST(FaceDetector, ATiltedHeadIsFoundInATurnedCopyAndStartsTilted) {
  const ClmModel& model = test::fitTestModel();
  const SynthHead& head = test::fitTestHeads()[test::kHeldOutHead];
  OffscreenRenderer renderer(head.mesh);
  const test::Scene scene = test::renderScene(renderer, head.landmarks, test::sceneCamera(), 0.0,
                                              0.0, 35.0, {330.0, 230.0}, 55.0, 7);
  FaceDetector detector;
  const std::vector<FaceBox> turned = detector.detectTurned(scene.bgr, -35.0);
  ASSERT_FALSE(turned.empty());
  const FaceBox& best = turned.front();
  EXPECT_EQ(best.rollDeg, 35.0);
  EXPECT_TRUE(best.box.contains({scene.eyeMid.x(), scene.eyeMid.y()})) << best.box;
  const FitState start = stateFromBox(model, test::sceneCamera(), best);
  EXPECT_NEAR(degrees(start.pose.roll), 35.0, 1e-9);
  EXPECT_LT(startError(model, scene, start), 0.2);
  // The same box placed upright starts much further off.
  FaceBox upright = best;
  upright.rollDeg = 0.0;
  EXPECT_GT(startError(model, scene, stateFromBox(model, test::sceneCamera(), upright)),
            startError(model, scene, start) + 0.1);
  // Turned the other way the head is at 70 degrees: no box near it is upright enough.
  for (const FaceBox& face : detector.detectTurned(scene.bgr, 35.0)) {
    EXPECT_FALSE(face.box.contains({scene.eyeMid.x(), scene.eyeMid.y()}) && !face.profile)
        << face.box;
  }
}

TEST(FaceDetector, ProfileCascadeSaysWhichWayTheHeadTurns) {
  const ClmModel& model = test::fitTestModel();
  FaceDetector detector;
  for (const double yaw : {-50.0, 50.0}) {
    const test::Scene scene = heldOutScene(yaw);
    const std::vector<FaceBox> faces = detector.detect(scene.bgr);
    ASSERT_FALSE(faces.empty()) << "yaw " << yaw;
    const FaceBox& best = faces.front();
    EXPECT_TRUE(best.box.contains({scene.eyeMid.x(), scene.eyeMid.y()})) << "yaw " << yaw;
    EXPECT_TRUE(best.profile) << "yaw " << yaw;
    // OpenCV's profile cascade finds heads turned towards the image's left (negative yaw); the
    // other side is found on the mirrored image.
    EXPECT_EQ(best.mirrored, yaw > 0.0) << "yaw " << yaw;
    const FitState start = stateFromBox(model, test::sceneCamera(), best);
    EXPECT_GT(start.pose.yaw * yaw, 0.0) << "yaw " << yaw;
    EXPECT_LT(startError(model, scene, start), 0.3) << "yaw " << yaw;
  }
}

// A head turned 75 degrees each way, cropped close as AFLW's faces are (120x120, the face's
// points filling most of it, the back of the head cut off): the detector finds it with a profile
// box on the right side (the border search, the profile cascades on image and mirror with one raw
// detection each, docs/initialisation.md "Side views").
TEST(FaceDetector, FindsARenderedProfileHeadCroppedCloseOnBothSides) {
  FaceDetector detector;
  for (const double yaw : {-75.0, 75.0}) {
    const test::Scene scene = heldOutScene(yaw);
    const Eigen::Vector2d low = scene.truth.rowwise().minCoeff();
    const Eigen::Vector2d high = scene.truth.rowwise().maxCoeff();
    const Eigen::Vector2d centre = 0.5 * (low + high);
    const double side = 1.1 * (high - low).maxCoeff();
    const cv::Rect crop(static_cast<int>(centre.x() - side / 2),
                        static_cast<int>(centre.y() - side / 2), static_cast<int>(side),
                        static_cast<int>(side));
    cv::Mat small;
    cv::resize(scene.bgr(crop), small, cv::Size(120, 120), 0, 0, cv::INTER_AREA);
    const double scale = 120.0 / side;
    const cv::Point2d middle((centre.x() - crop.x) * scale, (centre.y() - crop.y) * scale);
    const std::vector<FaceBox> faces = detector.detect(small);
    ASSERT_FALSE(faces.empty()) << "yaw " << yaw;
    const FaceBox& best = faces.front();
    EXPECT_TRUE(best.box.contains(middle)) << "yaw " << yaw << " box " << best.box;
    EXPECT_TRUE(best.profile) << "yaw " << yaw;
    EXPECT_EQ(best.mirrored, yaw > 0.0) << "yaw " << yaw;
  }
}

// Where the frontal cascade finds faces, the profile passes search only around them: with a
// frontal head and a head turned +50 degrees side by side, each keeps its own kind of box (the
// turned one its mirrored profile box, found in the region of its weaker frontal box), as when
// the profile passes search the whole image.
TEST(FaceDetector, ProfilePassesSearchAroundEachFrontalFace) {
  const test::Scene frontal = heldOutScene(0.0);
  const test::Scene turned = heldOutScene(50.0);
  // The middle 320 columns of each 640x480 frame, side by side.
  const int from = 170;
  const int width = 320;
  cv::Mat pair(frontal.bgr.rows, 2 * width, CV_8UC3);
  frontal.bgr.colRange(from, from + width).copyTo(pair.colRange(0, width));
  turned.bgr.colRange(from, from + width).copyTo(pair.colRange(width, 2 * width));
  const cv::Point2d frontalEyes(frontal.eyeMid.x() - from, frontal.eyeMid.y());
  const cv::Point2d turnedEyes(turned.eyeMid.x() - from + width, turned.eyeMid.y());

  for (const bool everywhere : {false, true}) {
    FaceDetectorSettings settings;
    settings.profilesEverywhere = everywhere;
    FaceDetector detector(DetectorKind::Cascade, settings);
    const std::vector<FaceBox> faces = detector.detect(pair);
    const auto at = [&faces](const cv::Point2d& eyes) {
      const auto it = std::find_if(faces.begin(), faces.end(),
                                   [&eyes](const FaceBox& f) { return f.box.contains(eyes); });
      return it == faces.end() ? nullptr : &*it;
    };
    const FaceBox* left = at(frontalEyes);
    const FaceBox* right = at(turnedEyes);
    ASSERT_NE(left, nullptr) << "everywhere " << everywhere;
    ASSERT_NE(right, nullptr) << "everywhere " << everywhere;
    EXPECT_FALSE(left->profile) << "everywhere " << everywhere;
    EXPECT_TRUE(right->profile) << "everywhere " << everywhere;
    EXPECT_TRUE(right->mirrored) << "everywhere " << everywhere;
  }
}

TEST(FaceDetector, AFaceBothDetectorsCallFrontalGetsNoProfilePass) {
  if (!FaceDetector::available(DetectorKind::DlibHog)) GTEST_SKIP() << "built without dlib";
  const test::Scene frontal = heldOutScene(0.0);
  const cv::Point2d eyes(frontal.eyeMid.x(), frontal.eyeMid.y());
  std::vector<FaceBox> firsts;
  for (const bool agreement : {true, false}) {
    FaceDetectorSettings settings;
    settings.dlibAgreement = agreement;
    FaceDetector detector(DetectorKind::Cascade, settings);
    const std::vector<FaceBox> faces = detector.detect(frontal.bgr);
    ASSERT_FALSE(faces.empty()) << "agreement " << agreement;
    EXPECT_TRUE(faces.front().box.contains(eyes)) << "agreement " << agreement;
    EXPECT_FALSE(faces.front().profile) << "agreement " << agreement;
    // Without dlib's word the profile passes search around the frontal box.
    EXPECT_EQ(detector.profileRegionsSearched(), agreement ? 0 : 1);
    firsts.push_back(faces.front());
  }
  EXPECT_EQ(firsts[0].box, firsts[1].box);  // the same frontal box either way
}

TEST(FaceDetector, DlibFindsARenderedHeadWhenBuiltWithDlib) {
  if (!FaceDetector::available(DetectorKind::DlibHog)) {
    try {
      FaceDetector detector(DetectorKind::DlibHog);
      FAIL() << "dlib detector made without dlib";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("without dlib"), std::string::npos) << e.what();
    }
    GTEST_SKIP() << "clm3d was built without dlib";
  }
  const ClmModel& model = test::fitTestModel();
  const test::Scene scene = heldOutScene(0.0);
  FaceDetectorSettings settings;
  settings.minFaceSize = 80;  // dlib's own window: no image doubling, fast
  FaceDetector detector(DetectorKind::DlibHog, settings);
  const std::vector<FaceBox> faces = detector.detect(scene.bgr);
  ASSERT_FALSE(faces.empty());
  EXPECT_TRUE(faces.front().box.contains({scene.eyeMid.x(), scene.eyeMid.y()}));
  EXPECT_EQ(faces.front().detector, DetectorKind::DlibHog);
  const FitState start = stateFromBox(model, test::sceneCamera(), faces.front());
  EXPECT_LT(startError(model, scene, start), 0.2);
  EXPECT_TRUE(detector.detect(cv::Mat(240, 320, CV_8UC1, cv::Scalar(90))).empty());
}

}  // namespace
}  // namespace clm3d
