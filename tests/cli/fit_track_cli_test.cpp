// clm3d fit and clm3d track through the real binary, on the fit fixture's model and renders of a
// procedural head: a fit from given points and from the detector, a short tracked video with its
// overlay evaluated against the truth, and the bad inputs the issue names (an unreadable video, a
// model of another scheme, an image without a face), which must exit 1 naming the problem.
#include <gtest/gtest.h>

#include <algorithm>
#include <opencv2/core.hpp>

#include "core/common/atomic_file.hpp"
#include "core/eval/synthetic_sequence.hpp"
#include "core/model/model_file.hpp"
#include "core/scheme/landmark_file.hpp"
#include "core/track/track_table.hpp"
#include "core/video/video_writer.hpp"
#include "core/viz/image_file.hpp"
#include "tests/support/fit_fixture.hpp"
#include "tests/support/test_support.hpp"
#include "tests/support/tiny_model.hpp"

namespace clm3d {
namespace {

using test::runClm3d;

struct FitFiles {
  test::TempDir dir;
  std::string model, image, init, blank;
  test::FitScene scene;
};

void fillFitFiles(FitFiles& f) {
  {
    f.model = (f.dir / "model.clm3d").string();
    saveModel(test::fitTestModel(), f.model);
    // Rendered with the video camera's 40 degrees; `clm3d fit` assumes a still image's 20 unless
    // told (FitCli.AStillImagesCameraIs20DegreesUnlessFovSaysOtherwise).
    f.scene = test::makeFitScene(test::fitTestModel(), 0.0, 15.0, test::kHeldOutHead, 70.0);
    f.image = (f.dir / "face.png").string();
    writeImage(f.image, f.scene.image);
    LandmarkSet start(25, 2);
    for (int i = 0; i < 25; ++i) {
      start.set(i, Eigen::Vector2d(f.scene.truthPoints.col(i) + Eigen::Vector2d(3.0, -2.0)));
    }
    f.init = (f.dir / "start.pts").string();
    writeLandmarks(f.init, start, Scheme::thesis25());
    f.blank = (f.dir / "blank.png").string();
    writeImage(f.blank, cv::Mat(240, 320, CV_8UC3, cv::Scalar(90, 90, 90)));
  }
}

const FitFiles& fitFiles() {
  static FitFiles files;
  static const bool filled = (fillFitFiles(files), true);
  (void)filled;
  return files;
}

double errorOf(const std::string& ptsPath, const test::FitScene& scene) {
  const LandmarkSet found = readLandmarks(ptsPath, &Scheme::thesis25());
  Eigen::Matrix2Xd points(2, 25);
  for (int i = 0; i < 25; ++i) points.col(i) = found.point(i).head<2>();
  return test::meanPointError(points, scene.truthPoints) / scene.interOcular;
}

TEST(FitCli, FitsFromGivenPointsAndWritesTheOverlay) {
  const FitFiles& f = fitFiles();
  const std::string out = (f.dir / "fit.pts").string();
  const std::string overlay = (f.dir / "fit.png").string();
  const auto result = runClm3d("fit --model " + f.model + " --image " + f.image + " --init " +
                               f.init + " --out " + out + " --overlay " + overlay);
  ASSERT_EQ(result.exitCode, 0) << result.output;
  EXPECT_NE(result.output.find("probability"), std::string::npos) << result.output;
  EXPECT_LT(errorOf(out, f.scene), 0.08);
  EXPECT_FALSE(readImage(overlay).empty());
}

TEST(FitCli, FitsFromTheFaceDetector) {
  const FitFiles& f = fitFiles();
  const std::string out = (f.dir / "detected.ljson").string();
  const auto result = runClm3d("fit --model " + f.model + " --image " + f.image + " --out " + out);
  ASSERT_EQ(result.exitCode, 0) << result.output;
  EXPECT_LT(errorOf(out, f.scene), 0.12);
}

// A still image's camera has a 20-degree field of view by default (kStillImageVerticalFovDeg): the
// points written without --fov are those of --fov 20, byte for byte, not those of --fov 40.
TEST(FitCli, AStillImagesCameraIs20DegreesUnlessFovSaysOtherwise) {
  const FitFiles& f = fitFiles();
  const auto fit = [&](const std::string& name, const std::string& options) {
    const std::string out = (f.dir / name).string();
    const auto result =
        runClm3d("fit --model " + f.model + " --image " + f.image + " --out " + out + options);
    EXPECT_EQ(result.exitCode, 0) << result.output;
    return readTextFile(out);
  };
  const std::string byDefault = fit("camera-default.pts", "");
  EXPECT_EQ(byDefault, fit("camera-20.pts", " --fov 20"));
  EXPECT_NE(byDefault, fit("camera-40.pts", " --fov 40"));
}

TEST(FitCli, EveryOptimiserRunsFromTheCommandLine) {
  const FitFiles& f = fitFiles();
  for (const char* optimiser :
       {"powell", "nelder-mead", "gauss-newton", "fastncc", "condensation"}) {
    const std::string out = (f.dir / (std::string(optimiser) + ".pts")).string();
    const auto result = runClm3d("fit --model " + f.model + " --image " + f.image + " --init " +
                                 f.init + " --optimiser " + optimiser + " --out " + out);
    ASSERT_EQ(result.exitCode, 0) << optimiser << ": " << result.output;
    EXPECT_LT(errorOf(out, f.scene), 0.1) << optimiser;
  }
}

TEST(FitCli, AnImageWithoutAFaceIsAClearError) {
  const FitFiles& f = fitFiles();
  const auto result = runClm3d("fit --model " + f.model + " --image " + f.blank + " --out " +
                               (f.dir / "none.pts").string());
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_NE(result.output.find("no face found"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("blank.png"), std::string::npos) << result.output;
}

TEST(FitCli, AModelOfAnotherSchemeIsAClearError) {
  const FitFiles& f = fitFiles();
  const std::string tiny = (f.dir / "tiny.clm3d").string();
  saveModel(test::makeTinyModel(), tiny);
  const auto result = runClm3d("fit --model " + tiny + " --image " + f.image + " --init " + f.init +
                               " --out " + (f.dir / "tiny.pts").string());
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_NE(result.output.find("start.pts"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("tiny5"), std::string::npos) << result.output;
}

TEST(FitCli, UnknownOptimiserListsTheValidOnes) {
  const FitFiles& f = fitFiles();
  const auto result = runClm3d("fit --model " + f.model + " --image " + f.image +
                               " --optimiser simulated-annealing --out x.pts");
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_NE(result.output.find("fastncc"), std::string::npos) << result.output;
}

// The held-out head turning from 0 to yawTo degrees in steps of stepDeg, 320x240, in `folder`.
SequenceFiles turningHead(const std::filesystem::path& folder, double yawTo, double stepDeg) {
  const SynthHead& head = test::fitTestHead(test::kHeldOutHead);
  SequenceSettings settings;
  settings.yawFromDeg = 0.0;
  settings.yawToDeg = yawTo;
  settings.stepDeg = stepDeg;
  settings.width = 320;
  settings.height = 240;
  settings.interOcularPixels = 60.0;
  settings.supersample = 1;
  const SequenceFiles files = SequenceFiles::inFolder(folder);
  writeSyntheticSequence(head.mesh, head.landmarks, Scheme::thesis25(), settings, {}, files);
  return files;
}

TEST(TrackCli, TracksAShortVideoWritesOverlayAndEvaluates) {
  const FitFiles& f = fitFiles();
  const SequenceFiles files = turningHead(f.dir / "sequence", 10.0, 2.0);
  const std::string tracks = (f.dir / "tracks.csv").string();
  const std::string overlay = (f.dir / "overlay.avi").string();
  const auto result = runClm3d("track --quiet --model " + f.model + " --video " +
                               files.video.string() + " --out " + tracks + " --overlay " + overlay);
  ASSERT_EQ(result.exitCode, 0) << result.output;
  EXPECT_NE(result.output.find("fit time per frame: median"), std::string::npos) << result.output;
  const TrackTable table = readTrackTable(tracks);
  ASSERT_EQ(table.rows.size(), 6u);
  for (const TrackRow& row : table.rows) {
    EXPECT_TRUE(row.success) << "frame " << row.frame;
    ASSERT_EQ(row.visibility.size(), 25u) << "frame " << row.frame;  // visible_1..visible_25
    EXPECT_EQ(std::count(row.visibility.begin(), row.visibility.end(), Visibility::Unknown), 0);
  }
  EXPECT_TRUE(std::filesystem::exists(overlay));
  const auto eval = runClm3d("eval --truth " + files.truth.string() + " --pred " + tracks);
  ASSERT_EQ(eval.exitCode, 0) << eval.output;

  // rlms is judged on the one probability, its experts' response through the built-in curve: every
  // frame tracked with a threshold for this small model's experts (12 renders a view score faces
  // 0.41-0.55, lower than a photo-trained model's; the curve puts 0.35 at 0.19), none with an
  // impossible one. The option's former name still works; the thresholds on the optimisers' own
  // scales it replaced are refused.
  const auto rlms = [&](const std::string& options) {
    const auto run =
        runClm3d("track --quiet --model " + f.model + " --video " + files.video.string() +
                 " --out " + tracks + " --optimiser rlms " + options);
    EXPECT_EQ(run.exitCode, 0) << run.output;
    int succeeded = 0;
    for (const TrackRow& row : readTrackTable(tracks).rows) succeeded += row.success ? 1 : 0;
    return succeeded;
  };
  EXPECT_EQ(rlms("--min-probability 0.19"), 6);
  EXPECT_EQ(rlms("--min-check-probability 0.99"), 0);
  const auto retired =
      runClm3d("track --quiet --model " + f.model + " --video " + files.video.string() + " --out " +
               tracks + " --min-expert-confidence 0.35");
  EXPECT_NE(retired.exitCode, 0);
  EXPECT_NE(retired.output.find("min-expert-confidence"), std::string::npos) << retired.output;
}

// --last tracks a segment from the start (the rows end at that frame, nothing marked missing after
// it), and --fov reaches the tracker's camera: with a 25-degree camera the face, the same size in
// the image, is fitted about 1.6 times as far away (tan 20 / tan 12.5) relative to its scale.
TEST(TrackCli, LastTracksASegmentAndFovReachesTheTrackersCamera) {
  const FitFiles& f = fitFiles();
  const SequenceFiles files = turningHead(f.dir / "segment-sequence", 10.0, 2.0);
  const std::string track =
      "track --quiet --model " + f.model + " --video " + files.video.string() + " --out ";
  const std::string wide = (f.dir / "segment.csv").string();
  const std::string narrow = (f.dir / "segment-fov25.csv").string();
  ASSERT_EQ(runClm3d(track + wide + " --last 2").exitCode, 0);
  const auto run = runClm3d(track + narrow + " --last 2 --fov 25");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const TrackTable a = readTrackTable(wide);
  const TrackTable b = readTrackTable(narrow);
  ASSERT_EQ(a.rows.size(), 3u);
  ASSERT_EQ(b.rows.size(), 3u);
  EXPECT_EQ(a.rows.back().frame, 2);
  for (std::size_t i = 0; i < a.rows.size(); ++i) {
    ASSERT_TRUE(a.rows[i].pose && b.rows[i].pose) << i;
    const double distanceA = -a.rows[i].pose->translation.z() / a.rows[i].pose->scale;
    const double distanceB = -b.rows[i].pose->translation.z() / b.rows[i].pose->scale;
    EXPECT_GT(distanceB / distanceA, 1.3) << "frame " << i;
    EXPECT_LT(distanceB / distanceA, 2.0) << "frame " << i;
  }
  const auto usage = runClm3d(track + wide + " --last -2");
  EXPECT_EQ(usage.exitCode, 2) << usage.output;
  EXPECT_NE(usage.output.find("--last"), std::string::npos) << usage.output;
}

// --smooth and its parameters reach the tracker: the same frames succeed, later points move, the
// eval prints the jitter; impossible parameters are usage errors naming the option.
TEST(TrackCli, SmoothOptionsSmoothThePointsAndEvalReportsJitter) {
  const FitFiles& f = fitFiles();
  const SequenceFiles files = turningHead(f.dir / "smooth-sequence", 8.0, 1.0);
  const std::string raw = (f.dir / "raw.csv").string();
  const std::string smooth = (f.dir / "smooth.csv").string();
  const std::string track =
      "track --quiet --model " + f.model + " --video " + files.video.string() + " --out ";
  ASSERT_EQ(runClm3d(track + raw).exitCode, 0);
  const auto run = runClm3d(track + smooth + " --smooth --smooth-min-cutoff 0.5 --smooth-beta 2");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const TrackTable a = readTrackTable(raw);
  const TrackTable b = readTrackTable(smooth);
  ASSERT_EQ(a.rows.size(), b.rows.size());
  int moved = 0;
  for (std::size_t i = 0; i < a.rows.size(); ++i) {
    EXPECT_EQ(a.rows[i].success, b.rows[i].success) << i;
    EXPECT_EQ(a.rows[i].confidence, b.rows[i].confidence) << i;
    ASSERT_EQ(a.rows[i].landmarkConfidence.size(), 25U);  // conf_k
    moved += (a.rows[i].points - b.rows[i].points).cwiseAbs().maxCoeff() > 1e-3 ? 1 : 0;
  }
  EXPECT_EQ(a.rows[0].points, b.rows[0].points);  // the first frame passes through
  EXPECT_GT(moved, 0);
  const auto eval = runClm3d("eval --truth " + files.truth.string() + " --pred " + smooth);
  ASSERT_EQ(eval.exitCode, 0) << eval.output;
  EXPECT_NE(eval.output.find("motion: jitter "), std::string::npos) << eval.output;

  for (const char* bad : {"--smooth-min-cutoff 0", "--smooth-beta -1"}) {
    const auto usage = runClm3d(track + smooth + " --smooth " + bad);
    EXPECT_EQ(usage.exitCode, 2) << bad << ": " << usage.output;
    EXPECT_NE(usage.output.find(std::string(bad).substr(0, std::string(bad).find(' '))),
              std::string::npos)
        << usage.output;
  }
}

TEST(TrackCli, AnUnreadableVideoIsAClearError) {
  const FitFiles& f = fitFiles();
  const std::string fake = (f.dir / "not-a-video.mp4").string();
  test::writeFile(fake, "this is text, not a video\n");
  const auto result = runClm3d("track --model " + f.model + " --video " + fake + " --out " +
                               (f.dir / "t.csv").string());
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_NE(result.output.find("not-a-video.mp4"), std::string::npos) << result.output;
}

TEST(TrackCli, ABrokenModelFileIsAClearError) {
  const FitFiles& f = fitFiles();
  const std::string broken = (f.dir / "broken.clm3d").string();
  const std::string bytes = test::readFile(f.model);
  test::writeFile(broken, bytes.substr(0, bytes.size() / 3));
  const auto result = runClm3d("track --model " + broken + " --video x.avi --out t.csv");
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_NE(result.output.find("broken.clm3d"), std::string::npos) << result.output;
}

}  // namespace
}  // namespace clm3d
