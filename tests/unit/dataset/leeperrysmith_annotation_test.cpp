// Checks of the committed thesis25 annotation of the Lee Perry-Smith scan
// (tests/fixtures/leeperrysmith; how it was made: docs/annotations.md): exactly the points the
// README lists are missing (the eyes are closed), the placed ones lie on the mesh, left/right
// pairs mirror each other, sizes are plausible once the file's units are scaled to millimetres,
// and a manifest with both real scans loads with level eyes. Checks that need ../shared/data
// skip with a message without it.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <array>
#include <cmath>
#include <nlohmann/json.hpp>
#include <set>
#include <utility>

#include "core/dataset/manifest.hpp"
#include "core/dataset/training_subjects.hpp"
#include "core/mesh/mesh_distance.hpp"
#include "core/mesh/mesh_import.hpp"
#include "core/scheme/landmark_file.hpp"
#include "core/scheme/scheme.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

using Eigen::Vector3d;

// The file's units are about 50 mm (README of the fixture); resources/datasets/scans.json says so.
constexpr double kMmPerUnit = 50.0;
// thesis25, 0-based.
constexpr int kLeftOuter = 1, kRightOuter = 2, kLpsLeftEye = 7, kLeftInner = 8, kRightInner = 9,
              kLpsRightEye = 10;
constexpr std::array<std::pair<int, int>, 9> kPlacedPairs = {
    {{1, 2}, {3, 6}, {4, 5}, {8, 9}, {12, 13}, {14, 15}, {18, 24}, {19, 23}, {20, 22}}};
constexpr std::array<int, 5> kMidline = {0, 11, 16, 17, 21};

std::filesystem::path fixture() {
  return test::fixturePath("leeperrysmith/leeperrysmith.thesis25.ljson");
}

// The fixture in millimetres (file coordinates times the scale).
LandmarkSet readLeeMm() {
  LandmarkSet points = readLandmarks(fixture(), &Scheme::thesis25());
  for (int i = 0; i < points.size(); ++i) {
    if (points.has(i)) points.set(i, Vector3d(kMmPerUnit * points.point(i)));
  }
  return points;
}

TEST(LeePerrySmithAnnotation, MissingAreExactlyTheEyeCentresTheReadmeLists) {
  const LandmarkSet lee = readLandmarks(fixture(), &Scheme::thesis25());
  ASSERT_EQ(lee.size(), 25);
  EXPECT_EQ(lee.dims(), 3);
  std::set<int> missing;
  for (int i = 0; i < lee.size(); ++i) {
    if (!lee.has(i)) missing.insert(i);
  }
  EXPECT_EQ(missing, (std::set<int>{kLpsLeftEye, kLpsRightEye}));
  // The README names them (1-based, as in the thesis table) in its list of missing points.
  const std::string readme = test::readFile(test::fixturePath("leeperrysmith/README.md"));
  EXPECT_NE(readme.find("Missing: 8 (centre of left eye) and 11 (centre of right eye)"),
            std::string::npos);
}

TEST(LeePerrySmithAnnotation, LeftRightPairsMirrorAndSizesArePlausible) {
  const LandmarkSet lee = readLeeMm();
  // Mid-plane from the placed pairs: normal towards the subject's left, through the midpoints.
  Vector3d normal = Vector3d::Zero();
  Vector3d centre = Vector3d::Zero();
  for (const auto& [l, r] : kPlacedPairs) {
    normal += lee.point(l) - lee.point(r);
    centre += 0.5 * (lee.point(l) + lee.point(r));
  }
  normal.normalize();
  centre /= static_cast<double>(kPlacedPairs.size());
  const auto side = [&](const Vector3d& p) { return normal.dot(p - centre); };
  EXPECT_GT(normal.x(), 0.95);  // +x is the subject's left, the head is square to the axes
  for (const auto& [l, r] : kPlacedPairs) {
    EXPECT_GT(side(lee.point(l)), 3.0) << l;  // each on its own side of the plane
    EXPECT_LT(side(lee.point(r)), -3.0) << r;
    const Vector3d mirrored = lee.point(r) - 2.0 * side(lee.point(r)) * normal;
    EXPECT_LT((mirrored - lee.point(l)).norm(), 10.0) << "pair " << l + 1 << "/" << r + 1;
  }
  for (const int m : kMidline) EXPECT_LT(std::abs(side(lee.point(m))), 5.0) << m + 1;
  const double outerCorners = (lee.point(kLeftOuter) - lee.point(kRightOuter)).norm();
  EXPECT_GT(outerCorners, 80.0);
  EXPECT_LT(outerCorners, 110.0);
  const double innerCorners = (lee.point(kLeftInner) - lee.point(kRightInner)).norm();
  EXPECT_GT(innerCorners, 24.0);
  EXPECT_LT(innerCorners, 42.0);
}

TEST(LeePerrySmithAnnotation, PlacedPointsLieOnTheMeshSurface) {
  CLM3D_REQUIRE_SHARED_DATA(data);
  const TexturedMesh mesh = loadTexturedMesh(data / "scans/leeperrysmith/leeperrysmith.obj");
  const LandmarkSet lee = readLandmarks(fixture(), &Scheme::thesis25());
  for (int i = 0; i < lee.size(); ++i) {
    if (!lee.has(i)) continue;
    EXPECT_LT(kMmPerUnit * nearestSurfacePoint(mesh, lee.point(i)).distance, 0.5) << i + 1;
  }
}

TEST(LeePerrySmithAnnotation, ShippedManifestScalesTheScanToMillimetres) {
  const nlohmann::json manifest = nlohmann::json::parse(
      test::readFile(test::fixturePath("../../resources/datasets/scans.json")));
  bool found = false;
  for (const auto& scan : manifest.at("scans")) {
    if (scan.at("subject") != "leeperrysmith") continue;
    found = true;
    EXPECT_DOUBLE_EQ(scan.at("scale").get<double>(), kMmPerUnit);
  }
  EXPECT_TRUE(found);
}

// Both real scans through a manifest like resources/datasets/scans.json: in millimetres, centred
// on landmark 1, levelled - Lee Perry-Smith on the midpoints of his eye corners, the eye centres
// being missing.
TEST(LeePerrySmithAnnotation, ManifestWithBothScansLoadsLevelled) {
  CLM3D_REQUIRE_SHARED_DATA(data);
  test::TempDir dir;
  test::writeFile(dir / "m.json",
                  R"({"version": 1, "scans": [
      {"mesh": ")" + (data / "scans/james/james.obj").string() +
                      R"(", "landmarks": ")" +
                      test::fixturePath("james/james.thesis25.ljson").string() +
                      R"(", "subject": "james"},
      {"mesh": ")" + (data / "scans/leeperrysmith/leeperrysmith.obj").string() +
                      R"(", "landmarks": ")" + fixture().string() +
                      R"(", "subject": "leeperrysmith", "scale": 50}]})");
  const auto subjects = loadTexturedSubjects(loadManifest(dir / "m.json"), 2);
  ASSERT_EQ(subjects.size(), 2u);
  const TexturedSubject& james = subjects[0];
  const TexturedSubject& lee = subjects[1];
  EXPECT_EQ(lee.id, "leeperrysmith/neutral");
  EXPECT_NEAR(james.landmarks.point(kLpsLeftEye).y(), james.landmarks.point(kLpsRightEye).y(),
              1e-6);

  EXPECT_EQ(lee.landmarks.presentCount(), 23);
  EXPECT_FALSE(lee.landmarks.has(kLpsLeftEye));
  EXPECT_FALSE(lee.landmarks.has(kLpsRightEye));
  EXPECT_LT(lee.landmarks.point(0).norm(), 1e-9);
  const Vector3d left = 0.5 * (lee.landmarks.point(kLeftOuter) + lee.landmarks.point(kLeftInner));
  const Vector3d right =
      0.5 * (lee.landmarks.point(kRightOuter) + lee.landmarks.point(kRightInner));
  EXPECT_NEAR(left.y(), right.y(), 1e-6);
  EXPECT_NEAR(left.z(), right.z(), 1e-6);
  EXPECT_GT(left.x(), right.x());
  EXPECT_GT((left - right).norm(), 50.0);  // eye-corner midpoints: about the inter-pupil distance
  EXPECT_LT((left - right).norm(), 75.0);
  EXPECT_GT(lee.landmarks.point(11).z(), 10.0);   // the nose tip is in front
  EXPECT_LT(lee.landmarks.point(21).y(), -80.0);  // the chin is below
  // The mesh was scaled with the landmarks: the nose tip is the front of the mesh, and the head,
  // neck and shoulders span a few decimetres.
  EXPECT_NEAR(lee.mesh.bounds().max().z(), lee.landmarks.point(11).z(), 5.0);
  const Eigen::Vector3f size = lee.mesh.bounds().sizes();
  EXPECT_GT(size.x(), 300.0f);
  EXPECT_LT(size.x(), 600.0f);
}

}  // namespace
}  // namespace clm3d
