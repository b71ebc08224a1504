// The review session without a widget: opening a video (its size, rate and length; an error
// naming a file that is not one), a track becoming the ground truth, keyframes surviving a new
// track, a re-track after a corrected frame and of scattered frames (padding a cancelled run), a
// model of another scheme resetting the corrections, and the per-frame error of eq. 5.1 against
// the keyframes or a loaded reference; a track of several faces (a face column) split by face,
// each face corrected and re-tracked on its own, and saved and loaded back with the face column.
#include "core/review/track_session.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <opencv2/core.hpp>
#include <string>

#include "core/common/error.hpp"
#include "core/common/number_text.hpp"
#include "core/video/video_writer.hpp"
#include "tests/support/test_support.hpp"
#include "tests/support/tiny_model.hpp"

namespace clm3d {
namespace {

constexpr int kFrames = 8;
constexpr double kFps = 25.0;

std::filesystem::path writeVideo(const test::TempDir& dir) {
  const auto path = dir / "clip.avi";
  VideoWriter writer(path, 64, 48, kFps);
  for (int f = 0; f < kFrames; ++f) writer.write(cv::Mat(48, 64, CV_8UC3, cv::Scalar::all(20 * f)));
  writer.close();
  return path;
}

// The tiny model's 5 landmarks (tests/support/tiny_model.hpp): eyes 60 px apart, shifted by
// `offset` pixels to the right.
TrackRow row(int frame, double offset = 0.0) {
  TrackRow r;
  r.frame = frame;
  r.timestamp = frame / kFps;
  r.success = true;
  r.confidence = 0.8;
  r.view = 1;
  r.points.resize(2, 5);
  r.points << 100, 130, 70, 100, 100,  //
      100, 98, 98, 135, 160;
  r.points.row(0).array() += offset;
  return r;
}

TrackTable track(int frames, double offset = 0.0) {
  TrackTable table;
  table.landmarkCount = 5;
  for (int f = 0; f < frames; ++f) table.rows.push_back(row(f, offset));
  return table;
}

std::vector<std::optional<FrameFit>> fits(int count) {
  std::vector<std::optional<FrameFit>> result;
  for (int i = 0; i < count; ++i) result.push_back(FrameFit{FitState{}, i % 3});
  return result;
}

class TrackSessionTest : public ::testing::Test {
 protected:
  void SetUp() override {
    session.openVideo(writeVideo(dir));
    session.setModel(dir / "tiny.clm3d", std::make_shared<const ClmModel>(test::makeTinyModel()));
  }
  test::TempDir dir;
  TrackSession session;
};

TEST_F(TrackSessionTest, OpeningAVideoReadsItsSizeRateAndLength) {
  EXPECT_TRUE(session.hasVideo());
  EXPECT_EQ(session.video().frameCount, kFrames);
  EXPECT_EQ(session.video().width, 64);
  EXPECT_EQ(session.video().height, 48);
  EXPECT_NEAR(session.video().fps, kFps, 1e-6);
  EXPECT_EQ(session.video().camera().width, 64);
  EXPECT_EQ(session.truth().frameCount(), kFrames);
  EXPECT_EQ(session.truth().keyframeCount(), 0);
  ASSERT_EQ(session.errors().size(), static_cast<std::size_t>(kFrames));
  for (const double e : session.errors()) EXPECT_TRUE(std::isnan(e));
  ASSERT_NE(session.scheme(), nullptr);
  EXPECT_EQ(session.scheme()->size(), 5);
}

TEST_F(TrackSessionTest, AFileThatIsNotAVideoIsAnErrorNamingIt) {
  const auto notVideo = dir / "notes.avi";
  test::writeFile(notVideo, "not a video");
  try {
    session.openVideo(notVideo);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("notes.avi"), std::string::npos) << e.what();
  }
}

TEST_F(TrackSessionTest, OpeningAnotherVideoForgetsTheTrackAndTheReference) {
  session.setTrack(track(kFrames), fits(kFrames));
  session.setReference(track(kFrames, 3.0));
  session.openVideo(session.video().path);
  EXPECT_TRUE(session.track().rows.empty());
  EXPECT_FALSE(session.reference().has_value());
  EXPECT_FALSE(session.fit(0).has_value());
  EXPECT_FALSE(session.hasPoints(0));
}

TEST_F(TrackSessionTest, ATrackBecomesTheGroundTruthRowByRow) {
  session.setTrack(track(5), fits(5));
  EXPECT_EQ(session.truth().frameCount(), kFrames);  // padded to the video
  for (int f = 0; f < 5; ++f) {
    EXPECT_TRUE(session.hasPoints(f));
    ASSERT_NE(session.trackRow(f), nullptr);
    EXPECT_EQ(session.trackRow(f)->frame, f);
    ASSERT_TRUE(session.fit(f).has_value());
    EXPECT_EQ(session.fit(f)->view, f % 3);
  }
  EXPECT_FALSE(session.hasPoints(5));
  EXPECT_EQ(session.trackRow(5), nullptr);
  EXPECT_EQ(session.trackRow(-1), nullptr);
  EXPECT_FALSE(session.fit(5).has_value());
  EXPECT_FALSE(session.hasPoints(kFrames));
}

TEST_F(TrackSessionTest, KeyframesSurviveANewTrack) {
  session.setTrack(track(kFrames), fits(kFrames));
  const Eigen::Matrix2Xd corrected = row(2, 7.0).points;
  session.truth().setKeyframe(2, corrected);
  session.setTrack(track(kFrames, 1.0), fits(kFrames));
  EXPECT_TRUE(session.truth().keyframe[2]);
  EXPECT_TRUE((session.truth().table.rows[2].points - corrected).norm() < 1e-12);
  EXPECT_TRUE((session.truth().table.rows[3].points - row(3, 1.0).points).norm() < 1e-12);
}

TEST_F(TrackSessionTest, ATrackOfAnotherLandmarkCountStartsTheGroundTruthAgain) {
  session.setTrack(track(kFrames), fits(kFrames));
  session.truth().setKeyframe(2, row(2, 7.0).points);
  TrackTable other;
  other.landmarkCount = 3;
  for (int f = 0; f < kFrames; ++f) {
    TrackRow r = row(f);
    r.points = r.points.leftCols(3).eval();
    other.rows.push_back(r);
  }
  session.setTrack(other, fits(kFrames));
  EXPECT_EQ(session.truth().table.landmarkCount, 3);
  EXPECT_EQ(session.truth().keyframeCount(), 0);
}

TEST_F(TrackSessionTest, ReTrackingAfterACorrectedFrameReplacesTheRowsAfterIt) {
  session.setTrack(track(kFrames), fits(kFrames));
  session.truth().setKeyframe(3, row(3, 5.0).points);
  session.truth().setKeyframe(6, row(6, 5.0).points);
  std::vector<TrackRow> rows;
  for (int f = 4; f < kFrames; ++f) rows.push_back(row(f, 2.0));
  session.replaceTrackAfter(3, rows, fits(static_cast<int>(rows.size())));
  ASSERT_EQ(session.track().rows.size(), static_cast<std::size_t>(kFrames));
  for (int f = 0; f < kFrames; ++f) {
    EXPECT_EQ(session.track().rows[static_cast<std::size_t>(f)].frame, f);
    const double shift = f > 3 ? 2.0 : 0.0;
    EXPECT_NEAR(session.track().rows[static_cast<std::size_t>(f)].points(0, 0), 100.0 + shift,
                1e-12);
  }
  // Rows after the corrected frame reach the ground truth, keyframes excepted.
  EXPECT_NEAR(session.truth().table.rows[5].points(0, 0), 102.0, 1e-12);
  EXPECT_NEAR(session.truth().table.rows[6].points(0, 0), 105.0, 1e-12);
  EXPECT_NEAR(session.truth().table.rows[3].points(0, 0), 105.0, 1e-12);
  EXPECT_EQ(session.fit(4)->view, 0);  // the re-track's own fits
}

TEST_F(TrackSessionTest, ReTrackingPastACancelledRunPadsWithUntrackedRows) {
  session.setTrack(track(2), fits(2));  // a run cancelled after two frames
  session.replaceTrackAfter(4, {row(5), row(6)}, fits(1));
  ASSERT_EQ(session.track().rows.size(), 7u);
  for (int f = 2; f <= 4; ++f) {
    const TrackRow& padded = session.track().rows[static_cast<std::size_t>(f)];
    EXPECT_EQ(padded.frame, f);
    EXPECT_NEAR(padded.timestamp, f / kFps, 1e-12);
    EXPECT_FALSE(padded.success);
    EXPECT_EQ(padded.points.cols(), 5);
    EXPECT_FALSE(padded.points.allFinite());
    EXPECT_FALSE(session.fit(f).has_value());
  }
  EXPECT_TRUE(session.fit(5).has_value());
  EXPECT_FALSE(session.fit(6).has_value());  // fewer fits than rows
  EXPECT_TRUE(session.hasPoints(6));
}

TEST_F(TrackSessionTest, ScatteredReTrackedFramesReplaceTheirRowsButNotKeyframes) {
  session.setTrack(track(3), fits(3));
  session.truth().setKeyframe(1, row(1, 9.0).points);
  // Any order; a frame outside the video is ignored.
  session.replaceTrackFrames({row(5, 4.0), row(1, 4.0), row(kFrames + 2, 4.0)}, fits(3));
  ASSERT_EQ(session.track().rows.size(), 6u);
  EXPECT_NEAR(session.track().rows[5].points(0, 0), 104.0, 1e-12);
  EXPECT_NEAR(session.track().rows[1].points(0, 0), 104.0, 1e-12);
  EXPECT_FALSE(session.track().rows[4].points.allFinite());
  EXPECT_EQ(session.track().rows[4].frame, 4);
  EXPECT_NEAR(session.truth().table.rows[5].points(0, 0), 104.0, 1e-12);
  EXPECT_NEAR(session.truth().table.rows[1].points(0, 0), 109.0, 1e-12);  // the keyframe stays
  EXPECT_EQ(session.fit(5)->view, 0);
  EXPECT_EQ(session.fit(1)->view, 1);
  EXPECT_FALSE(session.fit(4).has_value());
}

TEST_F(TrackSessionTest, ReTrackingFramesOfAnEmptyTrackTakesTheirLandmarkCount) {
  session.replaceTrackFrames({row(2)}, fits(1));
  EXPECT_EQ(session.track().landmarkCount, 5);
  ASSERT_EQ(session.track().rows.size(), 3u);
  EXPECT_EQ(session.track().rows[0].points.cols(), 5);
}

TEST_F(TrackSessionTest, WithoutAReferenceTheKeyframesAreScored) {
  session.setTrack(track(kFrames), fits(kFrames));
  ASSERT_EQ(session.errors().size(), static_cast<std::size_t>(kFrames));
  for (const double e : session.errors()) EXPECT_TRUE(std::isnan(e));  // no keyframe yet
  // Every point of frame 2 corrected 6 px to the right: eyes 60 px apart, error 0.1 (eq. 5.1).
  session.truth().setKeyframe(2, row(2, 6.0).points);
  session.updateErrors();
  for (int f = 0; f < kFrames; ++f) {
    const double e = session.errors()[static_cast<std::size_t>(f)];
    if (f == 2) {
      EXPECT_NEAR(e, 0.1, 1e-9);
    } else {
      EXPECT_TRUE(std::isnan(e)) << f;
    }
  }
}

TEST_F(TrackSessionTest, AReferenceIsScoredOnEveryTrackedFrame) {
  session.setTrack(track(5), fits(5));
  session.setReference(track(kFrames, -3.0));
  for (int f = 0; f < kFrames; ++f) {
    const double e = session.errors()[static_cast<std::size_t>(f)];
    if (f < 5) {
      EXPECT_NEAR(e, 0.05, 1e-9) << f;
    } else {
      EXPECT_TRUE(std::isnan(e)) << f;  // not tracked
    }
  }
  session.setReference(std::nullopt);
  ASSERT_EQ(session.errors().size(), static_cast<std::size_t>(kFrames));
  for (const double e : session.errors()) EXPECT_TRUE(std::isnan(e));
}

TEST_F(TrackSessionTest, AReferenceWithoutEyesScoresNothing) {
  session.setTrack(track(kFrames), fits(kFrames));
  TrackTable blind = track(kFrames);
  for (TrackRow& r : blind.rows) r.points.col(1).setConstant(kNan);
  session.setReference(blind);
  ASSERT_EQ(session.errors().size(), static_cast<std::size_t>(kFrames));
  for (const double e : session.errors()) EXPECT_TRUE(std::isnan(e));
}

TEST_F(TrackSessionTest, WithoutAModelNothingIsScored) {
  session.setModel({}, nullptr);
  EXPECT_EQ(session.scheme(), nullptr);
  session.setTrack(track(kFrames), fits(kFrames));
  session.setReference(track(kFrames, 3.0));
  ASSERT_EQ(session.errors().size(), static_cast<std::size_t>(kFrames));
  for (const double e : session.errors()) EXPECT_TRUE(std::isnan(e));
}

TEST_F(TrackSessionTest, ASetGroundTruthIsPaddedToTheVideo) {
  session.setTrack(track(kFrames), fits(kFrames));
  GroundTruthSet loaded = GroundTruthSet::fromTrack(track(3, 6.0), 3);
  loaded.setKeyframe(1, row(1, 6.0).points);
  session.setTruth(loaded);
  EXPECT_EQ(session.truth().frameCount(), kFrames);
  EXPECT_TRUE(session.truth().keyframe[1]);
  EXPECT_NEAR(session.errors()[1], 0.1, 1e-9);
}

// Two faces, 0 on every frame and 1 (shifted 200 px) from frame 2 on, as `clm3d track --faces`
// writes them: rows by frame, then face.
TrackTable twoFaces() {
  TrackTable table;
  table.landmarkCount = 5;
  table.extraColumns = {"face"};
  for (int f = 0; f < kFrames; ++f) {
    for (int face = 0; face < 2; ++face) {
      if (face == 1 && f < 2) continue;
      TrackRow r = row(f, 200.0 * face);
      r.extraCells = {std::to_string(face)};
      table.rows.push_back(std::move(r));
    }
  }
  return table;
}

TEST_F(TrackSessionTest, SeveralFacesAreSplitByFaceAndTheSelectedOneIsCorrected) {
  session.setFaceTrack(twoFaces(), {{1, fits(kFrames)}});
  ASSERT_TRUE(session.multiFace());
  ASSERT_EQ(session.faces().size(), 2u);
  EXPECT_EQ(session.selectedFace(), 0);
  EXPECT_EQ(session.track().rows.size(), static_cast<std::size_t>(kFrames));
  EXPECT_EQ(session.truthRow(1, 1), nullptr);  // face 1 is not in frame 1
  ASSERT_NE(session.truthRow(1, 3), nullptr);
  EXPECT_NEAR(session.truthRow(1, 3)->points(0, 0), 300.0, 1e-12);
  EXPECT_FALSE(session.fit(3).has_value());  // face 0 has no fits
  ASSERT_TRUE(session.selectFace(1));
  EXPECT_FALSE(session.selectFace(7));
  EXPECT_TRUE(session.fit(3).has_value());
  EXPECT_FALSE(session.hasPoints(1));
  EXPECT_TRUE(session.hasPoints(2));
  EXPECT_FALSE(session.inFrame(1));  // the timeline and the review list leave it out
  EXPECT_TRUE(session.inFrame(2));

  // A correction and a re-track of face 1 change face 1's rows only.
  session.truth().setKeyframe(4, row(4, 210.0).points);
  session.replaceTrackFrames(1, {row(5, 205.0), row(6, 205.0)}, {});
  EXPECT_NEAR(session.truth(1).table.rows[5].points(0, 0), 305.0, 1e-12);
  for (int f = 0; f < kFrames; ++f) {
    EXPECT_NEAR(session.truth(0).table.rows[static_cast<std::size_t>(f)].points(0, 0), 100.0,
                1e-12);
    EXPECT_FALSE(session.truth(0).keyframe[static_cast<std::size_t>(f)]);
  }

  // The track and the ground truth are written with the face column, by frame then face, and the
  // ground truth reads back face by face with its keyframe.
  const TrackTable written = session.trackTable();
  ASSERT_EQ(written.extraColumns, std::vector<std::string>{"face"});
  EXPECT_EQ(written.rows.size(), twoFaces().rows.size());
  EXPECT_EQ(written.rows[4].frame, 3);
  EXPECT_EQ(written.rows[4].extraCells[0], "0");
  EXPECT_EQ(written.rows[5].extraCells[0], "1");
  const auto csv = dir / "faces-truth.csv";
  session.saveTruth(csv, dir / "pts");
  EXPECT_FALSE(std::filesystem::exists(dir / "pts"));  // one .pts a frame holds one face
  TrackSession reopened;
  reopened.openVideo(session.video().path);
  reopened.loadTruth(csv);
  ASSERT_TRUE(reopened.multiFace());
  ASSERT_EQ(reopened.faces().size(), 2u);
  EXPECT_TRUE(reopened.truth(1).keyframe[4]);
  EXPECT_EQ(reopened.truthRow(1, 0), nullptr);
  EXPECT_NEAR(reopened.truth(1).table.rows[6].points(0, 0), 305.0, 1e-12);
  EXPECT_EQ(readTrackTable(csv).rows.size(), twoFaces().rows.size());
}

TEST_F(TrackSessionTest, AFaceCellThatIsNotAnIdIsAnErrorNamingTheFile) {
  TrackTable table = twoFaces();
  table.rows[3].extraCells = {"left"};
  try {
    splitFaceTruth(table, kFrames, "faces.csv");
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("faces.csv"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("left"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace clm3d
