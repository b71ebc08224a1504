// Tests of re-tracking forward from a corrected frame: the rows start on the frame after the
// correction and follow the head from the corrected state; the last frame gives no rows; a frame
// outside the video is an error naming the file; cancelling keeps the rows tracked so far.
#include "core/track/retrack.hpp"

#include <gtest/gtest.h>

#include "core/detect/initialisation.hpp"
#include "core/eval/synthetic_sequence.hpp"
#include "tests/support/fit_fixture.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

// A 9-frame held-out head turning 0 -> 16 degrees, written as a lossless video.
SequenceSummary writeShortSequence(const std::filesystem::path& folder, SequenceFiles& files) {
  SequenceSettings settings;
  settings.yawToDeg = 16.0;
  settings.stepDeg = 2.0;
  settings.width = 320;
  settings.height = 240;
  settings.interOcularPixels = 56.0;
  settings.supersample = 1;
  files = SequenceFiles::inFolder(folder);
  const SynthHead& head = test::fitTestHead(test::kHeldOutHead);
  return writeSyntheticSequence(head.mesh, head.landmarks, Scheme::thesis25(), settings,
                                SequenceSubject{}, files);
}

TEST(RetrackFrom, FollowsTheHeadFromTheFrameAfterTheCorrection) {
  const test::TempDir dir;
  SequenceFiles files;
  const SequenceSummary sequence = writeShortSequence(dir.path(), files);
  ASSERT_EQ(sequence.frames, 9);
  const ClmModel& model = test::fitTestModel();
  const int corrected = 3;
  const FitState state =
      stateFromPoints(model, sequence.camera, sequence.truth.rows[corrected].points, {});
  std::vector<TrackRow> rows;
  std::vector<double> fractions;
  int seen = 0;
  const TrackSummary summary = retrackFrom(
      files.video, model, TrackerSettings{}, corrected, state, -1, rows,
      [&](const cv::Mat& frame, const TrackStep&, Tracker&) {
        EXPECT_EQ(frame.cols, 320);
        ++seen;
      },
      [&](double fraction, std::string_view) { fractions.push_back(fraction); });
  ASSERT_EQ(rows.size(), 5u);
  EXPECT_EQ(summary.frames, 5);
  EXPECT_EQ(seen, 5);
  ASSERT_FALSE(fractions.empty());
  EXPECT_DOUBLE_EQ(fractions.back(), 1.0);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const TrackRow& row = rows[i];
    const int frame = corrected + 1 + static_cast<int>(i);
    EXPECT_EQ(row.frame, frame);
    EXPECT_TRUE(row.success) << "frame " << frame;
    const Eigen::Matrix2Xd& truth = sequence.truth.rows[static_cast<std::size_t>(frame)].points;
    const double interOcular = (truth.col(7) - truth.col(10)).norm();
    EXPECT_LT(test::meanPointError(row.points, truth) / interOcular, 0.08) << "frame " << frame;
  }
}

TEST(RetrackFrom, LastFrameGivesNoRowsAndAFrameOutsideIsAnError) {
  const test::TempDir dir;
  SequenceFiles files;
  const SequenceSummary sequence = writeShortSequence(dir.path(), files);
  const ClmModel& model = test::fitTestModel();
  const FitState state =
      stateFromPoints(model, sequence.camera, sequence.truth.rows.back().points, {});
  std::vector<TrackRow> rows;
  retrackFrom(files.video, model, TrackerSettings{}, sequence.frames - 1, state, -1, rows);
  EXPECT_TRUE(rows.empty());
  try {
    retrackFrom(files.video, model, TrackerSettings{}, sequence.frames + 5, state, -1, rows);
    ADD_FAILURE() << "no error";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find(files.video.filename().string()), std::string::npos)
        << error.what();
  }
}

TEST(RetrackFrom, CancelKeepsTheRowsSoFar) {
  const test::TempDir dir;
  SequenceFiles files;
  const SequenceSummary sequence = writeShortSequence(dir.path(), files);
  const ClmModel& model = test::fitTestModel();
  const FitState state = stateFromPoints(model, sequence.camera, sequence.truth.rows[0].points, {});
  std::vector<TrackRow> rows;
  CancelToken token;
  const auto cancelAfterTwo = [&](const cv::Mat&, const TrackStep&, Tracker&) {
    if (rows.size() == 1) token.cancel();  // the second frame is being appended
  };
  EXPECT_THROW(retrackFrom(files.video, model, TrackerSettings{}, 0, state, -1, rows,
                           cancelAfterTwo, {}, &token),
               Cancelled);
  EXPECT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows.front().frame, 1);
}

// The correction loop's re-track: forward over a span it follows the head; where the frames held
// rows it agrees with it stops (rejoined); backward it reads the frames in reverse.
TEST(RetrackSpan, ForwardStopsWhereItRejoinsAndBackwardReadsInReverse) {
  const test::TempDir dir;
  SequenceFiles files;
  const SequenceSummary sequence = writeShortSequence(dir.path(), files);
  const ClmModel& model = test::fitTestModel();
  const FitState state = stateFromPoints(model, sequence.camera, sequence.truth.rows[2].points, {});
  // Nothing to rejoin: the whole span is tracked.
  SpanRetrack forward;
  retrackSpan(files.video, model, TrackerSettings{}, state, -1, {3, 4, 5, 6}, {}, RetrackRules{},
              forward);
  ASSERT_EQ(forward.rows.size(), 4u);
  EXPECT_EQ(forward.stop, RetrackStop::Continue);
  for (std::size_t i = 0; i < forward.rows.size(); ++i) {
    EXPECT_EQ(forward.rows[i].frame, 3 + static_cast<int>(i));
    EXPECT_TRUE(forward.rows[i].success);
  }
  // The same run again, with frames 5 and on holding the first run's rows: it stops at 5.
  std::vector<TrackRow> previous(7);
  previous[5] = forward.rows[2];
  previous[6] = forward.rows[3];
  SpanRetrack again;
  retrackSpan(files.video, model, TrackerSettings{}, state, -1, {3, 4, 5, 6}, previous,
              RetrackRules{}, again);
  ASSERT_EQ(again.rows.size(), 3u);
  EXPECT_EQ(again.stop, RetrackStop::Rejoined);
  EXPECT_EQ(again.stoppedAt, 5);

  const FitState last = stateFromPoints(model, sequence.camera, sequence.truth.rows[6].points, {});
  SpanRetrack backward;
  retrackSpan(files.video, model, TrackerSettings{}, last, -1, {5, 4, 3}, {}, RetrackRules{},
              backward);
  ASSERT_EQ(backward.rows.size(), 3u);
  for (std::size_t i = 0; i < backward.rows.size(); ++i) {
    const int frame = 5 - static_cast<int>(i);
    EXPECT_EQ(backward.rows[i].frame, frame);
    const Eigen::Matrix2Xd& truth = sequence.truth.rows[static_cast<std::size_t>(frame)].points;
    const double interOcular = (truth.col(7) - truth.col(10)).norm();
    EXPECT_LT(test::meanPointError(backward.rows[i].points, truth) / interOcular, 0.08)
        << "frame " << frame;
  }
  SpanRetrack outside;
  EXPECT_THROW(retrackSpan(files.video, model, TrackerSettings{}, last, -1, {40}, {},
                           RetrackRules{}, outside),
               InputError);
}

}  // namespace
}  // namespace clm3d
