// Tests of training from annotated photos: procedural heads rendered as "photos" with their exact
// points (.pts beside each PNG) are listed from a manifest, placed in the view nearest their
// fitted pose (a frontal photo and its mirror image in the frontal view, a photo turned 25 degrees
// in the -30 view, its mirror image dropped because +30 is a mirrored view), their patches match a
// render's at the same pose, and a model trained with them holds experts and says where its data
// came from. Bad photo sources fail with the file named.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <opencv2/core.hpp>
#include <string_view>
#include <vector>

#include "core/common/error.hpp"
#include "core/dataset/manifest.hpp"
#include "core/dataset/training_photos.hpp"
#include "core/geometry/camera.hpp"
#include "core/geometry/projection.hpp"
#include "core/render/offscreen_renderer.hpp"
#include "core/scheme/landmark_file.hpp"
#include "core/scheme/scheme_map.hpp"
#include "core/synth/synth_head.hpp"
#include "core/train/photo_samples.hpp"
#include "core/train/refiner_training.hpp"
#include "core/train/trainer.hpp"
#include "core/viz/image_file.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

namespace fs = std::filesystem;

const SynthHead& photoHead() {
  static const SynthHead h = generateHead(1, {}, SynthOptions{1.5, 512});
  return h;
}

const SynthHead& otherHead() {
  static const SynthHead h = generateHead(2, {}, SynthOptions{1.5, 512});
  return h;
}

TrainSettings photoSettings() {
  TrainSettings s;
  s.yawsDeg = {-30, 0, 30};
  s.pitchesDeg = {0};
  s.scales = 2;
  s.patchSize = 12;
  s.samplesPerView = 2;
  s.supersample = 1;
  s.threads = 2;
  s.expertRadius = 4;
  s.textureMaxModes = 8;
  s.photoJitter = 0;
  return s;
}

// Renders the head at (0, yaw, roll) over mid-grey into DIR/NAME.png with its 25 points in
// NAME.pts; the face's eye distance is about 90 pixels in a 400 x 400 photo.
void writePhoto(const fs::path& dir, const std::string& name, double yawDeg, double rollDeg) {
  const Camera camera = Camera::fromVerticalFov(400, 400, 40.0);
  const Eigen::Matrix3Xd truth = photoHead().landmarks.matrix();
  const double iodMm = (truth.col(7) - truth.col(10)).norm();
  const Pose pose =
      Pose::fromDegrees(0.0, yawDeg, rollDeg, {5.0, 3.0, -camera.focalY() * iodMm / 90.0});
  OffscreenRenderer renderer(photoHead().mesh);
  const RenderResult render = renderer.render(pose, camera);
  cv::Mat photo(render.bgra.rows, render.bgra.cols, CV_8UC3);
  for (int y = 0; y < photo.rows; ++y) {
    for (int x = 0; x < photo.cols; ++x) {
      const cv::Vec4b s = render.bgra.at<cv::Vec4b>(y, x);
      const double a = s[3] / 255.0;
      for (int c = 0; c < 3; ++c) {
        photo.at<cv::Vec3b>(y, x)[c] = static_cast<unsigned char>(a * s[c] + (1 - a) * 128.0);
      }
    }
  }
  writeImage(dir / (name + ".png"), photo);
  const Eigen::Matrix2Xd points = projectPoints(truth, pose, camera);
  LandmarkSet set(25, 2);
  for (int i = 0; i < 25; ++i) set.set(i, Eigen::Vector2d(points.col(i)));
  writeLandmarks(dir / (name + ".pts"), set, Scheme::byNameOrPath("thesis25"));
}

struct PhotoFixture {
  test::TempDir dir;
  fs::path manifest;
  PhotoFixture() {
    fs::create_directories(dir / "photos");
    writePhoto(dir / "photos", "a-frontal", 0.0, 8.0);
    writePhoto(dir / "photos", "b-turned", -25.0, 0.0);
    manifest = dir / "manifest.json";
    test::writeFile(manifest, R"({"version": 1, "procedural": [{"seeds": "1-2"}],
                                  "photos": [{"folder": "photos"}]})");
  }
};

TEST(PhotoTraining, ManifestListsThePhotosWithTrustedPoints) {
  PhotoFixture fixture;
  const DatasetManifest manifest = loadManifest(fixture.manifest);
  ASSERT_EQ(manifest.photos.size(), 1u);
  const std::vector<TrainingPhoto> photos = loadTrainingPhotos(manifest);
  ASSERT_EQ(photos.size(), 2u);
  EXPECT_EQ(photos[0].id, "a-frontal.png");
  EXPECT_EQ(photos[0].points.size(), 25);
  for (const bool trusted : photos[0].trusted) EXPECT_TRUE(trusted);  // 25-point files: all
}

TEST(PhotoTraining, PhotosJoinTheViewNearestTheirPose) {
  PhotoFixture fixture;
  const std::vector<TrainingPhoto> photos = loadTrainingPhotos(loadManifest(fixture.manifest));
  const TrainSettings s = photoSettings();
  TrainingInput input;
  input.schemeJson = schemeJsonFor("thesis25");
  input.subjects.push_back({"head1", &photoHead().mesh, &photoHead().landmarks});
  input.subjects.push_back({"head2", &otherHead().mesh, &otherHead().landmarks});
  const ClmModel shapeOnly = trainModel(input, s);  // for its shape model
  std::vector<PhotoPlacement> placements;
  const std::vector<PhotoSample> samples =
      preparePhotoSamples(photos, input.schemeJson, shapeOnly.shape, s, &placements);
  ASSERT_EQ(placements.size(), 2u);
  EXPECT_NEAR(placements[0].yawDeg, 0.0, 4.0);
  EXPECT_NEAR(placements[0].rollDeg, 8.0, 2.0);
  EXPECT_EQ(placements[0].samples, 2);  // the photo and its mirror image, both frontal
  EXPECT_NEAR(placements[1].yawDeg, -25.0, 4.0);
  EXPECT_EQ(placements[1].samples, 1);  // its mirror image would train the mirrored +30 view
  ASSERT_EQ(samples.size(), 3u);
  EXPECT_EQ(samples[0].view, 1);  // views: yaw -30, 0, +30
  EXPECT_EQ(samples[1].view, 1);
  EXPECT_EQ(samples[2].view, 0);
  EXPECT_EQ(samples[1].id, "a-frontal.png (mirrored)");

  // The turned photo's patches match those of a training render of the head at its pose: same
  // scale, upright, same place.
  SampleSpec spec;
  spec.yawDeg = placements[1].yawDeg;
  spec.pitchDeg = placements[1].pitchDeg;
  OffscreenRenderer renderer(photoHead().mesh, RenderOptions{1});
  const SamplePatches render =
      renderSample(renderer, photoHead().landmarks, {7, 10}, spec, TrainSettings(s));
  const SamplePatches& photo = samples[2].patches;
  int matching = 0;
  for (const int landmark : {0, 7, 8, 9, 10, 11, 14, 15}) {
    const Eigen::VectorXf a = photo.grey[0].col(landmark);
    const Eigen::VectorXf b = render.grey[0].col(landmark);
    const double ncc = a.dot(b) / a.size();
    if (ncc > 0.8) ++matching;
  }
  EXPECT_GE(matching, 6);
  // Expert regions at both scales, (12 + 2 x 4)^2 values per landmark.
  ASSERT_EQ(samples[0].patches.regions.size(), 2u);
  EXPECT_EQ(samples[0].patches.regions[1].rows(), 20 * 20);

  // With jitter, each placed copy also gives perturbed placements, in the same view.
  TrainSettings jittered = s;
  jittered.photoJitter = 2;
  const std::vector<PhotoSample> more =
      preparePhotoSamples(photos, input.schemeJson, shapeOnly.shape, jittered);
  ASSERT_EQ(more.size(), 9u);
  EXPECT_EQ(more[8].view, 0);
  EXPECT_EQ(more[8].id, "b-turned.png");
  EXPECT_NE(more[7].patches.grey[0], more[6].patches.grey[0]);
}

TEST(PhotoTraining, ModelTrainedWithPhotosHasExpertsAndSaysSo) {
  PhotoFixture fixture;
  TrainSettings s = photoSettings();
  std::mutex mutex;
  std::vector<double> fractions;
  const ClmModel model =
      trainFromManifest(fixture.manifest, s, "test", [&](double fraction, std::string_view) {
        const std::lock_guard lock(mutex);
        fractions.push_back(fraction);
      });
  // Progress from two worker threads only rises, to 1 (the photos' stage once reported up to
  // twice its share, and parallel stages reported out of order).
  ASSERT_FALSE(fractions.empty());
  EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
  EXPECT_GE(fractions.front(), 0.0);
  EXPECT_DOUBLE_EQ(fractions.back(), 1.0);
  EXPECT_NE(model.provenance.notes.find("3 photo samples from 2 annotated photos"),
            std::string::npos)
      << model.provenance.notes;
  EXPECT_NE(model.provenance.notes.find("licence"), std::string::npos);
  for (const ViewModel& view : model.views) {
    for (const PatchModel& patches : view.scales) {
      EXPECT_EQ(patches.experts.size(), patches.landmarks.size());
    }
  }
  EXPECT_NO_THROW(model.validate());
  // The point refiner learnt from the photos: every point is trusted in both, so all 25 are
  // refined, the windows shrinking to 0.35 eye distances.
  EXPECT_EQ(model.refiner.stages.size(), static_cast<std::size_t>(s.refinerStages));
  EXPECT_EQ(model.refiner.landmarks.size(), 25u);
  EXPECT_NEAR(model.refiner.stages.back().window, 0.35, 1e-12);
  EXPECT_NEAR(model.refiner.stages.front().window, 0.35 * std::pow(1.3, s.refinerStages - 1), 1e-9);
  // Two photos (four faces with their mirror images) are too few to learn a check from and
  // calibrate it on others: the refiner goes without one.
  EXPECT_TRUE(model.refiner.check.empty());
  s.refinerStages = 0;
  EXPECT_TRUE(trainFromManifest(fixture.manifest, s, "test").refiner.empty());
}

TEST(PhotoTraining, BadPhotoSourcesNameTheFile) {
  test::TempDir dir;
  fs::create_directories(dir / "photos");
  test::writeFile(dir / "photos" / "x.png", "not really an image");  // no landmark file
  test::writeFile(dir / "m.json", R"({"version": 1, "procedural": [{"seeds": "1"}],
                                     "photos": [{"folder": "photos"}]})");
  try {
    loadTrainingPhotos(loadManifest(dir / "m.json"));
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("x.png"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("no landmark file"), std::string::npos) << e.what();
  }
  test::writeFile(dir / "photos" / "x.pts", "version: 1\nn_points: 3\n{\n1 2\n3 4\n5 6\n}\n");
  try {
    loadTrainingPhotos(loadManifest(dir / "m.json"));
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("x.pts"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("has 3 points"), std::string::npos) << e.what();
  }
  test::writeFile(dir / "m2.json", R"({"version": 1, "procedural": [{"seeds": "1"}],
                                      "photos": [{"folder": "photos", "list": "l.txt"}]})");
  EXPECT_THROW(loadManifest(dir / "m2.json"), InputError);
}

// Renders the head at (0, yaw, 0) over mid-grey into a small DIR/NAME.png (`size` pixels, the eye
// distance about size/4, as AFLW's 120 x 120 crops) with its points in AFLW's 21-point scheme:
// each point with a thesis counterpart where the render shows it, "-1 -1" where the head hides
// it; the brow and mouth centres (no counterpart) between their neighbours. Returns the thesis
// points (0-based) that the file marks.
std::vector<bool> writeAflwPhoto(const fs::path& dir, const std::string& name, double yawDeg,
                                 int size) {
  const Camera camera = Camera::fromVerticalFov(size, size, 40.0);
  const Eigen::Matrix3Xd truth = photoHead().landmarks.matrix();
  const double iodMm = (truth.col(7) - truth.col(10)).norm();
  const Pose pose =
      Pose::fromDegrees(0.0, yawDeg, 0.0, {0.0, 0.0, -camera.focalY() * iodMm / (size / 4.0)});
  OffscreenRenderer renderer(photoHead().mesh);
  const RenderResult render = renderer.render(pose, camera);
  cv::Mat photo(render.bgra.rows, render.bgra.cols, CV_8UC3);
  for (int y = 0; y < photo.rows; ++y) {
    for (int x = 0; x < photo.cols; ++x) {
      const cv::Vec4b s = render.bgra.at<cv::Vec4b>(y, x);
      const double a = s[3] / 255.0;
      for (int c = 0; c < 3; ++c) {
        photo.at<cv::Vec3b>(y, x)[c] = static_cast<unsigned char>(a * s[c] + (1 - a) * 128.0);
      }
    }
  }
  writeImage(dir / (name + ".png"), photo);
  const Eigen::Matrix2Xd points = projectPoints(truth, pose, camera);
  const SchemeMap& map = aflw21ToThesis25Map();
  std::vector<Eigen::Vector2d> aflw(21, Eigen::Vector2d(-1.0, -1.0));
  std::vector<bool> marked(25, false);
  for (int t = 0; t < 25; ++t) {
    const auto& entry = map.entries[static_cast<std::size_t>(t)];
    if (entry.sources.size() != 1 || !render.isVisible(truth.col(t))) continue;
    aflw[static_cast<std::size_t>(entry.sources[0])] = points.col(t) + Eigen::Vector2d(1.0, 1.0);
    marked[static_cast<std::size_t>(t)] = true;
  }
  // AFLW 2, 5 (brow centres) and 19 (mouth centre): no thesis counterpart.
  aflw[1] = (aflw[0] + aflw[2]) / 2.0;
  aflw[4] = (aflw[3] + aflw[5]) / 2.0;
  aflw[18] = (aflw[17] + aflw[19]) / 2.0;
  std::string text = "version: 1\nn_points: 21\n{\n";
  for (const Eigen::Vector2d& p : aflw) {
    text += p.x() == -1.0 ? std::string("-1 -1\n")
                          : std::to_string(p.x()) + " " + std::to_string(p.y()) + "\n";
  }
  test::writeFile(dir / (name + ".pts"), text + "}\n");
  return marked;
}

// A photo in another scheme (AFLW's 21 points, points hidden by the turn written "-1 -1") trains
// patches only for the points it marks, joins the view of the pose fitted to those points, is
// brought from its small crop to the training scale, and a source's per_view caps its copies in
// a view.
TEST(PhotoTraining, AflwPhotosTrainOnlyTheirMarkedPointsInTheViewOfTheirPose) {
  test::TempDir dir;
  fs::create_directories(dir / "aflw");
  const std::vector<bool> marked = writeAflwPhoto(dir / "aflw", "a-turned", -50.0, 120);
  writeAflwPhoto(dir / "aflw", "b-turned", -45.0, 120);
  test::writeFile(dir / "m.json", R"({"version": 1, "procedural": [{"seeds": "1-2"}],
                                     "photos": [{"folder": "aflw", "per_view": 1,
                                                 "refiner": false}]})");
  const std::vector<TrainingPhoto> photos = loadTrainingPhotos(loadManifest(dir / "m.json"));
  ASSERT_EQ(photos.size(), 2u);
  int hidden = 0;
  for (int t = 0; t < 25; ++t) {
    EXPECT_EQ(photos[0].trusted[static_cast<std::size_t>(t)], marked[static_cast<std::size_t>(t)])
        << "thesis " << t + 1;
    const auto& entry = aflw21ToThesis25Map().entries[static_cast<std::size_t>(t)];
    hidden += entry.sources.size() == 1 && !marked[static_cast<std::size_t>(t)] ? 1 : 0;
  }
  EXPECT_GE(hidden, 1);  // the turn hides at least the far ear lobe
  EXPECT_FALSE(photos[0].refiner);

  TrainSettings s = photoSettings();
  s.yawsDeg = {-60, -30, 0, 30, 60};
  TrainingInput input;
  input.schemeJson = schemeJsonFor("thesis25");
  input.subjects.push_back({"head1", &photoHead().mesh, &photoHead().landmarks});
  input.subjects.push_back({"head2", &otherHead().mesh, &otherHead().landmarks});
  const ClmModel shapeOnly = trainModel(input, s);
  std::vector<PhotoPlacement> placements;
  const std::vector<PhotoSample> samples =
      preparePhotoSamples(photos, input.schemeJson, shapeOnly.shape, s, &placements);
  ASSERT_EQ(placements.size(), 2u);
  EXPECT_NEAR(placements[0].yawDeg, -50.0, 6.0);
  EXPECT_NEAR(placements[1].yawDeg, -45.0, 6.0);
  // Its mirror image (+50) would train the mirrored +60 view; the second photo's copy finds the
  // -60 view full.
  EXPECT_EQ(placements[0].samples, 1);
  EXPECT_EQ(placements[1].samples, 0);
  EXPECT_EQ(placements[1].capped, 1);
  EXPECT_TRUE(placements[1].skipped.empty()) << placements[1].skipped;
  ASSERT_EQ(samples.size(), 1u);
  EXPECT_EQ(samples[0].view, 0);                             // views: yaw -60, -30, 0, +30, +60
  EXPECT_EQ(samples[0].patches.visible, photos[0].trusted);  // only marked points give patches

  // Brought to the training scale: the patches of the near side's points (the subject's left,
  // seen nearly square-on; the far side's are too foreshortened to compare across a few degrees
  // of fitted yaw) match a training render's at the same pose.
  SampleSpec spec;
  spec.yawDeg = placements[0].yawDeg;
  spec.pitchDeg = placements[0].pitchDeg;
  OffscreenRenderer renderer(photoHead().mesh, RenderOptions{1});
  const SamplePatches render =
      renderSample(renderer, photoHead().landmarks, {7, 10}, spec, TrainSettings(s));
  for (const int landmark : {1, 3, 4, 7, 8, 12, 14}) {
    ASSERT_TRUE(photos[0].trusted[static_cast<std::size_t>(landmark)]) << landmark;
    const Eigen::VectorXf a = samples[0].patches.grey[0].col(landmark);
    const Eigen::VectorXf b = render.grey[0].col(landmark);
    EXPECT_GT(a.dot(b) / a.size(), 0.85) << "thesis " << landmark + 1;
  }

  // The point refiner does not learn from a source that says `refiner: false`.
  EXPECT_TRUE(trainPhotoRefiner(photos, Scheme::thesis25(), s).empty());
  std::vector<TrainingPhoto> forRefiner = photos;
  for (TrainingPhoto& photo : forRefiner) photo.refiner = true;
  EXPECT_FALSE(trainPhotoRefiner(forRefiner, Scheme::thesis25(), s).empty());

  // Without the cap both photos join the view.
  std::vector<TrainingPhoto> uncapped = photos;
  for (TrainingPhoto& photo : uncapped) photo.perView = 0;
  EXPECT_EQ(preparePhotoSamples(uncapped, input.schemeJson, shapeOnly.shape, s).size(), 2u);
}

// With hidden-point removal off (hidden share 1) a view keeps landmarks hidden in all of its
// renders; their experts learn from where the points project, so every kept landmark has one.
TEST(ExpertTrainingInModels, HiddenShareOneGivesEveryKeptLandmarkAnExpert) {
  TrainSettings s = photoSettings();
  s.yawsDeg = {-60};
  s.scales = 1;
  s.hiddenShare = 1.0;
  TrainingInput input;
  input.schemeJson = schemeJsonFor("thesis25");
  input.subjects.push_back({"head1", &photoHead().mesh, &photoHead().landmarks});
  input.subjects.push_back({"head2", &otherHead().mesh, &otherHead().landmarks});
  const ClmModel model = trainModel(input, s);
  const PatchModel& patches = model.views.front().scales.front();
  EXPECT_EQ(patches.landmarks.size(), 25u);
  ASSERT_EQ(patches.experts.size(), 25u);
  for (const PatchExpert& expert : patches.experts) EXPECT_FALSE(expert.empty());
}

}  // namespace
}  // namespace clm3d
