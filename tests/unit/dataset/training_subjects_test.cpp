#include "core/dataset/training_subjects.hpp"

#include <gtest/gtest.h>

#include <atomic>

#include "core/common/error.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

namespace fs = std::filesystem;
using test::TempDir;
using test::writeFile;

constexpr int kSubjectLeftEye = 7, kSubjectRightEye = 10;  // thesis landmarks 8 and 11, 0-based

DatasetManifest tinyProcedural(const TempDir& dir, const std::string& seeds = "3,5") {
  writeFile(dir / "tiny.json", R"({"version": 1, "procedural": [
      {"seeds": ")" + seeds + R"(", "expressions": ["neutral", "smile"], "texture_size": 256,
       "face_step_degrees": 2}]})");
  return loadManifest(dir / "tiny.json");
}

TEST(LoadTexturedSubjects, ProceduralHeadsInManifestOrderWithLandmarkOneAtTheOrigin) {
  TempDir dir;
  const DatasetManifest manifest = tinyProcedural(dir);
  std::vector<double> fractions;
  const auto subjects = loadTexturedSubjects(
      manifest, 2, [&](double f, std::string_view) { fractions.push_back(f); });
  ASSERT_EQ(subjects.size(), 4u);
  const std::vector<std::string> ids = {"procedural/3/neutral", "procedural/3/smile",
                                        "procedural/5/neutral", "procedural/5/smile"};
  for (std::size_t i = 0; i < subjects.size(); ++i) {
    const TexturedSubject& s = subjects[i];
    EXPECT_EQ(s.id, ids[i]);
    EXPECT_EQ(s.subject + "/" + s.expression, s.id);
    ASSERT_EQ(s.landmarks.size(), 25);
    EXPECT_EQ(s.landmarks.dims(), 3);
    EXPECT_LT(s.landmarks.point(0).norm(), 1e-9);
    EXPECT_NO_THROW(s.mesh.validate());
    EXPECT_NEAR(s.landmarks.point(kSubjectLeftEye).y(), s.landmarks.point(kSubjectRightEye).y(),
                1e-6);
    EXPECT_GT(s.landmarks.point(kSubjectLeftEye).x(), 0.0);  // +x is the subject's left
  }
  EXPECT_FALSE(subjects[0].landmarks == subjects[1].landmarks);  // the smile moves points
  EXPECT_FALSE(subjects[0].landmarks == subjects[2].landmarks);  // another identity
  ASSERT_EQ(fractions.size(), 4u);
  EXPECT_DOUBLE_EQ(fractions.back(), 1.0);
}

TEST(LoadTexturedSubjects, SameResultOnAnyNumberOfThreads) {
  TempDir dir;
  const DatasetManifest manifest = tinyProcedural(dir, "4");
  const auto one = loadTexturedSubjects(manifest, 1);
  const auto two = loadTexturedSubjects(manifest, 2);
  ASSERT_EQ(one.size(), 2u);
  ASSERT_EQ(two.size(), 2u);
  for (std::size_t i = 0; i < one.size(); ++i) {
    EXPECT_EQ(one[i].id, two[i].id);
    EXPECT_TRUE(one[i].landmarks == two[i].landmarks);
    EXPECT_EQ(one[i].mesh.positions, two[i].mesh.positions);
  }
}

TEST(LoadTexturedSubjects, CancelStopsLoading) {
  TempDir dir;
  const DatasetManifest manifest = tinyProcedural(dir);
  CancelToken cancel;
  std::atomic<int> calls{0};
  auto progress = [&](double, std::string_view) {
    ++calls;
    cancel.cancel();
  };
  EXPECT_THROW(loadTexturedSubjects(manifest, 1, progress, &cancel), Cancelled);
  EXPECT_EQ(calls.load(), 1);  // stopped after the first head
}

TEST(LoadTexturedSubjects, ScanLandmarkFileErrorsNameTheFile) {
  TempDir dir;
  writeFile(dir / "head.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  writeFile(dir / "head.ljson",
            R"({"version": 3, "labels": [], "landmarks": {"points": [[0, 0]]}})");
  writeFile(dir / "m.json", R"({"version": 1, "scans": [
      {"mesh": "head.obj", "landmarks": "head.ljson", "subject": "x"}]})");
  try {
    loadTexturedSubjects(loadManifest(dir / "m.json"), 1);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("head.ljson"), std::string::npos) << e.what();
  }
}

// james through a manifest like resources/datasets/thesis.json: oriented, levelled, centred.
TEST(LoadTexturedSubjects, JamesIsLevelledAndCentred) {
  CLM3D_REQUIRE_SHARED_DATA(data);
  TempDir dir;
  writeFile(dir / "m.json", R"({"version": 1, "scans": [{"mesh": ")" +
                                (data / "scans/james/james.obj").string() + R"(", "landmarks": ")" +
                                test::fixturePath("james/james.thesis25.ljson").string() +
                                R"(", "subject": "james"}]})");
  const auto subjects = loadTexturedSubjects(loadManifest(dir / "m.json"), 2);
  ASSERT_EQ(subjects.size(), 1u);
  const TexturedSubject& james = subjects[0];
  EXPECT_EQ(james.id, "james/neutral");
  ASSERT_EQ(james.landmarks.presentCount(), 25);
  EXPECT_LT(james.landmarks.point(0).norm(), 1e-6);
  const Eigen::Vector3d left = james.landmarks.point(kSubjectLeftEye);
  const Eigen::Vector3d right = james.landmarks.point(kSubjectRightEye);
  EXPECT_LT(std::abs(left.y() - right.y()), 1.0);
  EXPECT_LT(std::abs(left.z() - right.z()), 1.0);  // the scan's 6 degree yaw is removed
  EXPECT_GT(left.x(), right.x());
  EXPECT_GT((left - right).norm(), 55.0);
  EXPECT_LT((left - right).norm(), 75.0);
  EXPECT_GT(james.landmarks.point(11).z(), 10.0);   // the nose tip is in front
  EXPECT_LT(james.landmarks.point(21).y(), -80.0);  // the chin is below
  // The mesh moved with the landmarks: the nose tip is near the front of the mesh.
  EXPECT_NEAR(james.mesh.bounds().max().z(), james.landmarks.point(11).z(), 15.0);
}

}  // namespace
}  // namespace clm3d
