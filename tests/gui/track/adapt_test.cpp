// The Track page's Adapt action on the tiny trained model and a short synthetic video: a ground
// truth with three keyframes loaded, Adapt runs on the worker without stalling the GUI thread,
// the adapted model joins the project beside the general one (its provenance names the keyframes),
// the keyframes stay as they were, the other frames take the adapted model's rows and the timeline
// marks those that changed; cancelled, the project and the ground truth stay as they were.
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>
#include <cmath>

#include "core/model/model_file.hpp"
#include "core/project/project.hpp"
#include "core/project/project_layout.hpp"
#include "core/track/ground_truth.hpp"
#include "tests/gui/project/isolated_settings.hpp"
#include "tests/gui/support/gui_test_support.hpp"
#include "tests/gui/track/track_fixture.hpp"
#include "ui/common/job_runner.hpp"
#include "ui/track/timeline_widget.hpp"
#include "ui/track/track_page.hpp"

namespace clm3d::ui {

namespace fs = std::filesystem;

namespace {

// The same points to a thousandth of a pixel (the CSV's precision), missing ones alike.
bool samePoints(const Eigen::Matrix2Xd& a, const Eigen::Matrix2Xd& b) {
  if (a.cols() != b.cols()) return false;
  for (Eigen::Index i = 0; i < a.size(); ++i) {
    const double x = a.data()[i], y = b.data()[i];
    if (std::isnan(x) != std::isnan(y) || (!std::isnan(x) && std::abs(x - y) > 1e-3)) return false;
  }
  return true;
}

}  // namespace

class AdaptTest : public QObject {
  Q_OBJECT

  static constexpr int kFrames = 12;
  const std::vector<int> keyframes_{0, 5, 10};

  test::IsolatedSettings settings_;
  test::TempDir temp_;
  Project project_;
  SequenceFiles sequence_;
  TrackTable truth_;
  fs::path groundTruth_;
  std::unique_ptr<TrackPage> page_;

  bool waitForJob(int timeoutMs = 180000) {
    return test::waitUntil([&] { return !page_->isBusy(); }, timeoutMs);
  }

  // The models in the project's models folder.
  int modelFiles() const {
    int count = 0;
    for (const auto& entry : fs::directory_iterator(project_.folder / "models")) {
      count += entry.path().extension() == ".clm3d" ? 1 : 0;
    }
    return count;
  }

 private slots:
  void initTestCase() {
    test::TrackProject made =
        test::makeTrackProject(temp_.path() / "project", "adapt-test", kFrames, 2.0);
    project_ = std::move(made.project);
    sequence_ = made.fixture.sequence;
    truth_ = made.fixture.summary.truth;
    // The exact truth with three frames marked as corrected.
    GroundTruthSet set = GroundTruthSet::fromTrack(truth_, kFrames);
    for (const int frame : keyframes_) {
      set.setKeyframe(frame, truth_.rows[static_cast<std::size_t>(frame)].points);
    }
    // Saved where the page keeps this video's ground truth, so opening the video opens it.
    groundTruth_ = project_layout::groundTruthFile(project_.folder, sequence_.video);
    fs::create_directories(groundTruth_.parent_path());
    saveGroundTruth(groundTruth_, set);
    page_ = std::make_unique<TrackPage>();
    QVERIFY(test::showForTest(*page_, {1280, 820}, true));
    page_->setProject(&project_);
    page_->setLoopEnabled(false);
    QVERIFY(page_->openVideo(sequence_.video));
    QCOMPARE(page_->groundTruthCsv(), groundTruth_);
    QCOMPARE(page_->session().truth().keyframeCount(), 3);
  }

  void cancelLeavesTheProjectAsItWas() {
    const std::vector<fs::path> models = project_.models;
    const GroundTruthSet before = page_->session().truth();
    JobRunner* runner = page_->jobRunner();
    QSignalSpy cancelled(runner, &JobRunner::cancelled);
    const auto connection = connect(runner, &JobRunner::progressed, this,
                                    [runner](double, const QString&) { runner->cancel(); });
    QVERIFY(page_->adaptModelToVideo());
    QVERIFY(waitForJob());
    disconnect(connection);
    QCOMPARE(cancelled.count(), 1);
    QCOMPARE(project_.models, models);
    QCOMPARE(modelFiles(), 1);
    QVERIFY(page_->adaptChangedFrames().empty());
    const GroundTruthSet& after = page_->session().truth();
    QCOMPARE(after.keyframe, before.keyframe);
    for (int f = 0; f < kFrames; ++f) {
      QVERIFY(samePoints(after.table.rows[static_cast<std::size_t>(f)].points,
                         before.table.rows[static_cast<std::size_t>(f)].points));
    }
  }

  void adaptKeepsBothModelsAndRetracksTheOtherFrames() {
    auto* adapt = page_->findChild<QPushButton*>("adaptButton");
    QVERIFY(adapt && adapt->isEnabled());
    const fs::path general = project_.models.front();
    test::StallWatchdog watchdog;
    watchdog.start();
    QTest::mouseClick(adapt, Qt::LeftButton);
    QVERIFY(page_->isBusy());
    QVERIFY(waitForJob());
    watchdog.stop();
    qInfo("adapt: GUI thread %s", qPrintable(watchdog.summary()));
    QVERIFY2(watchdog.withinBudget(), qPrintable(watchdog.summary()));

    // Both models in the project; the page now uses the adapted one.
    QCOMPARE(project_.models.size(), std::size_t{2});
    QCOMPARE(project_.models.front(), general);
    const fs::path adapted = project_.models.back();
    QVERIFY(fs::exists(adapted));
    QCOMPARE(page_->session().modelPath(), adapted);
    const ClmModel model = loadModel(adapted);
    QCOMPARE(model.adaptation.frames, keyframes_);
    QCOMPARE(fs::path(model.adaptation.model), general);
    QCOMPARE(fs::path(model.adaptation.video), sequence_.video);

    // Keyframes as they were; the other frames re-tracked, the changed ones marked.
    const GroundTruthSet& truth = page_->session().truth();
    QCOMPARE(static_cast<int>(page_->session().track().rows.size()), kFrames);
    for (const int frame : keyframes_) {
      QVERIFY(truth.keyframe[static_cast<std::size_t>(frame)]);
      QVERIFY(samePoints(truth.table.rows[static_cast<std::size_t>(frame)].points,
                         truth_.rows[static_cast<std::size_t>(frame)].points));
    }
    const std::vector<int>& changed = page_->adaptChangedFrames();
    QVERIFY(!changed.empty());
    for (const int frame : changed) {
      QVERIFY(!truth.keyframe[static_cast<std::size_t>(frame)]);
      const TrackRow& row = truth.table.rows[static_cast<std::size_t>(frame)];
      QCOMPARE(row.frame, frame);
      QVERIFY(!samePoints(row.points, truth_.rows[static_cast<std::size_t>(frame)].points));
    }
    QCOMPARE(page_->timeline()->data().changed, changed);
    // One undo step puts the rows back.
    page_->undoStack()->undo();
    const auto first = static_cast<std::size_t>(changed.front());
    QVERIFY(
        samePoints(page_->session().truth().table.rows[first].points, truth_.rows[first].points));
  }

  void cleanupTestCase() { page_.reset(); }
};

}  // namespace clm3d::ui

QTEST_MAIN(clm3d::ui::AdaptTest)
#include "adapt_test.moc"
