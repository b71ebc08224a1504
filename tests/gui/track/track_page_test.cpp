// The Track page end to end on a tiny trained model and a short synthetic video made at run time:
// tracking via the Track button without stalling the GUI thread, a row per frame and the tracks CSV
// in the project, timeline clicks, a landmark drag as one undo step, keyframes, interpolation,
// saving the ground truth (CSV and .pts hold the corrected point), re-tracking forward, the overlay
// export, and the error dialog for a file that is not a video. With CLM3D_STUDIO_SCREENSHOTS set
// to a folder, the documentation's screenshots are written there (docs/studio-track.md).
#include "ui/track/track_page.hpp"

#include <QApplication>
#include <QCheckBox>
#include <QMessageBox>
#include <QProcessEnvironment>
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>
#include <cmath>
#include <fstream>
#include <thread>

#include "core/eval/synthetic_sequence.hpp"
#include "core/model/model_file.hpp"
#include "core/project/autosave.hpp"
#include "core/project/project.hpp"
#include "core/scheme/landmark_file.hpp"
#include "core/track/ground_truth.hpp"
#include "core/track/tracker.hpp"
#include "core/video/video_reader.hpp"
#include "tests/gui/project/isolated_settings.hpp"
#include "tests/gui/support/gui_test_support.hpp"
#include "tests/gui/track/track_fixture.hpp"
#include "ui/common/job_runner.hpp"
#include "ui/project/studio_settings.hpp"
#include "ui/track/frame_view.hpp"
#include "ui/track/player_bar.hpp"
#include "ui/track/timeline_widget.hpp"

namespace clm3d::ui {
namespace {

namespace fs = std::filesystem;

constexpr int kFrames = 16;

QString screenshotFolder() {
  return QProcessEnvironment::systemEnvironment().value("CLM3D_STUDIO_SCREENSHOTS");
}

void screenshot(QWidget& widget, const QString& name) {
  const QString folder = screenshotFolder();
  if (folder.isEmpty()) return;
  QTest::qWait(100);
  QVERIFY(widget.grab().save(folder + "/" + name));
}

}  // namespace

class TrackPageTest : public QObject {
  Q_OBJECT
 private:
  test::IsolatedSettings settings_;  // the preferences tests never touch the user's own
  test::TempDir temp_;
  Project project_;
  SequenceFiles sequence_;
  fs::path model_;
  std::unique_ptr<TrackPage> page_;

  bool waitForJob(int timeoutMs = 120000) {
    return test::waitUntil([&] { return !page_->isBusy(); }, timeoutMs);
  }

 private slots:
  void initTestCase() {
    test::TrackProject made =
        test::makeTrackProject(temp_.path() / "project", "track-test", kFrames, 2.0);
    project_ = std::move(made.project);
    model_ = made.fixture.model;
    sequence_ = made.fixture.sequence;
    page_ = std::make_unique<TrackPage>();
    QVERIFY(test::showForTest(*page_, {1280, 820}, true));
    page_->setProject(&project_);
    // Drags here are single edits; the re-track that follows them is correction_loop_test's.
    page_->setLoopEnabled(false);
    QCOMPARE(page_->title(), QString("Track"));
  }

  void cancelKeepsTheFramesTrackedSoFar() {
    QVERIFY(page_->openVideo(sequence_.video));
    QCOMPARE(page_->session().video().frameCount, kFrames);
    JobRunner* runner = page_->jobRunner();
    QSignalSpy cancelled(runner, &JobRunner::cancelled);
    QSignalSpy finished(runner, &JobRunner::finished);
    QSignalSpy modified(page_.get(), &Page::projectModified);
    // Cancel (Escape) as soon as the first frames are reported.
    const auto connection =
        connect(runner, &JobRunner::progressed, this, [&](double fraction, const QString&) {
          if (fraction > 0.0 && fraction < 1.0) QTest::keyClick(page_.get(), Qt::Key_Escape);
        });
    QVERIFY(page_->startTracking());
    QVERIFY(waitForJob());
    disconnect(connection);
    QVERIFY(cancelled.count() + finished.count() == 1);
    QCOMPARE(modified.count(), 1);  // the tracks CSV joined the project
    QCOMPARE(project_.tracks.size(), std::size_t{1});
    const auto rows = static_cast<int>(page_->session().track().rows.size());
    qInfo("cancel: %s after %d of %d frames", cancelled.count() ? "cancelled" : "finished", rows,
          kFrames);
    if (cancelled.count() == 1) {
      // On a loaded machine the run may end first; when it was cancelled, the rows stay.
      QVERIFY(rows >= 1 && rows < kFrames);
      QCOMPARE(static_cast<int>(readTrackTable(page_->tracksCsv()).rows.size()), rows);
      QVERIFY(!page_->session().hasPoints(kFrames - 1) ||
              !page_->session().truth().table.rows.back().success);
    }
  }

  void trackButtonTracksEveryFrameWithoutStalling() {
    QCOMPARE(page_->session().video().frameCount, kFrames);
    auto* track = page_->findChild<QPushButton*>("trackButton");
    QVERIFY(track && track->isEnabled());
    test::StallWatchdog watchdog;
    watchdog.start();
    QTest::mouseClick(track, Qt::LeftButton);
    QVERIFY(page_->isBusy());
    QVERIFY(waitForJob());
    watchdog.stop();
    qInfo("tracking: GUI thread %s", qPrintable(watchdog.summary()));
    QVERIFY2(watchdog.withinBudget(), qPrintable(watchdog.summary()));
    const TrackTable& rows = page_->session().track();
    QCOMPARE(static_cast<int>(rows.rows.size()), kFrames);
    int succeeded = 0;
    for (int f = 0; f < kFrames; ++f) {
      QCOMPARE(rows.rows[static_cast<std::size_t>(f)].frame, f);
      succeeded += rows.rows[static_cast<std::size_t>(f)].success ? 1 : 0;
    }
    QVERIFY2(succeeded >= kFrames - 2, qPrintable(QString("%1 succeeded").arg(succeeded)));
    // The tracks CSV is in the project.
    QVERIFY(fs::exists(page_->tracksCsv()));
    QCOMPARE(page_->tracksCsv().parent_path(), project_.folder / "tracks");
    QCOMPARE(static_cast<int>(readTrackTable(page_->tracksCsv()).rows.size()), kFrames);
    QCOMPARE(project_.tracks.size(), std::size_t{1});  // the cancelled run's file, overwritten
    QCOMPARE(project_.tracks.front(), page_->tracksCsv());
  }

  void reviewingFramesWithPatchesStaysFast() {
    page_->setPatchesShown(true);
    test::StallWatchdog watchdog;
    watchdog.start();
    for (int f = 0; f < kFrames; ++f) {
      page_->setCurrentFrame(f);
      QTest::qWait(10);
    }
    watchdog.stop();
    qInfo("review: patch overlay search at most %.1f ms, decode at most %.1f ms; GUI thread %s",
          page_->longestOverlayMs(), page_->longestDecodeMs(), qPrintable(watchdog.summary()));
    QVERIFY(page_->longestOverlayMs() > 0.0);  // the patches were drawn
    // The page is built for < 20 ms per frame on the GUI thread (typically 0.5 ms overlay, 2 ms
    // decode here, printed above). Both run on the GUI thread inside the watched loop: an overlay
    // or decode over 100 ms a frame spends the stall budget within a few frames.
    QVERIFY2(watchdog.withinBudget(), qPrintable(watchdog.summary()));
    // The patch shortcut toggles them.
    auto* patches = page_->findChild<QCheckBox*>("patchesCheck");
    QVERIFY(patches->isChecked());
    QTest::keyClick(page_.get(), Qt::Key_P);
    QVERIFY(!patches->isChecked());
    QTest::keyClick(page_.get(), Qt::Key_P);
    QVERIFY(patches->isChecked());
  }

  // The frame view draws what the tracker wrote per landmark: visible_k = 0 hollow, conf_k below
  // the tracker's threshold ringed (landmark_marks_test checks the drawing itself).
  void theFrameViewMarksWhatTheTrackerWrote() {
    const double threshold =
        landmarkScoreThreshold(page_->trackerSettings(), *page_->session().model());
    int hidden = 0;
    for (int f = 0; f < kFrames; ++f) {
      page_->setCurrentFrame(f);
      const TrackRow* row = page_->session().trackRow(f);
      QVERIFY(row != nullptr);
      QCOMPARE(row->landmarkConfidence.size(), std::size_t{25});  // conf_k from the tracker
      const auto& marks = page_->frameView()->marks();
      QCOMPARE(marks.size(), std::size_t{25});
      for (std::size_t k = 0; k < 25; ++k) {
        QCOMPARE(marks[k].hidden, row->visibility[k] == Visibility::Hidden);
        const double c = row->landmarkConfidence[k];
        QCOMPARE(marks[k].lowConfidence, std::isfinite(c) && c < threshold);
        hidden += marks[k].hidden ? 1 : 0;
      }
    }
    qInfo("%d hidden landmark-frames marked", hidden);
    // The written CSV carries them too, so a reopened track shows the same marks.
    const TrackTable written = readTrackTable(page_->tracksCsv());
    QCOMPARE(written.rows.back().landmarkConfidence.size(), std::size_t{25});
  }

  void clickingTheTimelineMovesToThatFrame() {
    TimelineWidget* timeline = page_->timeline();
    const QPoint at(static_cast<int>(std::lround(timeline->xOf(7))), timeline->height() / 2);
    QTest::mouseClick(timeline, Qt::LeftButton, {}, at);
    QCOMPARE(page_->currentFrame(), 7);
    QCOMPARE(timeline->currentFrame(), 7);
    QTest::keyClick(page_.get(), Qt::Key_Right);
    QCOMPARE(page_->currentFrame(), 8);
    QTest::keyClick(page_.get(), Qt::Key_Left);
    QTest::keyClick(page_.get(), Qt::Key_Left);
    QCOMPARE(page_->currentFrame(), 6);
    // Playing runs to the end at the video's rate.
    page_->setCurrentFrame(kFrames - 5);
    QTest::keyClick(page_.get(), Qt::Key_Space);
    QVERIFY(test::waitUntil([&] { return page_->currentFrame() == kFrames - 1; }, 5000));
    QVERIFY(!page_->findChild<PlayerBar*>("playerBar")->isPlaying());  // stopped at the end
    screenshot(*page_, "studio-track.png");
  }

  void draggingALandmarkIsOneUndoStepAndAKeyframe() {
    page_->setCurrentFrame(5);
    FrameView* view = page_->frameView();
    const int landmark = 12;
    const Eigen::Vector2d before = view->landmarks().col(landmark);
    const QPointF start = view->toWidget({before.x(), before.y()});
    const QPointF end = start + QPointF(14, 9);
    const int steps = page_->undoStack()->count();
    QTest::mousePress(view, Qt::LeftButton, {}, start.toPoint());
    for (int i = 1; i <= 5; ++i) {
      QTest::mouseMove(view, (start + (end - start) * i / 5.0).toPoint());
    }
    QTest::mouseRelease(view, Qt::LeftButton, {}, end.toPoint());
    QCOMPARE(page_->undoStack()->count(), steps + 1);
    const QPointF target = view->toFrame(end.toPoint());
    const TrackRow& row = page_->session().truth().table.rows[5];
    QVERIFY(std::abs(row.points(0, landmark) - target.x()) < 1e-6);
    QVERIFY(std::abs(row.points(1, landmark) - target.y()) < 1e-6);
    QVERIFY((row.points.col(landmark) - before).norm() > 3.0);
    QVERIFY(page_->session().truth().keyframe[5]);
    QVERIFY(page_->hasUnsavedChanges());
    page_->undoStack()->undo();
    QVERIFY((page_->session().truth().table.rows[5].points.col(landmark) - before).norm() < 1e-9);
    QVERIFY(!page_->session().truth().keyframe[5]);
    page_->undoStack()->redo();
    QVERIFY(page_->session().truth().keyframe[5]);
    QVERIFY(std::abs(page_->session().truth().table.rows[5].points(0, landmark) - target.x()) <
            1e-6);
  }

  void keyframesInterpolateAndTheGroundTruthSaves() {
    page_->setCurrentFrame(10);
    QTest::keyClick(page_.get(), Qt::Key_K);
    QVERIFY(page_->session().truth().keyframe[10]);
    QCOMPARE(page_->interpolateKeyframes(), 4);
    QCOMPARE(page_->session().truth().keyframeCount(), 2);

    QSignalSpy modified(page_.get(), &Page::projectModified);
    QVERIFY(page_->save());
    QVERIFY(!page_->hasUnsavedChanges());
    const fs::path csv = page_->groundTruthCsv();
    QCOMPARE(csv, project_.folder / "ground-truth" / "sequence" / "sequence.csv");
    QCOMPARE(project_.groundTruth.size(), std::size_t{1});
    QCOMPARE(modified.count(), 1);
    const GroundTruthSet saved = loadGroundTruth(csv);
    QCOMPARE(saved.frameCount(), kFrames);
    QVERIFY(saved.keyframe[5] && saved.keyframe[10] && !saved.keyframe[7]);
    const Eigen::Vector2d corrected = page_->session().truth().table.rows[5].points.col(12);
    QVERIFY((saved.table.rows[5].points.col(12) - corrected).norm() < 1e-3);
    const TrackTable plain = readTrackTable(csv);
    QCOMPARE(static_cast<int>(plain.rows.size()), kFrames);
    const LandmarkSet pts = readLandmarks(csv.parent_path() / groundTruthPtsName(5));
    QCOMPARE(pts.size(), 25);
    QVERIFY((pts.point(12).head<2>() - corrected).norm() < 1e-3);
  }

  void retrackForwardReplacesTheFollowingRows() {
    page_->setCurrentFrame(5);
    const int steps = page_->undoStack()->count();
    test::StallWatchdog watchdog;
    watchdog.start();
    QTest::mouseClick(page_->findChild<QPushButton*>("retrackButton"), Qt::LeftButton);
    QVERIFY(page_->isBusy());
    QVERIFY(waitForJob());
    watchdog.stop();
    qInfo("re-tracking: GUI thread %s", qPrintable(watchdog.summary()));
    QVERIFY2(watchdog.withinBudget(), qPrintable(watchdog.summary()));
    const TrackTable& track = page_->session().track();
    QCOMPARE(static_cast<int>(track.rows.size()), kFrames);
    for (int f = 0; f < kFrames; ++f) QCOMPARE(track.rows[static_cast<std::size_t>(f)].frame, f);
    QCOMPARE(page_->undoStack()->count(), steps + 1);
    // Keyframes survive a re-track; frame 6 now holds the re-tracked points.
    QVERIFY(page_->session().truth().keyframe[10]);
    QVERIFY((page_->session().truth().table.rows[6].points - track.rows[6].points).norm() < 1e-9);
  }

  void comparingWithTheTruthPlotsTheError() {
    QVERIFY(page_->compareWith(sequence_.truth));
    int scored = 0;
    for (double e : page_->session().errors()) {
      if (std::isfinite(e)) {
        ++scored;
        QVERIFY(e < 0.2);
      }
    }
    QCOMPARE(scored, kFrames);
    page_->setCurrentFrame(5);  // the frame corrected by dragging
    screenshot(*page_, "studio-track-correct.png");
  }

  void exportWritesTheOverlayVideo() {
    const fs::path out = temp_.path() / "overlay.avi";
    QVERIFY(page_->exportOverlay(out));
    QVERIFY(waitForJob());
    QVERIFY(fs::exists(out));
    VideoReader reader(out);
    QCOMPARE(reader.frameCount(), kFrames);
  }

  void aFileThatIsNotAVideoShowsTheErrorNamingIt() {
    const fs::path garbage = temp_.path() / "broken-video.avi";
    std::ofstream(garbage) << "this is not a video at all\n";
    QVERIFY(page_->save());  // else opening another video first asks about the corrections
    QString message;
    test::expectErrorDialog(&message);
    QVERIFY(!page_->openVideo(garbage));
    QVERIFY2(message.contains("broken-video.avi"), qPrintable(message));
    // The previous video stays open.
    QCOMPARE(page_->session().video().path, sequence_.video);
  }

  void theAutosaveIntervalIsThePreferences() {
    QCOMPARE(page_->autosaveIntervalMs(), loadPreferences().autosaveSeconds * 1000);
    StudioPreferences preferences = loadPreferences();
    preferences.autosaveSeconds = 11;
    savePreferences(preferences);
    page_->preferencesChanged();
    QCOMPARE(page_->autosaveIntervalMs(), 11000);
    TrackPage fresh;  // a page built later reads them too
    QCOMPARE(fresh.autosaveIntervalMs(), 11000);
  }

  void unsavedCorrectionsAreAutosavedAndRecoveredOnReopen() {
    const fs::path csv = page_->groundTruthCsv();
    QVERIFY(!page_->hasUnsavedChanges());
    page_->setCurrentFrame(3);
    page_->toggleKeyframe();
    QVERIFY(page_->autosave());
    QVERIFY(!page_->autosave());  // nothing new
    QVERIFY(hasRecoverableAutosave(csv));
    QVERIFY(loadGroundTruth(autosavePathFor(csv)).keyframe[3]);
    // The studio "crashes": the page goes without saving; a new page opens the video again and
    // offers the autosave, which the user accepts.
    page_->undoStack()->setClean();  // so the page closes without asking
    page_ = std::make_unique<TrackPage>();
    auto* answer = new QTimer(this);
    bool asked = false;
    connect(answer, &QTimer::timeout, this, [&] {
      for (QWidget* widget : QApplication::topLevelWidgets()) {
        auto* box = qobject_cast<QMessageBox*>(widget);
        if (box && box->isVisible() && box->windowTitle() == "Recover corrections") {
          asked = true;
          box->button(QMessageBox::Yes)->click();
        }
      }
    });
    answer->start(20);
    // Opening the project opens its first video (this one), which offers the autosave.
    page_->setProject(&project_);
    if (page_->session().video().path != sequence_.video) {
      QVERIFY(page_->openVideo(sequence_.video));
    }
    answer->stop();
    answer->deleteLater();
    QVERIFY(asked);
    QVERIFY(page_->session().truth().keyframe[3]);
    QVERIFY(page_->session().truth().keyframe[5]);  // from the saved set
    QVERIFY(page_->hasUnsavedChanges());
    QVERIFY(page_->save());
    QVERIFY(!hasRecoverableAutosave(csv));
    QVERIFY(loadGroundTruth(csv).keyframe[3]);
  }

  void cleanupTestCase() { page_.reset(); }
};

}  // namespace clm3d::ui

QTEST_MAIN(clm3d::ui::TrackPageTest)
#include "track_page_test.moc"
