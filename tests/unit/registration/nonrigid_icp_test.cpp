// Registration and texture baking on procedural heads: two identities share one topology, so
// after registering head B onto head A, vertex v of B should sit on A's surface where A's vertex v
// is, and A's texture baked into B's UV layout should show A's colours at B's vertices.
#include "core/registration/nonrigid_icp.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "core/common/error.hpp"
#include "core/mesh/mesh_distance.hpp"
#include "core/registration/surface_index.hpp"
#include "core/registration/texture_bake.hpp"
#include "core/synth/synth_head.hpp"

namespace clm3d {
namespace {

SynthHead head(std::uint64_t seed) {
  SynthOptions options;
  options.faceStepDegrees = 1.5;
  options.textureSize = 512;
  return generateHead(seed, Expression{}, options);
}

// Vertices of the front of the face: within 70 mm of landmark 1 with a normal towards +z.
std::vector<bool> faceVertices(const SynthHead& h) {
  TexturedMesh mesh = h.mesh;
  mesh.computeNormals();
  std::vector<bool> face(mesh.positions.size(), false);
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    face[v] = mesh.positions[v].norm() < 70.0F && mesh.normals[v].z() > 0.5F;
  }
  return face;
}

cv::Vec3b texel(const cv::Mat& texture, const Eigen::Vector2f& uv) {
  const int x =
      std::clamp(static_cast<int>(uv.x() * static_cast<float>(texture.cols)), 0, texture.cols - 1);
  const int y = std::clamp(static_cast<int>((1.0F - uv.y()) * static_cast<float>(texture.rows)), 0,
                           texture.rows - 1);
  return texture.at<cv::Vec3b>(y, x);
}

class ProceduralPair : public ::testing::Test {
 protected:
  void SetUp() override {
#if defined(__SANITIZE_ADDRESS__)
    // Unoptimised under the sanitizers one registration of these 21,000-vertex heads takes over
    // 6 minutes (the sparse solves): the release pass runs these tests.
    GTEST_SKIP() << "skipped in the sanitizer build: the release build runs it";
#endif
  }
  static void SetUpTestSuite() {
#if defined(__SANITIZE_ADDRESS__)
    return;  // every test skips (SetUp)
#endif
    a_ = new SynthHead(head(3));
    b_ = new SynthHead(head(11));
  }
  static void TearDownTestSuite() {
    delete a_;
    delete b_;
  }
  static SynthHead* a_;
  static SynthHead* b_;
};
SynthHead* ProceduralPair::a_ = nullptr;
SynthHead* ProceduralPair::b_ = nullptr;

TEST_F(ProceduralPair, RegistersOntoTheOtherIdentity) {
  const SynthHead& a = *a_;
  const SynthHead& b = *b_;
  ASSERT_EQ(a.mesh.positions.size(), b.mesh.positions.size());
  const auto start = std::chrono::steady_clock::now();
  const NonRigidIcpResult r = registerNonRigid(b.mesh, b.landmarks, a.mesh, a.landmarks);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "registered " << b.mesh.positions.size() << " vertices in " << seconds << " s; mean "
            << r.meanDistance << " mm, max " << r.maxDistance << " mm, matched "
            << r.matchedFraction << "\n";

  // Distance of B's registered face vertices to A's surface, and to A's same vertex.
  const std::vector<bool> face = faceVertices(a);
  const SurfaceIndex index(a.mesh);
  double surface = 0.0, vertex = 0.0, rigidVertex = 0.0;
  int count = 0;
  for (std::size_t v = 0; v < face.size(); ++v) {
    if (!face[v]) continue;
    const auto hit = index.nearest(r.positions[v].cast<double>(), 20.0);
    ASSERT_TRUE(hit.has_value()) << "vertex " << v;
    surface += hit->distance;
    vertex += (r.positions[v] - a.mesh.positions[v]).norm();
    rigidVertex += (r.rest[v] - a.mesh.positions[v]).norm();
    ++count;
  }
  ASSERT_GT(count, 500);
  std::cout << "face: mean surface distance " << surface / count << " mm, to the same vertex "
            << vertex / count << " mm (after the similarity alone " << rigidVertex / count
            << " mm)\n";
  EXPECT_LT(surface / count, 1.0);
  // The surface fit slides vertices along the surface; still they end nearer their counterparts
  // than the landmark similarity alone put them.
  EXPECT_LT(vertex / count, rigidVertex / count);
  EXPECT_GT(r.matchedFraction, 0.9);
  for (const double residual : r.landmarkResiduals) EXPECT_LT(residual, 4.0);
}

TEST_F(ProceduralPair, BakesTheTargetTextureIntoTheTemplateLayout) {
  const SynthHead& a = *a_;
  const SynthHead& b = *b_;
  const NonRigidIcpResult r = registerNonRigid(b.mesh, b.landmarks, a.mesh, a.landmarks);
  TextureBakeOptions options;
  options.width = options.height = 512;
  const TextureBakeResult baked = bakeTexture(b.mesh, r.positions, a.mesh, options);
  ASSERT_EQ(baked.texture.size(), cv::Size(512, 512));
  EXPECT_GT(baked.bakedFraction, 0.8);

  // At corresponding vertices (same index) of the face, the colours agree, after a light blur
  // that forgives the sub-millimetre slide of the registration over pores and hair strands.
  cv::Mat bakedBlur, targetBlur;
  cv::GaussianBlur(baked.texture, bakedBlur, cv::Size(0, 0), 2.0);
  cv::GaussianBlur(a.mesh.texture, targetBlur, cv::Size(0, 0), 2.0);
  const std::vector<bool> face = faceVertices(a);
  int agree = 0, count = 0, differFromB = 0;
  for (std::size_t v = 0; v < face.size(); ++v) {
    if (!face[v]) continue;
    const cv::Vec3b got = texel(bakedBlur, b.mesh.uvs[v]);
    const cv::Vec3b want = texel(targetBlur, a.mesh.uvs[v]);
    const cv::Vec3b own = texel(b.mesh.texture, b.mesh.uvs[v]);
    ++count;
    if (cv::norm(cv::Vec3d(got) - cv::Vec3d(want)) < 30.0) ++agree;
    if (cv::norm(cv::Vec3d(own) - cv::Vec3d(want)) >= 30.0) ++differFromB;
  }
  std::cout << agree << " of " << count << " face vertices agree; B's own texture differs at "
            << differFromB << "\n";
  EXPECT_GT(agree, 0.85 * count);
}

TEST(Registration, RejectsBadInput) {
  const SynthHead a = head(1);
  TexturedMesh empty;
  empty.source = "empty.obj";
  EXPECT_THROW(registerNonRigid(empty, a.landmarks, a.mesh, a.landmarks), InputError);
  EXPECT_THROW(registerNonRigid(a.mesh, a.landmarks, empty, a.landmarks), InputError);
  LandmarkSet fewer(10, 3);
  try {
    registerNonRigid(a.mesh, a.landmarks, a.mesh, fewer);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("25 landmarks"), std::string::npos) << e.what();
  }
  LandmarkSet two(25, 3);
  two.set(0, Eigen::Vector3d(0, 0, 0));
  two.set(1, Eigen::Vector3d(1, 0, 0));
  EXPECT_THROW(registerNonRigid(a.mesh, a.landmarks, a.mesh, two), InputError);
  std::vector<Eigen::Vector3f> wrongCount(3);
  EXPECT_THROW(bakeTexture(a.mesh, wrongCount, a.mesh), InputError);
  TexturedMesh untextured = a.mesh;
  untextured.texture = cv::Mat();
  EXPECT_THROW(bakeTexture(a.mesh, a.mesh.positions, untextured), InputError);
}

TEST(TextureFill, FillsHolesFromTheirNeighbours) {
  cv::Mat image(64, 64, CV_8UC3, cv::Scalar::all(0));
  cv::Mat known(64, 64, CV_8U, cv::Scalar::all(0));
  image(cv::Rect(0, 0, 32, 64)).setTo(cv::Scalar(200, 100, 50));
  known(cv::Rect(0, 0, 32, 64)).setTo(255);
  image(cv::Rect(40, 0, 24, 64)).setTo(cv::Scalar(20, 40, 60));
  known(cv::Rect(40, 0, 24, 64)).setTo(255);
  fillUnknownTexels(image, known);
  EXPECT_EQ(image.at<cv::Vec3b>(10, 10), cv::Vec3b(200, 100, 50));  // known texels unchanged
  const cv::Vec3b gap = image.at<cv::Vec3b>(30, 36);                // between the two colours
  EXPECT_GT(gap[0], 20);
  EXPECT_LT(gap[0], 200);
  EXPECT_THROW(fillUnknownTexels(image, cv::Mat(64, 64, CV_8U, cv::Scalar::all(0))), InputError);
}

}  // namespace
}  // namespace clm3d
