// MakeHuman identities from ../shared/data/makehuman (skipped when it is absent): loading, seeds,
// the landmark table on the generated meshes, symmetry, size, and the manifest entry.
#include "core/dataset/detail/makehuman_head.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/core.hpp>

#include "core/common/error.hpp"
#include "core/dataset/ict_facekit.hpp"
#include "core/dataset/manifest.hpp"
#include "core/dataset/training_subjects.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

using test::TempDir;
using test::writeFile;

std::vector<int> table() {
  return readLandmarkVertexTable(test::fixturePath("makehuman/thesis25_vertices.json"), "thesis25",
                                 25);
}

std::shared_ptr<const MakeHumanAssets> loadAssets(const std::filesystem::path& data,
                                                  MakeHumanOptions options = {}) {
  options.textureSize = 256;
  return MakeHumanAssets::load(data / "makehuman", table(), options);
}

double nearestVertexDistance(const TexturedMesh& mesh, const Eigen::Vector3d& p) {
  double best = INFINITY;
  for (const auto& v : mesh.positions) best = std::min(best, (v.cast<double>() - p).norm());
  return best;
}

TEST(MakeHumanHead, IdentityLoadsWithLandmarksOnTheMesh) {
  CLM3D_REQUIRE_SHARED_DATA(data);
  const auto assets = loadAssets(data);
  EXPECT_EQ(assets->baseVertexCount(), 19158u);
  EXPECT_GT(assets->identityModifierCount(), 80u);
  const MakeHumanAssets::Head head = assets->generate(5, "neutral");
  EXPECT_NO_THROW(head.mesh.validate());
  EXPECT_GT(head.mesh.triangleCount(), 5000u);
  EXPECT_EQ(head.mesh.texture.cols, 256 + 64);
  EXPECT_EQ(head.mesh.texture.rows, 256);
  ASSERT_EQ(head.landmarks.presentCount(), 25);
  for (int i = 0; i < 25; ++i) {
    EXPECT_LT(nearestVertexDistance(head.mesh, head.landmarks.point(i)), 0.01) << "landmark " << i;
  }
  // Head-sized, in millimetres: inter-ocular distance (points 7 and 10) and face height.
  const double iod = (head.landmarks.point(7) - head.landmarks.point(10)).norm();
  EXPECT_GT(iod, 52.0);
  EXPECT_LT(iod, 75.0);
  EXPECT_GT(head.landmarks.point(7).x(), head.landmarks.point(10).x());   // +x = subject's left
  EXPECT_GT(head.landmarks.point(0).y(), head.landmarks.point(21).y());   // +y up
  EXPECT_GT(head.landmarks.point(11).z(), head.landmarks.point(18).z());  // +z front
  const Eigen::Vector3f size = head.mesh.bounds().sizes();
  EXPECT_GT(size.y(), 180.0f);
  EXPECT_LT(size.y(), 320.0f);
}

TEST(MakeHumanHead, DeterministicForASeedAndDifferentBetweenSeeds) {
  CLM3D_REQUIRE_SHARED_DATA(data);
  const auto assets = loadAssets(data);
  const auto a = assets->generate(7, "neutral");
  const auto b = assets->generate(7, "neutral");
  const auto c = assets->generate(8, "neutral");
  EXPECT_EQ(a.mesh.positions, b.mesh.positions);
  EXPECT_EQ(a.landmarks, b.landmarks);
  EXPECT_EQ(a.skin, b.skin);
  EXPECT_EQ(cv::norm(a.mesh.texture, b.mesh.texture, cv::NORM_INF), 0.0);
  ASSERT_EQ(a.mesh.positions.size(), c.mesh.positions.size());  // one topology
  double largest = 0;
  for (std::size_t i = 0; i < a.mesh.positions.size(); ++i) {
    largest =
        std::max(largest, static_cast<double>((a.mesh.positions[i] - c.mesh.positions[i]).norm()));
  }
  EXPECT_GT(largest, 3.0) << "two seeds gave nearly the same shape";
  // Landmark geometry differs too (not just a shift): nose-tip to chin distance.
  const auto span = [](const MakeHumanAssets::Head& h) {
    return (h.landmarks.point(11) - h.landmarks.point(21)).norm();
  };
  EXPECT_GT(std::abs(span(a) - span(c)), 0.1);
}

TEST(MakeHumanHead, SymmetricIdentityHasMirroredLandmarks) {
  CLM3D_REQUIRE_SHARED_DATA(data);
  const auto assets = loadAssets(data);
  const auto head = assets->generate(11, "neutral", /*symmetric=*/true);
  const std::vector<std::pair<int, int>> pairs = {{1, 2},   {3, 6},   {4, 5},   {7, 10},  {8, 9},
                                                  {12, 13}, {14, 15}, {18, 24}, {19, 23}, {20, 22}};
  // The mid-plane: where the mid-line points lie (x of the nose tip, top of the lip, chin).
  const double mid =
      (head.landmarks.point(11).x() + head.landmarks.point(16).x() + head.landmarks.point(21).x()) /
      3.0;
  for (const auto& [l, r] : pairs) {
    const Eigen::Vector3d a = head.landmarks.point(l);
    const Eigen::Vector3d b = head.landmarks.point(r);
    EXPECT_NEAR(a.x() - mid, mid - b.x(), 3.0) << l << "/" << r;
    EXPECT_NEAR(a.y(), b.y(), 3.0) << l << "/" << r;
    EXPECT_NEAR(a.z(), b.z(), 3.0) << l << "/" << r;
  }
}

TEST(MakeHumanHead, ExpressionsMoveTheMouthAndUnknownOnesAreErrors) {
  CLM3D_REQUIRE_SHARED_DATA(data);
  MakeHumanOptions options;
  options.expressions = {"neutral", "mouth-open"};
  const auto assets = loadAssets(data, options);
  const auto neutral = assets->generate(3, "neutral");
  const auto open = assets->generate(3, "mouth-open");
  const auto lipGap = [](const MakeHumanAssets::Head& h) {
    return (h.landmarks.point(16) - h.landmarks.point(17)).norm();
  };
  EXPECT_GT(lipGap(open), lipGap(neutral) + 3.0);
  EXPECT_THROW((void)assets->generate(3, "smile"), InputError);
  options.expressions = {"no-such-unit"};
  try {
    (void)loadAssets(data, options);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no-such-unit.target"), std::string::npos) << e.what();
  }
  options.expressions = {"neutral"};
  options.skins = {"no_such_skin"};
  EXPECT_THROW((void)loadAssets(data, options), InputError);
}

TEST(MakeHumanManifest, EntryParsesAndYieldsSubjectsInModelCoordinates) {
  CLM3D_REQUIRE_SHARED_DATA(data);
  TempDir dir;
  const std::string root = (data / "makehuman").string();
  const std::string vertices = test::fixturePath("makehuman/thesis25_vertices.json").string();
  writeFile(dir / "m.json", R"({"version": 1, "makehuman": [{"root": ")" + root +
                                R"(", "vertices": ")" + vertices +
                                R"(", "identities": 2, "expressions": ["neutral", "mouth-open"],
                                 "texture_size": 128, "seed_offset": 40}]})");
  const DatasetManifest manifest = loadManifest(dir / "m.json");
  ASSERT_EQ(manifest.makehuman.size(), 1u);
  EXPECT_EQ(manifest.makehuman[0].identities, 2);
  EXPECT_EQ(manifest.makehuman[0].textureSize, 128);
  const auto subjects = loadTexturedSubjects(manifest, 2);
  ASSERT_EQ(subjects.size(), 4u);
  EXPECT_EQ(subjects[0].id, "makehuman/40/neutral");
  EXPECT_EQ(subjects[1].id, "makehuman/40/mouth-open");
  EXPECT_EQ(subjects[3].id, "makehuman/41/mouth-open");
  for (const auto& s : subjects) {
    EXPECT_LT(s.landmarks.point(0).norm(), 1e-6) << s.id;  // landmark 1 at the origin
    EXPECT_NEAR(s.landmarks.point(7).y(), s.landmarks.point(10).y(), 1e-6) << s.id;  // levelled
    EXPECT_GT(s.landmarks.point(11).z(), 10.0) << s.id;  // nose in front
  }
}

TEST(MakeHumanManifest, BadFieldsAreNamed) {
  CLM3D_REQUIRE_SHARED_DATA(data);
  TempDir dir;
  const std::string root = (data / "makehuman").string();
  const std::string vertices = test::fixturePath("makehuman/thesis25_vertices.json").string();
  const std::string head = R"({"version": 1, "makehuman": [{"root": ")" + root +
                           R"(", "vertices": ")" + vertices + R"(")";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"(, "identities": 0)", "field makehuman[0].identities: must be in [1, 100000]"},
      {R"(, "skins": ["nope"])", "field makehuman[0].skins[0]: no such texture"},
      {R"(, "eyes": ["red_eye"])", "field makehuman[0].eyes[0]: no such texture"},
      {R"(, "expressions": ["mouth-open+grin"])", "field makehuman[0].expressions[0]:"},
      {R"(, "expressions": ["a/b"])", "field makehuman[0].expressions[0]: must not contain '/'"},
      {R"(, "identity_weight": 2)", "field makehuman[0].identity_weight: must be in [0, 1]"},
      {R"(, "texture_size": 4)", "field makehuman[0].texture_size: must be in [16, 8192]"},
      {R"(, "expression_units": "martian")", "field makehuman[0].expression_units: no folder"},
      {R"(, "colour": 1)", "field makehuman[0].colour: unknown field"},
  };
  for (const auto& [extra, expected] : cases) {
    writeFile(dir / "m.json", head + extra + "}]}");
    try {
      (void)loadManifest(dir / "m.json");
      ADD_FAILURE() << "no error for " << extra;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
  }
  writeFile(dir / "m.json", R"({"version": 1, "makehuman": [{"root": ")" +
                                (dir.path() / "nowhere").string() + R"(", "vertices": ")" +
                                vertices + R"("}]})");
  EXPECT_THROW((void)loadManifest(dir / "m.json"), InputError);
  // Two entries with the same seeds define the same subjects.
  writeFile(dir / "m.json", head + "}, " + head.substr(head.find("{\"root\"")) + "}]}");
  try {
    (void)loadManifest(dir / "m.json");
    ADD_FAILURE() << "no error for duplicate identities";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("already defined"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace clm3d
