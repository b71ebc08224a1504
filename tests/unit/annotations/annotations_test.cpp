// Checks of the committed thesis25 annotations of the shared data (tests/fixtures/james,
// tests/fixtures/ict-facekit; how they were made: docs/annotations.md): the points lie on the
// meshes, agree with the iBUG 68 conversion where they come from it, are left/right consistent
// and of a plausible size. Checks that need ../shared/data skip with a message without it.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "core/mesh/mesh_distance.hpp"
#include "core/mesh/mesh_import.hpp"
#include "core/mesh/textured_mesh.hpp"
#include "core/scheme/ibug68_conversion.hpp"
#include "core/scheme/landmark_file.hpp"
#include "core/scheme/landmark_set.hpp"
#include "core/scheme/scheme.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

using Eigen::Vector3d;

constexpr int kPoints = 25;
// Thesis25 indices (0-based) used below.
constexpr int kMidEyes = 0;
constexpr int kLeftEyeCentre = 7;
constexpr int kRightEyeCentre = 10;
constexpr int kLeftMouthCorner = 14;
constexpr int kRightMouthCorner = 15;
constexpr int kLeftEarlobe = 18;
constexpr int kLeftCheek = 19;
constexpr int kRightCheek = 23;
constexpr int kRightEarlobe = 24;
// (left, right) mirror pairs and mid-line points of the thesis scheme (DESIGN.md, 0-based).
constexpr std::array<std::pair<int, int>, 10> kMirrorPairs = {
    {{1, 2}, {3, 6}, {4, 5}, {7, 10}, {8, 9}, {12, 13}, {14, 15}, {18, 24}, {19, 23}, {20, 22}}};
constexpr std::array<int, 5> kMidline = {0, 11, 16, 17, 21};
// Points whose 3D position is derived (a mean of iBUG points, then moved onto the surface).
constexpr std::array<int, 3> kDerived = {kMidEyes, kLeftEyeCentre, kRightEyeCentre};

std::filesystem::path jamesFixture() {
  return test::fixturePath("james/james.thesis25.ljson");
}
std::filesystem::path ictFixture() {
  return test::fixturePath("ict-facekit/thesis25_vertices.json");
}

// A mid-sagittal plane fitted to mirror pairs: unit normal towards the subject's left (mean of
// left - right), through the mean of the pair midpoints.
struct MidPlane {
  Vector3d normal;
  double offset;  // signed distance = normal.dot(p) + offset
  double signedDistance(const Vector3d& p) const { return normal.dot(p) + offset; }
};

MidPlane fitMidPlane(const std::vector<Vector3d>& points) {
  Vector3d n = Vector3d::Zero();
  Vector3d centre = Vector3d::Zero();
  int count = 0;
  for (const auto& [l, r] : kMirrorPairs) {
    n += points[l] - points[r];
    centre += 0.5 * (points[l] + points[r]);
    ++count;
  }
  n.normalize();
  centre /= count;
  return {n, -n.dot(centre)};
}

// Reflection of p in the plane.
Vector3d reflect(const MidPlane& plane, const Vector3d& p) {
  return p - 2.0 * plane.signedDistance(p) * plane.normal;
}

std::vector<Vector3d> toVector(const LandmarkSet& set) {
  std::vector<Vector3d> out;
  for (int i = 0; i < set.size(); ++i) {
    out.push_back(set.has(i) ? set.point(i) : Vector3d::Constant(std::nan("")));
  }
  return out;
}

// ---------------------------------------------------------------------------------------------
// james (menpo3d's scan): millimetres, +x = subject's left, +y up, +z out of the face; the face
// is turned about 6 degrees towards the subject's right (README in the fixture folder).

LandmarkSet readJames() {
  return readLandmarks(jamesFixture(), &Scheme::thesis25());
}

TEST(JamesAnnotation, HasAll25Points3D) {
  const auto points = readJames();
  ASSERT_EQ(points.size(), kPoints);
  EXPECT_EQ(points.dims(), 3);
  for (int i = 0; i < kPoints; ++i) EXPECT_TRUE(points.has(i)) << "thesis point " << i;
}

TEST(JamesAnnotation, MirrorPairsAreOnOppositeSidesOfTheMidPlane) {
  const auto p = toVector(readJames());
  const MidPlane plane = fitMidPlane(p);
  // The subject's left is +x in james's coordinates.
  EXPECT_GT(plane.normal.x(), 0.95);
  for (const auto& [l, r] : kMirrorPairs) {
    const double dl = plane.signedDistance(p[l]), dr = plane.signedDistance(p[r]);
    EXPECT_GT(dl, 5.0) << "left point " << l << " not on the subject's left";
    EXPECT_LT(dr, -5.0) << "right point " << r << " not on the subject's right";
    // A real face is not exactly symmetric, and the points come from hand-placed iBUG points:
    // the mirror image of a left point lies within 6 mm of its right partner.
    EXPECT_LT((reflect(plane, p[l]) - p[r]).norm(), 6.0) << "pair " << l << "/" << r;
  }
  for (const int m : kMidline) {
    EXPECT_LT(std::abs(plane.signedDistance(p[m])), 3.0) << "mid-line point " << m;
  }
}

TEST(JamesAnnotation, InterOcularDistanceIsPlausibleInMillimetres) {
  const auto p = toVector(readJames());
  const double iod = (p[kLeftEyeCentre] - p[kRightEyeCentre]).norm();
  EXPECT_GT(iod, 55.0);
  EXPECT_LT(iod, 75.0);
}

TEST(JamesAnnotation, PointsLieOnTheMeshSurface) {
  CLM3D_REQUIRE_SHARED_DATA(dataDir);
  const auto mesh = loadTexturedMesh(dataDir / "scans/james/james.obj", MeshLoadOptions{});
  ASSERT_GT(mesh.bounds().sizes().maxCoeff(), 100.0f) << "james should be in millimetres";
  const auto p = toVector(readJames());
  for (int i = 0; i < kPoints; ++i) {
    EXPECT_LT(nearestSurfacePoint(mesh, p[i]).distance, 1.0)
        << "thesis point " << i << " is off the surface";
  }
}

TEST(JamesAnnotation, AgreesWithTheIbug68Conversion) {
  CLM3D_REQUIRE_SHARED_DATA(dataDir);
  // james.ljson is in landmarker.io's label order; readLandmarks puts it in iBUG order.
  const auto ibug = readLandmarks(dataDir / "scans/james/james.ljson", &Scheme::ibug68());
  ASSERT_EQ(ibug.size(), 68);
  const auto converted = ibug68ToThesis25(ibug);
  const auto annotated = readJames();
  const auto p = toVector(annotated);
  // The face's frontal direction: normal to the left-right axis and to the scan's up (+y).
  const MidPlane plane = fitMidPlane(p);
  const Vector3d front = plane.normal.cross(Vector3d::UnitY()).normalized();
  EXPECT_GT(front.z(), 0.95) << "james should face +z";

  for (int i = 0; i < kPoints; ++i) {
    if (!converted.has(i)) {
      EXPECT_TRUE(i == kLeftEarlobe || i == kRightEarlobe) << "no iBUG counterpart for " << i;
      continue;
    }
    const Vector3d offset = p[i] - converted.point(i);
    const bool derived = std::find(kDerived.begin(), kDerived.end(), i) != kDerived.end();
    if (!derived) {
      EXPECT_LT(offset.norm(), 1e-3) << "thesis point " << i << " should be its iBUG point";
      continue;
    }
    // Derived points were moved onto the surface along the frontal direction only: the move is
    // along `front` (up to 1 mm sideways), forwards, and at most the depth of the nasal bridge
    // in front of the inner eye corners.
    const double along = offset.dot(front);
    EXPECT_GE(along, -0.5) << "thesis point " << i;
    EXPECT_LT(along, 25.0) << "thesis point " << i;
    EXPECT_LT((offset - along * front).norm(), 1.0) << "thesis point " << i;
  }
}

// ---------------------------------------------------------------------------------------------
// ICT-FaceKit: vertex indices into generic_neutral_mesh.obj (centimetres, +x = subject's left,
// +y up, +z out of the face, symmetric about x = 0).

constexpr int kIctVertexCount = 26719;
constexpr int kIctFaceAreaEnd = 9409;                             // face area [0, 9408]
constexpr std::pair<int, int> kIctLeftEyeball = {21451, 23021};   // [first, end)
constexpr std::pair<int, int> kIctRightEyeball = {23021, 24591};  // [first, end)

std::vector<int> readIctIndices() {
  const auto json = nlohmann::json::parse(test::readFile(ictFixture()));
  EXPECT_EQ(json.at("scheme").get<std::string>(), "thesis25");
  return json.at("vertices").get<std::vector<int>>();
}

// The "v x y z" lines of an OBJ, in file order: the ICT indices refer to these, whereas a mesh
// importer may split or reorder vertices.
std::vector<Vector3d> readObjVertices(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::vector<Vector3d> vertices;
  std::string line;
  while (std::getline(in, line)) {
    if (line.size() < 2 || line[0] != 'v' || line[1] != ' ') continue;
    std::istringstream fields(line.substr(2));
    Vector3d v;
    fields >> v.x() >> v.y() >> v.z();
    vertices.push_back(v);
  }
  return vertices;
}

// The 68 vertex indices listed in the ICT-FaceKit README ("Multi-PIE 68 point ... indices:").
std::vector<int> readIctReadmeIbug68(const std::filesystem::path& readme) {
  const std::string text = test::readFile(readme);
  const auto heading = text.find("Multi-PIE 68 point facial landmarks indices");
  if (heading == std::string::npos) return {};
  std::size_t pos = text.find('\n', heading);
  std::vector<int> indices;
  while (pos < text.size() && indices.size() < 68) {
    const auto digit = text.find_first_of("0123456789", pos);
    if (digit == std::string::npos) break;
    std::size_t end = 0;
    indices.push_back(std::stoi(text.substr(digit, 12), &end));
    pos = digit + end;
  }
  return indices;
}

TEST(IctAnnotation, IndicesAreInRangeAndOnTheFaceOrEyeballs) {
  const auto indices = readIctIndices();
  ASSERT_EQ(static_cast<int>(indices.size()), kPoints);
  for (int i = 0; i < kPoints; ++i) {
    const int v = indices[i];
    ASSERT_GE(v, 0) << "thesis point " << i << " has no vertex";
    ASSERT_LT(v, kIctVertexCount) << "thesis point " << i;
    if (i == kLeftEyeCentre) {
      EXPECT_TRUE(v >= kIctLeftEyeball.first && v < kIctLeftEyeball.second) << v;
    } else if (i == kRightEyeCentre) {
      EXPECT_TRUE(v >= kIctRightEyeball.first && v < kIctRightEyeball.second) << v;
    } else {
      EXPECT_LT(v, kIctFaceAreaEnd) << "thesis point " << i << " is not a face-area vertex";
    }
  }
}

class IctNeutral : public ::testing::Test {
 protected:
  void load(const std::filesystem::path& dataDir) {
    vertices_ = readObjVertices(dataDir / "morphable/ict-facekit/generic_neutral_mesh.obj");
    ASSERT_EQ(static_cast<int>(vertices_.size()), kIctVertexCount);
    indices_ = readIctIndices();
    ASSERT_EQ(static_cast<int>(indices_.size()), kPoints);
    for (const int v : indices_) points_.push_back(vertices_.at(v));
  }
  std::vector<Vector3d> vertices_;
  std::vector<int> indices_;
  std::vector<Vector3d> points_;
};

TEST_F(IctNeutral, IsSymmetricAboutTheMidPlane) {
  CLM3D_REQUIRE_SHARED_DATA(dataDir);
  load(dataDir);
  const auto& p = points_;
  const MidPlane plane = fitMidPlane(p);
  EXPECT_GT(plane.normal.x(), 0.999) << "the subject's left should be +x";
  for (const auto& [l, r] : kMirrorPairs) {
    EXPECT_GT(plane.signedDistance(p[l]), 0.5) << "left point " << l;
    EXPECT_LT(plane.signedDistance(p[r]), -0.5) << "right point " << r;
    // The neutral mesh is symmetric: mirror partners agree to 1 mm (0.1 cm).
    EXPECT_LT((reflect(plane, p[l]) - p[r]).norm(), 0.1) << "pair " << l << "/" << r;
  }
  for (const int m : kMidline) {
    EXPECT_LT(std::abs(plane.signedDistance(p[m])), 0.1) << "mid-line point " << m;
  }
}

TEST_F(IctNeutral, SizesArePlausibleInCentimetres) {
  CLM3D_REQUIRE_SHARED_DATA(dataDir);
  load(dataDir);
  const auto& p = points_;
  const double iod = (p[kLeftEyeCentre] - p[kRightEyeCentre]).norm();
  EXPECT_GT(iod, 5.5);
  EXPECT_LT(iod, 7.5);
  // Eye centres sit on the eye surface between the lids: not behind the eye corners' plane by
  // more than a few millimetres, and between the corners left to right.
  EXPECT_GT(p[kLeftEyeCentre].x(), p[8].x());
  EXPECT_LT(p[kLeftEyeCentre].x(), p[1].x());
  EXPECT_LT(p[kRightEyeCentre].x(), p[9].x());
  EXPECT_GT(p[kRightEyeCentre].x(), p[2].x());
  // Cheeks at mouth-corner height (within 5 mm), earlobes the most lateral points.
  const double mouthY = 0.5 * (p[kLeftMouthCorner].y() + p[kRightMouthCorner].y());
  EXPECT_LT(std::abs(p[kLeftCheek].y() - mouthY), 0.5);
  EXPECT_LT(std::abs(p[kRightCheek].y() - mouthY), 0.5);
  for (int i = 0; i < kPoints; ++i) {
    if (i == kLeftEarlobe || i == kRightEarlobe) continue;
    EXPECT_GT(p[kLeftEarlobe].x(), p[i].x()) << i;
    EXPECT_LT(p[kRightEarlobe].x(), p[i].x()) << i;
  }
  // The nose tip is the most forward point.
  for (int i = 0; i < kPoints; ++i) {
    if (i != 11) {
      EXPECT_GT(p[11].z(), p[i].z()) << i;
    }
  }
}

TEST_F(IctNeutral, AgreesWithTheReadme68AndTheConversionTable) {
  CLM3D_REQUIRE_SHARED_DATA(dataDir);
  load(dataDir);
  const auto ibug = readIctReadmeIbug68(dataDir / "morphable/ict-facekit/README.md");
  ASSERT_EQ(ibug.size(), 68u) << "README.md landmark list not found";
  for (const auto& entry : thesis25FromIbug68Table()) {
    const int i = entry.thesisIndex;
    if (entry.ibugIndices.size() != 1 || i == kLeftCheek || i == kRightCheek) continue;
    EXPECT_EQ(indices_[i], ibug[entry.ibugIndices[0]])
        << "thesis point " << i << " should be iBUG " << entry.ibugIndices[0];
  }
  // Derived points: within 2 mm of the frontal projection of the mean of their iBUG vertices.
  for (const int i : kDerived) {
    const auto& sources = thesis25FromIbug68Table()[i].ibugIndices;
    Vector3d mean = Vector3d::Zero();
    for (const int s : sources) mean += vertices_.at(ibug.at(s));
    mean /= static_cast<double>(sources.size());
    const Vector3d offset = points_[i] - mean;
    EXPECT_LT(offset.head<2>().norm(), 0.2) << "thesis point " << i;
    EXPECT_GT(offset.z(), 0.0) << "thesis point " << i << " should be in front of the mean";
    EXPECT_LT(offset.z(), 2.5) << "thesis point " << i;
  }
}

}  // namespace
}  // namespace clm3d
