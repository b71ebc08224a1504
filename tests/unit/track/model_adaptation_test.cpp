// Tests of adapting a model to one video (core/train/model_adaptation, core/track/
// video_adaptation): a held-out procedural head turning, a few of its frames "corrected" with
// their exact truth, the fixture model adapted to them tracks the other frames with a lower error;
// the same seed gives the same model whatever the thread count; bad frames and truths are refused
// naming what is wrong; cancelling throws and the general model is untouched.
#include "core/train/model_adaptation.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <iostream>

#include "core/common/error.hpp"
#include "core/detect/initialisation.hpp"
#include "core/eval/synthetic_sequence.hpp"
#include "core/model/model_file.hpp"
#include "core/track/adapt_request.hpp"
#include "core/track/tracker.hpp"
#include "core/track/video_adaptation.hpp"
#include "tests/support/fit_fixture.hpp"
#include "tests/support/refiner_fixture.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

// The held-out head turning 0 -> 40 degrees a degree a frame at 640x480 (41 frames), lit from its
// right side and dimmer than any training render: this video's person and light are new to the
// fixture model, whose track drifts off the face.
SequenceSettings adaptSequence() {
  SequenceSettings settings;
  settings.lighting.direction = Eigen::Vector3d(-1.0, 0.2, 0.5);
  settings.lighting.ambient = 0.3;
  settings.lighting.diffuse = 0.9;
  settings.yawFromDeg = 0.0;
  settings.yawToDeg = 40.0;
  settings.stepDeg = 1.0;
  settings.supersample = 1;
  return settings;
}

struct RenderedSequence {
  Camera camera;
  std::vector<SequenceFrame> frames;
};

const RenderedSequence& renderedSequence() {
  static const RenderedSequence sequence = [] {
    const SynthHead& head = test::fitTestHead(test::kHeldOutHead);
    SequenceRenderer renderer(head.mesh, head.landmarks, Scheme::thesis25(), adaptSequence());
    RenderedSequence out{renderer.camera(), {}};
    for (int i = 0; i < renderer.frameCount(); ++i) out.frames.push_back(renderer.render(i));
    return out;
  }();
  return sequence;
}

bool isCorrected(int frame) {
  return frame % 4 == 0;
}

std::vector<AdaptationFrame> sequenceCorrections(const RenderedSequence& sequence) {
  std::vector<AdaptationFrame> frames;
  for (int i = 0; i < static_cast<int>(sequence.frames.size()); ++i) {
    if (!isCorrected(i)) continue;
    const SequenceFrame& frame = sequence.frames[static_cast<std::size_t>(i)];
    frames.push_back({i, frame.bgr, frame.points});
  }
  return frames;
}

// Mean error (eq. 5.1) over the frames that were not corrected, tracking every frame from the
// truth of frame 0 moved 3 pixels.
double errorOnOtherFrames(const ClmModel& model, const RenderedSequence& sequence) {
  TrackerSettings settings;
  settings.fit.optimiser = "rlms";
  Tracker tracker(model, sequence.camera, settings);
  Eigen::Matrix2Xd start = sequence.frames.front().points;
  start.row(0).array() += 3.0;
  tracker.setState(stateFromPoints(model, sequence.camera, start, std::vector<bool>(25, true)));
  double sum = 0.0;
  int count = 0;
  for (int i = 0; i < static_cast<int>(sequence.frames.size()); ++i) {
    const SequenceFrame& frame = sequence.frames[static_cast<std::size_t>(i)];
    const TrackStep step = tracker.track(frame.bgr, i, i / 30.0);
    if (isCorrected(i)) continue;
    const double interOcular = (frame.points.col(7) - frame.points.col(10)).norm();
    const Eigen::Matrix2Xd& points = step.row.points;
    sum += points.allFinite() ? test::meanPointError(points, frame.points) / interOcular : 1.0;
    ++count;
  }
  return sum / count;
}

TEST(ModelAdaptation, CorrectedFramesLowerTheErrorOnTheOtherFrames) {
  const ClmModel& general = test::fitTestModel();
  const RenderedSequence& sequence = renderedSequence();
  AdaptSettings settings;
  settings.threads = 2;
  AdaptationSummary summary;
  const ClmModel adapted = adaptModel(general, sequenceCorrections(sequence), settings, &summary);
  EXPECT_EQ(summary.frames, 11);
  EXPECT_EQ(summary.framesUsed.size(), 11u);
  EXPECT_TRUE(summary.skipped.empty());
  EXPECT_GT(summary.expertsAdapted, 0);
  EXPECT_GT(summary.templatesAdapted, 0);
  EXPECT_EQ(adapted.adaptation.frames, (std::vector<int>{0, 4, 8, 12, 16, 20, 24, 28, 32, 36, 40}));

  const double before = errorOnOtherFrames(general, sequence);
  const double after = errorOnOtherFrames(adapted, sequence);
  std::cout << "error on the 30 frames not corrected: general " << before << ", adapted " << after
            << "\n";
  EXPECT_LT(after, before);
}

// A model with a point refiner (as one trained with photos has) gets its refiner adapted too, from
// every corrected frame and its mirror image, and says so; --refiner-prior 0 leaves it as it was.
TEST(ModelAdaptation, ThePointRefinerIsAdaptedFromTheFramesAndTheirMirrorImages) {
  ClmModel general = test::fitTestModel();
  general.refiner = test::photoRefiner();
  std::vector<AdaptationFrame> frames = sequenceCorrections(renderedSequence());
  frames.resize(4);
  AdaptSettings settings;
  settings.jitter = 1;
  settings.threads = 2;
  AdaptationSummary summary;
  const ClmModel adapted = adaptModel(general, frames, settings, &summary);
  EXPECT_EQ(summary.refinerFaces, 8);
  ASSERT_EQ(adapted.refiner.stages.size(), general.refiner.stages.size());
  EXPECT_FALSE(adapted.refiner.stages.back().bias.isApprox(general.refiner.stages.back().bias));
  EXPECT_EQ(adapted.refiner.meanShape, general.refiner.meanShape);
  EXPECT_NE(adapted.provenance.notes.find("point refiner adapted to 8 faces"), std::string::npos)
      << adapted.provenance.notes;

  settings.refinerPrior = 0.0;
  const ClmModel kept = adaptModel(general, frames, settings, &summary);
  EXPECT_EQ(summary.refinerFaces, 0);
  EXPECT_EQ(kept.refiner.stages.back().bias, general.refiner.stages.back().bias);
  settings.refinerPrior = -1.0;
  EXPECT_THROW(adaptModel(general, frames, settings), InputError);
}

TEST(ModelAdaptation, SameSeedSameModelWhateverTheThreads) {
  const ClmModel& general = test::fitTestModel();
  std::vector<AdaptationFrame> frames = sequenceCorrections(renderedSequence());
  frames.resize(4);
  AdaptSettings settings;
  settings.jitter = 1;
  settings.threads = 1;
  const std::string one = serializeModel(adaptModel(general, frames, settings));
  settings.threads = 2;
  ClmModel two = adaptModel(general, frames, settings);
  ClmModel first = parseModel(one, "one");
  two.provenance.created = first.provenance.created;  // the clock
  EXPECT_EQ(serializeModel(two), serializeModel(first));
  settings.seed = 2;
  ClmModel other = adaptModel(general, frames, settings);
  other.provenance.created = first.provenance.created;
  EXPECT_NE(serializeModel(other), serializeModel(first));
}

TEST(ModelAdaptation, BadFramesAreRefusedSayingWhy) {
  const ClmModel& general = test::fitTestModel();
  EXPECT_THROW(adaptModel(general, {}, AdaptSettings{}), InputError);
  std::vector<AdaptationFrame> frames = sequenceCorrections(renderedSequence());
  frames.resize(1);
  frames[0].points.conservativeResize(2, 3);
  try {
    adaptModel(general, frames, AdaptSettings{});
    FAIL() << "three points accepted";
  } catch (const InputError& e) {
    EXPECT_TRUE(test::contains(e.what(), "frame 0 has 3 points")) << e.what();
  }
  // Points nowhere near a face cannot be placed in a view.
  frames = sequenceCorrections(renderedSequence());
  frames.resize(1);
  frames[0].points.setConstant(std::numeric_limits<double>::quiet_NaN());
  try {
    adaptModel(general, frames, AdaptSettings{});
    FAIL() << "a frame without points accepted";
  } catch (const InputError& e) {
    EXPECT_TRUE(test::contains(e.what(), "none of the 1 corrected frames")) << e.what();
  }
}

TEST(ModelAdaptation, CancelThrowsAndLeavesTheGeneralModelAsItWas) {
  const ClmModel& general = test::fitTestModel();
  const std::string before = serializeModel(general);
  CancelToken cancel;
  cancel.cancel();
  EXPECT_THROW(adaptModel(general, sequenceCorrections(renderedSequence()), AdaptSettings{},
                          nullptr, {}, &cancel),
               Cancelled);
  EXPECT_EQ(serializeModel(general), before);
}

// The video's corrected frames: a truth whose landmark count is not the model's, one without
// keyframes and a video shorter than a keyframe are refused naming the file; the adapted model
// records where it came from.
TEST(VideoAdaptation, ReadsTheKeyframesFromTheVideoAndRecordsWhereItCameFrom) {
  const test::TempDir dir;
  SequenceSettings settings = adaptSequence();
  settings.yawToDeg = 6.0;
  settings.width = 320;
  settings.height = 240;
  settings.interOcularPixels = 56.0;
  const SequenceFiles files = SequenceFiles::inFolder(dir.path());
  const SynthHead& head = test::fitTestHead(test::kHeldOutHead);
  const SequenceSummary written =
      writeSyntheticSequence(head.mesh, head.landmarks, Scheme::thesis25(), settings, {}, files);
  ASSERT_EQ(written.frames, 7);
  const ClmModel& general = test::fitTestModel();
  const auto modelPath = dir / "general.clm3d";
  saveModel(general, modelPath);

  GroundTruthSet truth = GroundTruthSet::fromTrack(written.truth, written.frames);
  try {
    adaptToVideo(general, modelPath, files.video, truth, "gt.csv", AdaptSettings{});
    FAIL() << "a truth without keyframes accepted";
  } catch (const InputError& e) {
    EXPECT_TRUE(test::contains(e.what(), "gt.csv: has no corrected frames")) << e.what();
  }
  truth.setKeyframe(2, written.truth.rows[2].points);
  truth.setKeyframe(5, written.truth.rows[5].points);
  EXPECT_EQ(correctedFrames(truth), (std::vector<int>{2, 5}));
  AdaptSettings adapt;
  adapt.jitter = 1;
  const ClmModel adapted = adaptToVideo(general, modelPath, files.video, truth, "gt.csv", adapt);
  EXPECT_EQ(adapted.adaptation.model, modelPath.string());
  EXPECT_EQ(adapted.adaptation.modelCrc32.size(), 8u);
  EXPECT_EQ(adapted.adaptation.video, files.video.string());
  EXPECT_EQ(adapted.adaptation.truth, "gt.csv");
  EXPECT_EQ(adapted.adaptation.frames, (std::vector<int>{2, 5}));

  GroundTruthSet longer = truth;
  longer.padTo(12);
  longer.setKeyframe(11, written.truth.rows[5].points);
  try {
    adaptToVideo(general, modelPath, files.video, longer, "gt.csv", adapt);
    FAIL() << "a keyframe beyond the video accepted";
  } catch (const InputError& e) {
    EXPECT_TRUE(
        test::contains(e.what(), files.video.string() + ": gives no image for corrected frame 11"))
        << e.what();
  }

  // Cancelled, `clm3d adapt` writes nothing.
  const auto truthPath = dir / "gt.csv";
  saveGroundTruth(truthPath, truth);
  AdaptRequest request;
  request.model = modelPath;
  request.video = files.video;
  request.truth = truthPath;
  request.out = dir / "adapted.clm3d";
  CancelToken cancel;
  cancel.cancel();
  EXPECT_THROW(runAdapt(request, {}, &cancel), Cancelled);
  EXPECT_FALSE(std::filesystem::exists(request.out));
  EXPECT_TRUE(test::contains(runAdapt(request).text, "to 2 of 2 corrected frames"));
  EXPECT_EQ(loadModel(request.out).adaptation.frames, (std::vector<int>{2, 5}));

  TrackTable five = written.truth;
  five.landmarkCount = 5;
  for (TrackRow& row : five.rows) row.points.conservativeResize(2, 5);
  GroundTruthSet wrong = GroundTruthSet::fromTrack(five, written.frames);
  wrong.setKeyframe(1, five.rows[1].points);
  try {
    adaptToVideo(general, modelPath, files.video, wrong, "gt.csv", adapt);
    FAIL() << "five landmarks accepted";
  } catch (const InputError& e) {
    EXPECT_TRUE(test::contains(e.what(), "gt.csv: has 5 landmarks")) << e.what();
  }
}

}  // namespace
}  // namespace clm3d
