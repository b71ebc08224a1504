// Training with per-scan missing landmarks (a scan with closed eyes has no eye centres): through
// the manifest path (a scan entry whose landmark file has nulls, next to a complete procedural
// head), the shape model imputes the missing points, the renders are framed on imputed eye
// centres, and a point missing from some subjects still gets patches in the views where the
// subjects that have it show it.
#include <gtest/gtest.h>

#include <algorithm>
#include <tuple>

#include "core/common/error.hpp"
#include "core/mesh/mesh_export.hpp"
#include "core/scheme/landmark_file.hpp"
#include "core/scheme/scheme.hpp"
#include "core/synth/synth_head.hpp"
#include "core/train/trainer.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

using test::TempDir;
using test::writeFile;

// thesis25, 0-based.
constexpr int kLeftOuter = 1, kRightOuter = 2, kLeftEye = 7, kLeftInner = 8, kRightInner = 9,
              kRightEye = 10, kLeftEarlobe = 18;

TrainSettings smallSettings() {
  TrainSettings settings;
  settings.yawsDeg = {-60, 0, 60};
  settings.pitchesDeg = {0};
  settings.scales = 1;
  settings.patchSize = 8;
  settings.samplesPerView = 2;
  settings.supersample = 1;
  settings.threads = 1;
  settings.seed = 3;
  return settings;
}

// A procedural head saved as a scan (OBJ + LJSON) with the given landmarks set missing.
void saveScan(const TempDir& dir, const std::string& name, std::uint64_t seed,
              const std::vector<int>& missing) {
  SynthHead head = generateHead(seed, {}, SynthOptions{2.0, 256});
  saveObj(head.mesh, dir / (name + ".obj"));
  for (const int i : missing) head.landmarks.setMissing(i);
  writeLandmarks(dir / (name + ".ljson"), head.landmarks, Scheme::thesis25());
}

// Two scans without eye centres (one also without its left earlobe) and one complete procedural
// head: the eye centres are missing from 2 of 3 subjects, i.e. from most samples.
std::filesystem::path writeManifest(const TempDir& dir) {
  saveScan(dir, "a", 11, {kLeftEye, kRightEye, kLeftEarlobe});
  saveScan(dir, "b", 12, {kLeftEye, kRightEye});
  writeFile(dir / "m.json", R"({"version": 1, "scans": [
      {"mesh": "a.obj", "landmarks": "a.ljson", "subject": "a"},
      {"mesh": "b.obj", "landmarks": "b.ljson", "subject": "b"}],
    "procedural": [{"seeds": "13", "texture_size": 256, "face_step_degrees": 2}]})");
  return dir / "m.json";
}

const ViewModel& viewAt(const ClmModel& model, double yaw) {
  for (const ViewModel& view : model.views) {
    if (view.yawDeg == yaw && view.pitchDeg == 0) return view;
  }
  throw Error("no view at yaw " + std::to_string(yaw));
}

TEST(MissingLandmarks, ManifestScanWithoutEyeCentresTrains) {
  TempDir dir;
  const ClmModel model = trainFromManifest(writeManifest(dir), smallSettings(), "test");
  EXPECT_NO_THROW(model.validate());
  ASSERT_EQ(model.views.size(), 3u);

  // Shape model: the missing points were imputed; the mean eye centre lies between its corners.
  const Eigen::Matrix3Xd& mean = model.shape.meanShape;
  ASSERT_EQ(mean.cols(), 25);
  EXPECT_TRUE(mean.allFinite());
  for (const auto& [eye, outer, inner] : {std::tuple{kLeftEye, kLeftOuter, kLeftInner},
                                          std::tuple{kRightEye, kRightOuter, kRightInner}}) {
    const double lo = std::min(mean(0, outer), mean(0, inner));
    const double hi = std::max(mean(0, outer), mean(0, inner));
    EXPECT_GT(mean(0, eye), lo) << "eye " << eye;
    EXPECT_LT(mean(0, eye), hi) << "eye " << eye;
    EXPECT_NEAR(mean(1, eye), 0.5 * (mean(1, outer) + mean(1, inner)), 8.0) << "eye " << eye;
  }

  // Views: the eye centres, missing from most samples, still have patches in the frontal view,
  // and their mean alpha is that of the subject that has them (face, not background zeros).
  const ViewModel& frontal = viewAt(model, 0);
  for (const int eye : {kLeftEye, kRightEye}) {
    ASSERT_TRUE(frontal.visible[static_cast<std::size_t>(eye)]) << "eye " << eye;
    const PatchModel& patches = frontal.scales[0];
    const int entry = patches.entryOf(eye);
    ASSERT_GE(entry, 0);
    EXPECT_GT(patches.alpha[static_cast<std::size_t>(entry)].mean(), 0.9) << "eye " << eye;
  }
  EXPECT_TRUE(frontal.visible[static_cast<std::size_t>(kLeftEarlobe)]);
  // Left out only where hidden: the right earlobe (24) is behind the head when the head turns to
  // show its left side, in whichever yaw view that is, and the left earlobe in the other.
  const ViewModel& left = viewAt(model, -60);
  const ViewModel& right = viewAt(model, 60);
  EXPECT_NE(left.visible[kLeftEarlobe], right.visible[kLeftEarlobe]);
  EXPECT_NE(left.visible[24], right.visible[24]);
}

std::vector<SynthHead> headsWithoutEyeCentres() {
  std::vector<SynthHead> heads;
  for (const std::uint64_t seed : {11u, 12u}) {
    heads.push_back(generateHead(seed, {}, SynthOptions{2.0, 256}));
    heads.back().landmarks.setMissing(kLeftEye);
    heads.back().landmarks.setMissing(kRightEye);
  }
  return heads;
}

// No textured subject has eye centres (closed eyes on every scan), but a shape-only set does: the
// renders are framed on eye centres imputed from it.
TEST(MissingLandmarks, ShapeOnlySetsSupplyTheEyeCentresForFraming) {
  const std::vector<SynthHead> heads = headsWithoutEyeCentres();
  TrainingInput input;
  input.schemeJson = schemeJsonFor("thesis25");
  input.subjects = {{"a", &heads[0].mesh, &heads[0].landmarks},
                    {"b", &heads[1].mesh, &heads[1].landmarks}};
  input.shapeOnly = {generateHead(13, {}, SynthOptions{2.0, 256}).landmarks};
  const ClmModel model = trainModel(input, smallSettings());
  ASSERT_FALSE(model.views.empty());
  // It trains (without the donors it throws, see below) and the frontal view keeps both eyes.
  const ViewModel& frontal = model.views[model.views.size() / 2];
  for (const int corner : {1, 2, 8, 9}) EXPECT_TRUE(frontal.visible[corner]) << corner;
}

// Without any set that has the eye centres, the error is bad input naming the landmark.
TEST(MissingLandmarks, NoSetWithEyeCentresIsAnInputErrorNamingTheLandmark) {
  const std::vector<SynthHead> heads = headsWithoutEyeCentres();
  TrainingInput input;
  input.schemeJson = schemeJsonFor("thesis25");
  input.subjects = {{"a", &heads[0].mesh, &heads[0].landmarks},
                    {"b", &heads[1].mesh, &heads[1].landmarks}};
  try {
    trainModel(input, smallSettings());
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("eye_centre"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace clm3d
