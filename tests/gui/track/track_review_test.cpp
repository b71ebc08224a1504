// The Track page reviewing what exists (issue 13, item 2): a project's track of a video opens with
// the video, without tracking; any tracks or ground-truth CSV loads as the track; two tracks are
// compared (the compared points drawn over the frame, their per-frame difference on the timeline);
// a broken tracks CSV shows the error dialog naming the file and the problem and loses nothing;
// a two-face track (a face column, as `clm3d track --faces` writes) shows both faces, and a drag
// of one face corrects and re-tracks that face only, undone in one step (issue 27 item 3).
#include <QApplication>
#include <QComboBox>
#include <QListWidget>
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>
#include <cmath>
#include <fstream>
#include <thread>

#include "core/eval/synthetic_sequence.hpp"
#include "core/model/model_file.hpp"
#include "core/project/project.hpp"
#include "core/project/project_layout.hpp"
#include "core/track/track_table.hpp"
#include "core/video/video_writer.hpp"
#include "tests/gui/support/gui_test_support.hpp"
#include "tests/gui/track/track_fixture.hpp"
#include "tests/support/fit_fixture.hpp"
#include "tests/support/two_faces.hpp"
#include "ui/common/job_runner.hpp"
#include "ui/track/compared_points.hpp"
#include "ui/track/face_overlays.hpp"
#include "ui/track/frame_view.hpp"
#include "ui/track/timeline_widget.hpp"
#include "ui/track/track_files_panel.hpp"
#include "ui/track/track_page.hpp"

namespace clm3d::ui {
namespace {

namespace fs = std::filesystem;

constexpr int kFrames = 12;
constexpr double kShiftPixels = 3.0;

// The truth with every point moved kShiftPixels to the right: a "track" whose difference to the
// truth is known exactly.
TrackTable shifted(TrackTable table, double dx) {
  for (TrackRow& row : table.rows) {
    row.points.row(0).array() += dx;
    row.success = true;
    row.confidence = 0.9;
  }
  return table;
}

// Equal, NaN where the other is NaN.
bool samePoints(const Eigen::Matrix2Xd& a, const Eigen::Matrix2Xd& b) {
  return a.cols() == b.cols() &&
         (a.array() == b.array() || (a.array().isNaN() && b.array().isNaN())).all();
}

// Eq. 5.1 for a uniform shift: the shift over the truth's eye-centre distance (points 8 and 11).
double expectedDifference(const TrackRow& truth) {
  return kShiftPixels / (truth.points.col(7) - truth.points.col(10)).norm();
}

}  // namespace

class TrackReviewTest : public QObject {
  Q_OBJECT
 private:
  test::TempDir temp_;
  Project project_;
  SequenceFiles sequence_;
  fs::path model_;
  fs::path shiftedTrack_;
  TrackTable truth_;
  std::unique_ptr<TrackPage> page_;

  static constexpr int kTwoFrames = 6;
  fs::path twoVideo_;
  std::vector<test::TwoFaceFrame> twoFrames_;

  // Two procedural heads in one video (tests/support/two_faces.hpp), made once.
  const fs::path& twoFaceVideo() {
    if (!twoVideo_.empty()) return twoVideo_;
    twoVideo_ = project_.folder / "videos" / "two" / "two.avi";
    test::runOffGuiThread([&] {
      twoFrames_ = test::twoFaceFrames(kTwoFrames, 10);
      fs::create_directories(twoVideo_.parent_path());
      VideoWriter writer(twoVideo_, 640, 520, 25.0);
      for (const auto& frame : twoFrames_) writer.write(frame.image);
      writer.close();
    });
    return twoVideo_;
  }

  void openPage() {
    page_ = std::make_unique<TrackPage>();
    QVERIFY(test::showForTest(*page_, {1280, 820}));
  }

 private slots:
  void initTestCase() {
    test::TrackProject made =
        test::makeTrackProject(temp_.path() / "project", "review-test", kFrames, 2.0);
    project_ = std::move(made.project);
    model_ = made.fixture.model;
    sequence_ = made.fixture.sequence;
    truth_ = readTrackTable(sequence_.truth);
    QCOMPARE(static_cast<int>(truth_.rows.size()), kFrames);
    // A track made elsewhere (by `clm3d track`, or another model), in the project's layout.
    shiftedTrack_ = project_layout::tracksFile(project_.folder, sequence_.video, model_);
    fs::create_directories(shiftedTrack_.parent_path());
    writeTrackTable(shiftedTrack_, shifted(truth_, kShiftPixels));
    project_.tracks.push_back(shiftedTrack_);
    project_.groundTruth.push_back(sequence_.truth);
    saveProject(project_);
  }

  void theProjectsTrackOpensWithTheVideoWithoutTracking() {
    openPage();
    QSignalSpy started(page_->jobRunner(), &JobRunner::started);
    page_->setProject(&project_);
    QCOMPARE(page_->session().video().path, sequence_.video);
    QCOMPARE(started.count(), 0);  // nothing was tracked
    QCOMPARE(page_->tracksCsv(), shiftedTrack_);
    QCOMPARE(static_cast<int>(page_->session().track().rows.size()), kFrames);
    QVERIFY((page_->session().track().rows[4].points - truth_.rows[4].points).norm() > 1.0);
    QVERIFY(page_->session().model() != nullptr);  // loaded for the view names and the scheme
    // The ground truth beside the video is compared with the track at once.
    QCOMPARE(page_->comparedCsv(), sequence_.truth);
    QVERIFY(!page_->hasUnsavedChanges());
    // The panel lists both files of this video.
    const auto& listed = page_->trackFiles()->files();
    QCOMPARE(listed.size(), std::size_t{2});
    QCOMPARE(listed[0].path, sequence_.truth);
    QVERIFY(listed[0].groundTruth);
    QCOMPARE(listed[1].path, shiftedTrack_);
    // The per-frame difference is on the timeline, and it is the known shift.
    const auto& errors = page_->session().errors();
    QCOMPARE(static_cast<int>(errors.size()), kFrames);
    for (int f = 0; f < kFrames; ++f) {
      const double expected = expectedDifference(truth_.rows[static_cast<std::size_t>(f)]);
      QVERIFY2(std::abs(errors[static_cast<std::size_t>(f)] - expected) < 1e-6,
               qPrintable(QString("frame %1: %2 vs %3")
                              .arg(f)
                              .arg(errors[static_cast<std::size_t>(f)])
                              .arg(expected)));
    }
  }

  void comparingTwoTracksDrawsBothAndPlotsTheirDifference() {
    // A second model's track: the truth moved the other way; compare the first with it.
    const fs::path other = project_.folder / "tracks" / "sequence-other.csv";
    writeTrackTable(other, shifted(truth_, -kShiftPixels));
    project_.tracks.push_back(other);
    page_->setProject(&project_);
    QVERIFY(page_->trackFiles()->select(other));
    auto* compare = page_->trackFiles()->findChild<QPushButton*>("compareTrackButton");
    QVERIFY(compare && compare->isEnabled());
    QTest::mouseClick(compare, Qt::LeftButton);
    QCOMPARE(page_->comparedCsv(), other);
    for (int f = 0; f < kFrames; ++f) {
      const double error = page_->session().errors()[static_cast<std::size_t>(f)];
      QVERIFY(std::abs(error - 2.0 * expectedDifference(truth_.rows[static_cast<std::size_t>(f)])) <
              1e-6);
    }
    // The compared points are drawn over the frame where they are, nowhere else.
    cv::Mat black(240, 320, CV_8UC3, cv::Scalar::all(0));
    const cv::Mat drawn = withComparedPoints(black, *page_->session().reference(), 3);
    const Eigen::Vector2d at = comparedRow(*page_->session().reference(), 3)->points.col(11);
    const cv::Rect around(static_cast<int>(at.x()) - 6, static_cast<int>(at.y()) - 6, 13, 13);
    QVERIFY(cv::countNonZero(drawn(around).reshape(1)) > 0);
    QVERIFY(cv::countNonZero(
                withComparedPoints(black, *page_->session().reference(), 999).reshape(1)) == 0);
    // Loading the other track as the track (double click) and comparing with the truth.
    QVERIFY(page_->trackFiles()->select(other));
    auto* load = page_->trackFiles()->findChild<QPushButton*>("loadTrackButton");
    QTest::mouseClick(load, Qt::LeftButton);
    QCOMPARE(page_->tracksCsv(), other);
    QVERIFY(page_->compareWith(sequence_.truth));
    QVERIFY(std::abs(page_->session().errors()[0] - expectedDifference(truth_.rows[0])) < 1e-6);
  }

  void aGroundTruthCsvLoadsAsTheTrack() {
    QVERIFY(page_->loadTrack(sequence_.truth));
    QVERIFY((page_->session().track().rows[7].points - truth_.rows[7].points).norm() < 1e-9);
    QVERIFY(page_->session().errors()[7] < 1e-9);
  }

  void aBrokenTracksCsvShowsTheDialogAndLosesNothing() {
    QVERIFY(page_->loadTrack(shiftedTrack_));
    // A correction: frame 2 becomes a keyframe (unsaved work in the undo history).
    page_->setCurrentFrame(2);
    page_->toggleKeyframe();
    QVERIFY(page_->hasUnsavedChanges());
    const int undoSteps = page_->undoStack()->count();
    const TrackTable trackBefore = page_->session().track();

    const fs::path broken = temp_.path() / "broken-tracks.csv";
    std::ofstream(broken) << "frame,timestamp,success,confidence,x_1,y_1\n0,0,1,0.5,12,oops\n";
    QString message;
    test::expectErrorDialog(&message);
    QVERIFY(!page_->loadTrack(broken));
    QVERIFY2(message.contains("broken-tracks.csv") && message.contains("oops"),
             qPrintable(message));

    // Frames beyond the video: also refused, naming the file and the video.
    const fs::path longer = temp_.path() / "longer-tracks.csv";
    TrackTable tooLong = truth_;
    tooLong.rows.back().frame = kFrames + 40;
    writeTrackTable(longer, tooLong);
    test::expectErrorDialog(&message);
    QVERIFY(!page_->loadTrack(longer));
    QVERIFY2(message.contains("longer-tracks.csv") && message.contains("sequence"),
             qPrintable(message));

    // Another landmark count would replace the corrected keyframes: refused too.
    const fs::path fewer = temp_.path() / "three-points.csv";
    TrackTable three = truth_;
    three.landmarkCount = 3;
    for (TrackRow& row : three.rows) {
      row.points = Eigen::Matrix2Xd(row.points.leftCols(3));
      row.visibility.clear();
    }
    writeTrackTable(fewer, three);
    test::expectErrorDialog(&message);
    QVERIFY(!page_->loadTrack(fewer));
    QVERIFY2(message.contains("three-points.csv") && message.contains("keyframes"),
             qPrintable(message));

    // Nothing was lost: the track, the keyframe, the history, the unsaved state.
    QCOMPARE(page_->tracksCsv(), shiftedTrack_);
    QCOMPARE(page_->session().track().rows.size(), trackBefore.rows.size());
    QVERIFY((page_->session().track().rows[5].points - trackBefore.rows[5].points).norm() < 1e-12);
    QVERIFY(page_->session().truth().keyframe[2]);
    QCOMPARE(page_->undoStack()->count(), undoSteps);
    QVERIFY(page_->hasUnsavedChanges());
    // Loading a good file now keeps the keyframe and is itself undoable.
    QVERIFY(page_->loadTrack(sequence_.truth));
    QVERIFY(page_->session().truth().keyframe[2]);
    QCOMPARE(page_->undoStack()->count(), undoSteps + 1);
    page_->undoStack()->setClean();
  }

  // Two procedural heads in one video (tests/support/two_faces.hpp) and their truth as a two-face
  // track: face 0 the top head, face 1 the bottom one.
  void twoFacesAreDrawnAndCorrectedFaceByFace() {
    const fs::path& video = twoFaceVideo();
    const std::vector<test::TwoFaceFrame>& frames = twoFrames_;
    const fs::path csv = temp_.path() / "two-faces.csv";
    TrackTable faces;
    faces.landmarkCount = static_cast<int>(frames[0].top.cols());
    faces.extraColumns = {"face"};
    for (int f = 0; f < kTwoFrames; ++f) {
      for (int face = 0; face < 2; ++face) {
        TrackRow row;
        row.frame = f;
        row.timestamp = f / 25.0;
        row.success = true;
        row.confidence = 0.9;
        row.points = face == 0 ? frames[static_cast<std::size_t>(f)].top
                               : frames[static_cast<std::size_t>(f)].bottom;
        row.extraCells = {std::to_string(face)};
        faces.rows.push_back(std::move(row));
      }
    }
    writeTrackTable(csv, faces);

    if (!page_) {  // run on its own
      openPage();
      page_->setProject(&project_);
    }
    QVERIFY(page_->openVideo(video));
    QVERIFY(page_->loadTrack(csv));
    const TrackSession& session = page_->session();
    QVERIFY(session.multiFace());
    QCOMPARE(session.faces().size(), std::size_t{2});
    QCOMPARE(session.selectedFace(), 0);
    QVERIFY(page_->faceCombo()->isVisible());

    // Both faces drawn, each in its colour: the selected one as the landmarks, the other beside.
    page_->setCurrentFrame(2);
    FrameView* view = page_->frameView();
    QCOMPARE(view->otherFaces().size(), std::size_t{1});
    QCOMPARE(view->otherFaces()[0].face, 1);
    const QImage drawn = view->grab().toImage();
    const auto colourAt = [&](const Eigen::Vector2d& point) {
      return drawn.pixelColor(view->toWidget({point.x(), point.y()}).toPoint());
    };
    const auto near = [](const QColor& a, const QColor& b) {
      return std::abs(a.red() - b.red()) + std::abs(a.green() - b.green()) +
                 std::abs(a.blue() - b.blue()) <
             60;
    };
    const int nose = 11;  // point 12, the tip of the nose: no other point on it
    QVERIFY2(near(colourAt(frames[2].top.col(nose)), faceColour(0)),
             qPrintable(colourAt(frames[2].top.col(nose)).name()));
    QVERIFY2(near(colourAt(frames[2].bottom.col(nose)), faceColour(1)),
             qPrintable(colourAt(frames[2].bottom.col(nose)).name()));

    // A click inside the bottom face selects it.
    const Eigen::Vector2d centre = frames[2].bottom.rowwise().mean();
    QTest::mouseClick(view, Qt::LeftButton, {}, view->toWidget({centre.x(), centre.y()}).toPoint());
    QCOMPARE(session.selectedFace(), 1);
    QCOMPARE(view->otherFaces()[0].face, 0);

    // Drag face 1's nose 8 pixels; the loop re-tracks face 1 from frame 2 on.
    const TrackTable face0Track = session.faces()[0].track;
    const GroundTruthSet face0Truth = session.truth(0);
    const GroundTruthSet face1Truth = session.truth(1);
    const int steps = page_->undoStack()->count();
    const int retracks = page_->loopRetracks();
    page_->setLoopEnabled(true);
    const Eigen::Vector2d from = face1Truth.table.rows[2].points.col(nose);
    const QPoint press = view->toWidget({from.x(), from.y()}).toPoint();
    const QPoint release = view->toWidget({from.x() + 8.0, from.y()}).toPoint();
    QTest::mousePress(view, Qt::LeftButton, {}, press);
    QTest::mouseMove(view, release);
    QTest::mouseRelease(view, Qt::LeftButton, {}, release);
    QVERIFY(test::waitUntil([&] { return !page_->loopPending() && !page_->isBusy(); }, 60000));
    QCOMPARE(page_->loopRetracks(), retracks + 1);
    QCOMPARE(page_->undoStack()->count(), steps + 1);  // the drag and its re-track: one step
    const GroundTruthSet& corrected = session.truth(1);
    QVERIFY(corrected.keyframe[2]);
    QVERIFY((corrected.table.rows[2].points.col(nose) - from).norm() > 4.0);
    // Face 0's track and truth are untouched.
    for (int f = 0; f < kTwoFrames; ++f) {
      const auto i = static_cast<std::size_t>(f);
      QVERIFY(samePoints(session.faces()[0].track.rows[i].points, face0Track.rows[i].points));
      QVERIFY(samePoints(session.truth(0).table.rows[i].points, face0Truth.table.rows[i].points));
      QCOMPARE(session.truth(0).keyframe[i], face0Truth.keyframe[i]);
    }

    // Saving writes both faces with the face column, face 0 as it was.
    QVERIFY(page_->save());
    const TrackTable saved = readTrackTable(page_->groundTruthCsv());
    QCOMPARE(saved.rows.size(), std::size_t{2 * kTwoFrames});
    QCOMPARE(saved.extraColumns, (std::vector<std::string>{"face", "keyframe"}));
    for (const TrackRow& row : saved.rows) {
      if (row.extraCells[0] == "0") {
        QVERIFY(samePoints(row.points,
                           face0Truth.table.rows[static_cast<std::size_t>(row.frame)].points));
      }
    }

    // One Ctrl+Z takes back the drag and the re-track of face 1.
    page_->undoStack()->undo();
    for (int f = 0; f < kTwoFrames; ++f) {
      const auto i = static_cast<std::size_t>(f);
      QVERIFY(samePoints(session.truth(1).table.rows[i].points, face1Truth.table.rows[i].points));
      QCOMPARE(session.truth(1).keyframe[i], face1Truth.keyframe[i]);
      QVERIFY(samePoints(session.truth(0).table.rows[i].points, face0Truth.table.rows[i].points));
    }
    page_->undoStack()->setClean();
  }

  // Faces to track = all (the settings' --faces) tracks the two heads with trackVideoFaces, as
  // `clm3d track --faces all` does: two faces, each on its head, the tracks CSV with the face
  // column.
  void trackingEveryFaceFromTheSettingsGivesEachFaceItsTrack() {
    if (!page_) {
      openPage();
      page_->setProject(&project_);
    }
    QVERIFY(page_->openVideo(twoFaceVideo()));
    TrackerSettings settings = page_->trackerSettings();
    settings.faces = 0;  // all
    page_->setTrackerSettings(settings);
    QCOMPARE(project_.trackerOptions.at("faces"), std::string("all"));
    QVERIFY(page_->startTracking());
    QVERIFY(test::waitUntil([&] { return !page_->isBusy(); }, 60000));
    const TrackSession& session = page_->session();
    QVERIFY(session.multiFace());
    QCOMPARE(session.faces().size(), std::size_t{2});
    for (const TrackSession::Face& face : session.faces()) {
      const TrackRow& first = face.track.rows[0];
      QVERIFY(first.success);
      const double top = test::meanPointError(first.points, twoFrames_[0].top);
      const double bottom = test::meanPointError(first.points, twoFrames_[0].bottom);
      QVERIFY2(std::min(top, bottom) < 6.0, qPrintable(QString("%1 %2").arg(top).arg(bottom)));
    }
    const TrackTable saved = readTrackTable(page_->tracksCsv());
    QCOMPARE(saved.extraColumns, std::vector<std::string>{"face"});
    QCOMPARE(saved.rows.size(), std::size_t{2 * kTwoFrames});
    page_->setTrackerSettings(TrackerSettings{});
  }

  void cleanupTestCase() { page_.reset(); }
};

}  // namespace clm3d::ui

QTEST_MAIN(clm3d::ui::TrackReviewTest)
#include "track_review_test.moc"
