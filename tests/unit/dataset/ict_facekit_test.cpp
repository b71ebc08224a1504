#include "core/dataset/ict_facekit.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <sstream>

#include "core/common/error.hpp"
#include "core/dataset/training_subjects.hpp"
#include "core/scheme/scheme.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

namespace fs = std::filesystem;
using test::TempDir;
using test::writeFile;

constexpr int kLeftEye = 7, kRightEye = 10, kLeftMouth = 14, kRightMouth = 15, kChin = 21;

// A tiny stand-in for the ICT-FaceKit model: 51 vertices per mesh, landmark p at vertex 2p + 1
// (the even vertices are decoys), centimetres. identity000 widens the face by 10 %, identity001 is
// the neutral; jawOpen lowers the chin, mouthSmile_L/_R raise one mouth corner each.
class TinyIctModel {
 public:
  TinyIctModel() {
    neutral_.resize(25);
    for (int p = 0; p < 25; ++p) neutral_[p] = Eigen::Vector3d(0.25 * (p - 12), -0.3 * p, 1.0);
    neutral_[0] = Eigen::Vector3d(0.0, 1.0, 2.0);
    neutral_[kLeftEye] = Eigen::Vector3d(3.2, 1.0, 0.5);
    neutral_[kRightEye] = Eigen::Vector3d(-3.2, 1.0, 0.5);
    fs::create_directories(dir_ / "model/FaceXModel");
    write("generic_neutral_mesh", neutral_);
    auto wide = neutral_;
    for (auto& p : wide) p.x() *= 1.1;
    write("identity000", wide);
    write("identity001", neutral_);
    auto jaw = neutral_;
    jaw[kChin].y() -= 1.0;
    write("jawOpen", jaw);
    auto left = neutral_;
    left[kLeftMouth].y() += 0.5;
    write("mouthSmile_L", left);
    auto right = neutral_;
    right[kRightMouth].y() += 0.5;
    write("mouthSmile_R", right);
    writeFile(dir_ / "model/README.md", "not a mesh");
    std::ostringstream table;
    table << R"({"scheme": "thesis25", "vertices": [)";
    for (int p = 0; p < 25; ++p) table << (p ? ", " : "") << 2 * p + 1;
    table << "]}";
    writeFile(dir_ / "vertices.json", table.str());
  }

  // A manifest with one ict_facekit entry holding `fields` besides model and vertices.
  DatasetManifest manifest(const std::string& fields, const std::string& model = "model") const {
    writeFile(dir_ / "m.json", R"({"version": 1, "ict_facekit": [{"model": ")" + model +
                                   R"(", "vertices": "vertices.json")" +
                                   (fields.empty() ? "" : ", " + fields) + "}]}");
    return loadManifest(dir_ / "m.json");
  }
  const TempDir& dir() const { return dir_; }

 private:
  void write(const std::string& name, const std::vector<Eigen::Vector3d>& landmarks) {
    std::ostringstream obj;
    obj << "# " << name << "\nmtllib ICTFaceModelMaterial.mtl\n";
    for (int v = 0; v < 51; ++v) {
      const Eigen::Vector3d p = v % 2 ? landmarks[v / 2] : Eigen::Vector3d(99, 99, 99);
      obj << "v " << p.x() << ' ' << p.y() << ' ' << p.z() << "\nvt 0 0\n";
    }
    obj << "f 1 2 3\n";
    writeFile(dir_ / "model/FaceXModel" / (name + ".obj"), obj.str());
  }

  TempDir dir_;
  std::vector<Eigen::Vector3d> neutral_;
};

std::string inputErrorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(IctFaceKit, MillimetresCentredOnLandmarkOneAndLevelled) {
  TinyIctModel model;
  const auto samples = sampleShapeOnlyLandmarks(
      model.manifest(R"("identities": 3, "identity_weight_sd": 0, "expressions_per_sample": 0)"),
      1);
  ASSERT_EQ(samples.size(), 3u);
  for (const LandmarkSet& s : samples) {
    ASSERT_EQ(s.size(), 25);
    EXPECT_EQ(s.presentCount(), 25);
    EXPECT_LT(s.point(0).norm(), 1e-9);
    EXPECT_NEAR(s.point(kLeftEye).x(), 32.0, 1e-9);  // 3.2 cm, relative to landmark 1
    EXPECT_NEAR(s.point(kLeftEye).y(), 0.0, 1e-9);
    EXPECT_NEAR(s.point(kLeftEye).z(), -15.0, 1e-9);
    EXPECT_NEAR((s.point(kLeftEye) - s.point(kRightEye)).norm(), 64.0, 1e-9);
    EXPECT_TRUE(s == samples[0]);  // no randomness left
  }
}

TEST(IctFaceKit, IdentityWeightsVarySamplesDeterministically) {
  TinyIctModel model;
  const auto manifest = model.manifest(R"("identities": 20, "expressions_per_sample": 0)");
  const auto a = sampleShapeOnlyLandmarks(manifest, 7);
  const auto b = sampleShapeOnlyLandmarks(manifest, 7);
  const auto c = sampleShapeOnlyLandmarks(manifest, 8);
  ASSERT_EQ(a.size(), 20u);
  double lo = 1e9, hi = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_TRUE(a[i] == b[i]);
    EXPECT_FALSE(a[i] == c[i]);
    const double iod = (a[i].point(kLeftEye) - a[i].point(kRightEye)).norm();
    lo = std::min(lo, iod);
    hi = std::max(hi, iod);
  }
  // iod = 64 (1 + 0.1 w), w ~ N(0, 1): 20 draws spread over several millimetres.
  EXPECT_GT(hi - lo, 3.0);
  // seed_offset shifts the stream.
  const auto shifted = sampleShapeOnlyLandmarks(
      model.manifest(R"("identities": 20, "expressions_per_sample": 0, "seed_offset": 1)"), 7);
  for (std::size_t i = 0; i < shifted.size(); ++i) EXPECT_TRUE(shifted[i] == c[i]);
}

TEST(IctFaceKit, MirrorBlendshapesComeInPairs) {
  TinyIctModel model;
  const auto samples = sampleShapeOnlyLandmarks(
      model.manifest(R"("identities": 10, "identity_weight_sd": 0, "expressions_per_sample": 1,
                        "expressions": ["mouthSmile_L", "mouthSmile_R"])"),
      3);
  bool moved = false;
  for (const LandmarkSet& s : samples) {
    const double left = s.point(kLeftMouth).y() - (-0.3 * kLeftMouth - 1.0) * 10.0;
    const double right = s.point(kRightMouth).y() - (-0.3 * kRightMouth - 1.0) * 10.0;
    EXPECT_NEAR(left, right, 1e-9);
    EXPECT_GE(left, 0.0);
    EXPECT_LE(left, 5.0);
    moved = moved || left > 0.1;
    EXPECT_NEAR(s.point(kChin).y(), (-0.3 * kChin - 1.0) * 10.0, 1e-9);  // jawOpen not listed
  }
  EXPECT_TRUE(moved);
}

TEST(IctFaceKit, ArchiveGivesTheSameSamplesAsTheFolder) {
  TinyIctModel model;
  const auto tar = test::runCommand("tar czf '" + (model.dir() / "model.tar.gz").string() +
                                    "' -C '" + model.dir().path().string() + "' model");
  ASSERT_EQ(tar.exitCode, 0) << tar.output;
  const std::string fields = R"("identities": 5)";
  const auto fromFolder = sampleShapeOnlyLandmarks(model.manifest(fields), 2);
  const auto fromArchive = sampleShapeOnlyLandmarks(model.manifest(fields, "model.tar.gz"), 2);
  ASSERT_EQ(fromArchive.size(), 5u);
  for (std::size_t i = 0; i < fromArchive.size(); ++i) {
    EXPECT_TRUE(fromArchive[i] == fromFolder[i]);
  }
}

TEST(IctFaceKit, ErrorsNameTheManifestFieldOrTheDataFile) {
  TinyIctModel model;
  const fs::path dir = model.dir().path();
  std::string message = inputErrorOf([&] {
    sampleShapeOnlyLandmarks(model.manifest(R"("expressions": ["jawOpen", "grin"])"), 1);
  });
  EXPECT_NE(message.find((dir / "m.json").string() + ": field ict_facekit[0].expressions[1]: "),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("no blendshape 'grin'"), std::string::npos) << message;

  writeFile(dir / "model/FaceXModel/broken.obj", "v 1 2 3\n");
  message = inputErrorOf([&] { sampleShapeOnlyLandmarks(model.manifest(""), 1); });
  EXPECT_NE(message.find("broken.obj: has 1 vertices"), std::string::npos) << message;
  fs::remove(dir / "model/FaceXModel/broken.obj");

  fs::remove(dir / "model/FaceXModel/generic_neutral_mesh.obj");
  message = inputErrorOf([&] { sampleShapeOnlyLandmarks(model.manifest(""), 1); });
  EXPECT_NE(message.find("holds no generic_neutral_mesh.obj"), std::string::npos) << message;

  writeFile(dir / "garbage.tar.xz", "this is not an archive");
  message =
      inputErrorOf([&] { sampleShapeOnlyLandmarks(model.manifest("", "garbage.tar.xz"), 1); });
  EXPECT_EQ(message.rfind((dir / "garbage.tar.xz").string() + ": ", 0), 0u) << message;

  writeFile(dir / "vertices.json", R"({"scheme": "ibug68", "vertices": []})");
  message = inputErrorOf([&] { sampleShapeOnlyLandmarks(model.manifest(""), 1); });
  EXPECT_EQ(message.rfind((dir / "vertices.json").string() + ": field scheme:", 0), 0u) << message;

  // The vertex table's fields are read with core/common/json_fields: an unknown key is refused.
  writeFile(dir / "vertices.json", R"({"scheme": "thesis25", "vertices": [], "vertexes": [1]})");
  message = inputErrorOf([&] { sampleShapeOnlyLandmarks(model.manifest(""), 1); });
  EXPECT_EQ(message.rfind((dir / "vertices.json").string() + ": field vertexes: unknown field", 0),
            0u)
      << message;
}

TEST(IctFaceKit, CancelStops) {
  TinyIctModel model;
  CancelToken cancel;
  cancel.cancel();
  EXPECT_THROW(sampleShapeOnlyLandmarks(model.manifest(""), 1, {}, &cancel), Cancelled);
}

// The real model, read from the distributed archive.
class RealIctModel : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto data = sharedDataDir();
    if (!data) GTEST_SKIP() << "../shared/data not found (set CLM3D_DATA to run this test)";
    archive_ = *data / "morphable/ict-facekit/ICT-FaceKit_FaceXModel.tar.xz";
    if (!fs::exists(archive_)) GTEST_SKIP() << archive_ << " not found";
  }
  DatasetManifest manifest(const std::string& fields) const {
    writeFile(dir_ / "m.json",
              R"({"version": 1, "ict_facekit": [{"model": ")" + archive_.string() +
                  R"(", "vertices": ")" +
                  test::fixturePath("ict-facekit/thesis25_vertices.json").string() + R"(", )" +
                  fields + "}]}");
    return loadManifest(dir_ / "m.json");
  }
  // Largest distance between a point and its mirror partner reflected in x = 0.
  static double asymmetry(const LandmarkSet& s) {
    double worst = 0.0;
    for (int p = 0; p < 25; ++p) {
      Eigen::Vector3d mirrored = s.point(Scheme::thesis25().mirrorOf(p));
      mirrored.x() = -mirrored.x();
      worst = std::max(worst, (s.point(p) - mirrored).norm());
    }
    return worst;
  }
  // Checks every sample is a plausible face and differs from the one before.
  static void expectPlausibleFaces(const std::vector<LandmarkSet>& samples) {
    ASSERT_GE(samples.size(), 10u) << "too few samples for the share of typical faces below";
    std::size_t typical = 0;
    for (std::size_t i = 0; i < samples.size(); ++i) {
      const LandmarkSet& s = samples[i];
      ASSERT_EQ(s.presentCount(), 25);
      EXPECT_LT(s.point(0).norm(), 1e-9);
      const double iod = (s.point(kLeftEye) - s.point(kRightEye)).norm();
      // Adult inter-ocular distances are about 55-75 mm; the model's tails (sd 1) reach a little
      // beyond, about 1 sample in 100 on each side.
      EXPECT_GT(iod, 48.0) << "sample " << i;
      EXPECT_LT(iod, 82.0) << "sample " << i;
      if (iod > 55.0 && iod < 75.0) ++typical;
      EXPECT_NEAR(s.point(kLeftEye).y(), s.point(kRightEye).y(), 1e-6);
      EXPECT_GT(s.point(kLeftEye).x(), 0.0);
      EXPECT_GT(s.point(11).z(), 10.0);   // nose tip in front
      EXPECT_LT(s.point(21).y(), -70.0);  // chin below
      if (i > 0) {
        EXPECT_GT((s.matrix() - samples[i - 1].matrix()).norm(), 1.0);
      }
    }
    EXPECT_GE(static_cast<double>(typical), 0.9 * static_cast<double>(samples.size()));
  }
  fs::path archive_;
  TempDir dir_;
};

TEST_F(RealIctModel, IdentitySamplesArePlausibleSymmetricFaces) {
  const auto start = std::chrono::steady_clock::now();
  const auto samples =
      sampleShapeOnlyLandmarks(manifest(R"("identities": 30, "expressions_per_sample": 0)"), 1);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "ICT-FaceKit: read and sampled 30 shapes in " << seconds << " s\n";
  ASSERT_EQ(samples.size(), 30u);
  expectPlausibleFaces(samples);
  // Real faces are a little asymmetric, and so are the higher identity components.
  for (const auto& s : samples) EXPECT_LT(asymmetry(s), 10.0);
}

TEST_F(RealIctModel, MirrorPairedExpressionsStaySymmetric) {
  const auto samples = sampleShapeOnlyLandmarks(
      manifest(R"("identities": 20, "expressions_per_sample": 2, "expressions":
                  ["jawOpen", "mouthSmile_L", "mouthSmile_R", "browInnerUp_L", "browInnerUp_R",
                   "eyeBlink_L", "eyeBlink_R", "mouthFrown_L", "mouthFrown_R"])"),
      2);
  ASSERT_EQ(samples.size(), 20u);  // one per identity: the checks below run on every one
  expectPlausibleFaces(samples);
  // Paired blendshapes add no asymmetry to the identity's own (up to 10 mm, see above).
  for (const auto& s : samples) EXPECT_LT(asymmetry(s), 10.0);
}

TEST_F(RealIctModel, AllExpressionsGivePlausibleFaces) {
  // jawLeft/Right and mouthLeft/Right have no mirror partner and move the mouth sideways by up
  // to 18 mm, so these samples are only symmetric-ish.
  const auto samples = sampleShapeOnlyLandmarks(manifest(R"("identities": 30)"), 3);
  ASSERT_EQ(samples.size(), 30u);  // one per identity: the checks below run on every one
  expectPlausibleFaces(samples);
  for (const auto& s : samples) EXPECT_LT(asymmetry(s), 40.0);
}

TEST_F(RealIctModel, CancellingWhileReadingTheArchiveStopsSoon) {
  CancelToken cancel;
  int calls = 0;
  auto progress = [&](double, std::string_view) {
    ++calls;
    cancel.cancel();
  };
  EXPECT_THROW(sampleShapeOnlyLandmarks(manifest(R"("identities": 5)"), 1, progress, &cancel),
               Cancelled);
  EXPECT_EQ(calls, 1);
}

}  // namespace
}  // namespace clm3d
