// Tests of the tracker: following a held-out procedural head through a short synthetic rotation
// from the previous frame, marking a frame without a face as failed and recovering by detection,
// and drawing the overlay (patches and landmarks) of thesis figure 5.5.
#include "core/track/tracker.hpp"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "core/detect/initialisation.hpp"
#include "core/eval/synthetic_sequence.hpp"
#include "core/track/fit_overlay.hpp"
#include "tests/support/fit_fixture.hpp"

namespace clm3d {
namespace {

SequenceSettings shortSequence(double yawTo) {
  SequenceSettings settings;
  settings.yawFromDeg = 0.0;
  settings.yawToDeg = yawTo;
  settings.stepDeg = 2.0;
  settings.width = 320;
  settings.height = 240;
  settings.interOcularPixels = 56.0;
  settings.supersample = 1;
  return settings;
}

double frameError(const Eigen::Matrix2Xd& predicted, const Eigen::Matrix2Xd& truth) {
  const double interOcular = (truth.col(7) - truth.col(10)).norm();
  return test::meanPointError(predicted, truth) / interOcular;
}

TEST(Tracker, FollowsAHeldOutHeadFromTheFirstFrame) {
  const ClmModel& model = test::fitTestModel();
  const SynthHead& head = test::fitTestHead(test::kHeldOutHead);
  SequenceRenderer sequence(head.mesh, head.landmarks, Scheme::thesis25(), shortSequence(20.0));
  TrackerSettings settings;
  Tracker tracker(model, sequence.camera(), settings);
  // Start from the truth of frame 0 perturbed a little, as a detection would.
  SequenceFrame first = sequence.render(0);
  std::vector<bool> present(25, true);
  double worst = 0.0;
  for (int i = 0; i < sequence.frameCount(); ++i) {
    const SequenceFrame frame = i == 0 ? first : sequence.render(i);
    if (i == 0) {
      // A start 3 pixels off the truth.
      Eigen::Matrix2Xd start = frame.points;
      start.row(0).array() += 3.0;
      tracker.setState(stateFromPoints(model, sequence.camera(), start, present));
    }
    const TrackStep step = tracker.track(frame.bgr, i, i / 30.0);
    ASSERT_TRUE(step.fit.has_value()) << "frame " << i;
    EXPECT_TRUE(step.row.success) << "frame " << i << ": " << toString(step.failure);
    worst = std::max(worst, frameError(step.row.points, frame.points));
  }
  EXPECT_LT(worst, 0.08);
}

TEST(Tracker, ABlankFrameFailsAndTheFaceIsFoundAgain) {
  const ClmModel& model = test::fitTestModel();
  const test::FitScene scene = test::makeFitScene(model, 0.0, 0.0, 0, 70.0);
  Tracker tracker(model, scene.camera);
  tracker.setState(scene.truth);
  const cv::Mat blank(scene.image.size(), CV_8UC3, cv::Scalar(128, 128, 128));
  const TrackStep lost = tracker.track(blank, 0, 0.0);
  EXPECT_FALSE(lost.row.success);
  EXPECT_NE(lost.failure, TrackFailure::None);
  const TrackStep again = tracker.track(blank, 1, 0.1);
  EXPECT_FALSE(again.row.success);
  EXPECT_EQ(again.failure, TrackFailure::NoFace);
  EXPECT_FALSE(again.row.points.col(0).allFinite());
  // The face comes back: detected and tracked again.
  const TrackStep found = tracker.track(scene.image, 2, 0.2);
  EXPECT_TRUE(found.detected);
  ASSERT_TRUE(found.fit.has_value());
  EXPECT_TRUE(found.row.success) << toString(found.failure);
  EXPECT_LT(test::meanPointError(found.row.points, scene.truthPoints), 0.1 * scene.interOcular);
}

TEST(FitOverlay, DrawsPatchesLandmarksAndLabel) {
  const ClmModel& model = test::fitTestModel();
  const test::FitScene scene = test::makeFitScene(model, 0.0, 0.0);
  Fitter fitter(model, scene.camera);
  TrackStep step;
  step.fit = fitter.fit(scene.image, scene.truth);
  step.row.success = true;
  cv::Mat drawn = scene.image.clone();
  drawFitOverlay(drawn, step, fitter, Scheme::thesis25());
  cv::Mat difference;
  cv::absdiff(drawn, scene.image, difference);
  cv::cvtColor(difference, difference, cv::COLOR_BGR2GRAY);
  // Patches cover a good part of the face: far more changed pixels than dots alone would.
  EXPECT_GT(cv::countNonZero(difference), 25 * 80);
  EXPECT_EQ(fitter.lastTemplates().size(),
            static_cast<std::size_t>(
                std::count(step.fit->modelled.begin(), step.fit->modelled.end(), true)));
}

}  // namespace
}  // namespace clm3d
