// The Track page's frames worth a look (issue 29, item 1) on a synthetic head's track with a low
// check, a jump and an outlier made into it: the page's list is core's ranking of the ground truth,
// the timeline marks every listed frame, N / Shift+N walk the list in rank order (wrapping), and
// accepting a frame (A) or correcting it (a drag) takes it off the list and off the timeline, N
// then going on from the rank it had; saving writes the COCO keypoints beside the ground-truth CSV.
#include "core/track/review_list.hpp"

#include <QApplication>
#include <QTest>
#include <algorithm>
#include <cmath>

#include "core/project/project.hpp"
#include "core/project/project_layout.hpp"
#include "core/scheme/scheme.hpp"
#include "core/track/coco_keypoints.hpp"
#include "core/track/track_table.hpp"
#include "tests/gui/support/gui_test_support.hpp"
#include "tests/gui/track/track_fixture.hpp"
#include "ui/track/frame_view.hpp"
#include "ui/track/timeline_widget.hpp"
#include "ui/track/track_page.hpp"

namespace clm3d::ui {
namespace {

namespace fs = std::filesystem;

constexpr int kFrames = 24;
constexpr int kLowFrame = 5;
constexpr int kJumpFrame = 12;
constexpr int kOutlierFrame = 18;

// The truth as a confident track, then: frame 5 a low check, every point from frame 12 on 0.3 eye
// distances lower (a jump at 12), point 12 of frame 18 0.12 eye distances off (an outlier).
TrackTable reviewTrack(TrackTable table) {
  for (TrackRow& row : table.rows) {
    row.success = true;
    row.confidence = 0.9;
    const double eyes = (row.points.col(7) - row.points.col(10)).norm();
    if (row.frame >= kJumpFrame) row.points.row(1).array() += 0.3 * eyes;
    if (row.frame == kOutlierFrame) row.points(0, 11) += 0.12 * eyes;
    if (row.frame == kLowFrame) row.confidence = 0.2;
  }
  return table;
}

std::vector<int> listedFrames(const std::vector<ReviewItem>& items) {
  std::vector<int> frames;
  for (const ReviewItem& item : items) frames.push_back(item.frame);
  return frames;
}

bool listed(const std::vector<ReviewItem>& items, int frame, ReviewCriterion criterion) {
  for (const ReviewItem& item : items) {
    if (item.frame != frame) continue;
    for (const ReviewReason& reason : item.reasons) {
      if (reason.criterion == criterion) return true;
    }
  }
  return false;
}

}  // namespace

class ReviewListTest : public QObject {
  Q_OBJECT
 private:
  test::TempDir temp_;
  Project project_;
  TrackTable track_;
  std::unique_ptr<TrackPage> page_;

  void press(Qt::Key key, Qt::KeyboardModifiers modifiers = Qt::NoModifier) {
    QTest::keyClick(page_.get(), key, modifiers);
  }

  // The page's list must be core's ranking of the page's ground truth, and the timeline must mark
  // exactly its frames.
  void checkListMatchesCore() {
    const GroundTruthSet& truth = page_->session().truth();
    ReviewListSettings settings;
    settings.lowConfidence = 0.5;
    const auto expected = rankFramesForReview(truth.table, truth.keyframe,
                                              Scheme::thesis25().normalisationPair(), settings);
    QCOMPARE(listedFrames(page_->reviewList()), listedFrames(expected));
    std::vector<int> marked = page_->timeline()->data().review;
    std::vector<int> frames = listedFrames(expected);
    std::sort(marked.begin(), marked.end());
    std::sort(frames.begin(), frames.end());
    QCOMPARE(marked, frames);
  }

 private slots:
  void initTestCase() {
    test::TrackProject made =
        test::makeTrackProject(temp_.path() / "project", "review-list", kFrames, 2.0);
    project_ = std::move(made.project);
    track_ = reviewTrack(readTrackTable(made.fixture.sequence.truth));
    const fs::path csv = project_layout::tracksFile(project_.folder, made.fixture.sequence.video,
                                                    made.fixture.model);
    fs::create_directories(csv.parent_path());
    writeTrackTable(csv, track_);
    project_.tracks.push_back(csv);
    saveProject(project_);
    page_ = std::make_unique<TrackPage>();
    QVERIFY(test::showForTest(*page_, {1280, 820}, true));
    page_->setProject(&project_);
    QCOMPARE(static_cast<int>(page_->session().track().rows.size()), kFrames);
  }

  void theListHasEachCriterionAndTheTimelineMarksIt() {
    const auto& items = page_->reviewList();
    QVERIFY(listed(items, kLowFrame, ReviewCriterion::LowConfidence));
    QVERIFY(listed(items, kJumpFrame, ReviewCriterion::Jump));
    QVERIFY(listed(items, kOutlierFrame, ReviewCriterion::TemporalFit));
    QVERIFY(items.size() >= 3);
    for (std::size_t i = 1; i < items.size(); ++i) QVERIFY(items[i - 1].score >= items[i].score);
    checkListMatchesCore();
  }

  void nAndShiftNWalkTheListInRankOrder() {
    page_->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(page_.get()));
    page_->setFocus();
    const std::vector<int> ranked = listedFrames(page_->reviewList());
    const int count = static_cast<int>(ranked.size());
    // A frame not in the list: N starts at the top.
    int outside = 0;
    while (std::find(ranked.begin(), ranked.end(), outside) != ranked.end()) ++outside;
    page_->setCurrentFrame(outside);
    press(Qt::Key_N);
    QCOMPARE(page_->currentFrame(), ranked[0]);
    for (int r = 1; r < count; ++r) {
      press(Qt::Key_N);
      QCOMPARE(page_->currentFrame(), ranked[static_cast<std::size_t>(r)]);
    }
    press(Qt::Key_N);  // past the end: back to the top
    QCOMPARE(page_->currentFrame(), ranked[0]);
    press(Qt::Key_N, Qt::ShiftModifier);  // and back up past the top: the last
    QCOMPARE(page_->currentFrame(), ranked.back());
    press(Qt::Key_N, Qt::ShiftModifier);
    QCOMPARE(page_->currentFrame(), ranked[static_cast<std::size_t>(count - 2)]);
  }

  void acceptingTakesAFrameOffTheList() {
    const std::vector<int> ranked = listedFrames(page_->reviewList());
    QVERIFY(ranked.size() >= 3);
    // The jump ranks first (0.3 / 0.15 = 2, the low check (1 - 0.2) / 0.5 = 1.6, the outlier 1.2);
    // accepting it keeps its points, so only being a keyframe takes it off the list.
    QCOMPARE(ranked[0], kJumpFrame);
    page_->setCurrentFrame(ranked.back());
    press(Qt::Key_N);  // wraps to the top, so the page knows the rank
    QCOMPARE(page_->currentFrame(), ranked[0]);
    press(Qt::Key_A);  // accept: a keyframe, off the list, and on to the next one
    QVERIFY(page_->session().truth().keyframe[static_cast<std::size_t>(ranked[0])]);
    std::vector<int> now = listedFrames(page_->reviewList());
    QVERIFY(std::find(now.begin(), now.end(), ranked[0]) == now.end());
    QCOMPARE(page_->currentFrame(), ranked[1]);  // it took the accepted frame's rank
    checkListMatchesCore();
    // Undo puts it back on the list.
    QTest::keyClick(page_.get(), Qt::Key_Z, Qt::ControlModifier);
    now = listedFrames(page_->reviewList());
    QVERIFY(std::find(now.begin(), now.end(), ranked[0]) != now.end());
  }

  void correctingTakesAFrameOffTheList() {
    page_->setLoopEnabled(false);  // the correction only, no re-track
    const std::vector<int> before = listedFrames(page_->reviewList());
    QVERIFY(std::find(before.begin(), before.end(), kOutlierFrame) != before.end());
    page_->setCurrentFrame(kOutlierFrame);
    // Drag the outlying point back where the frames around it have it.
    FrameView* view = page_->frameView();
    const Eigen::Vector2d now = track_.rows[kOutlierFrame].points.col(11);
    const Eigen::Vector2d home = 0.5 * (track_.rows[kOutlierFrame - 1].points.col(11) +
                                        track_.rows[kOutlierFrame + 1].points.col(11));
    const QPoint from = view->toWidget({now.x(), now.y()}).toPoint();
    const QPoint to = view->toWidget({home.x(), home.y()}).toPoint();
    QTest::mousePress(view, Qt::LeftButton, {}, from);
    QTest::mouseMove(view, (from + to) / 2);
    QTest::mouseMove(view, to);
    QTest::mouseRelease(view, Qt::LeftButton, {}, to);
    QVERIFY(page_->session().truth().keyframe[kOutlierFrame]);
    const std::vector<int> after = listedFrames(page_->reviewList());
    QVERIFY(std::find(after.begin(), after.end(), kOutlierFrame) == after.end());
    checkListMatchesCore();
  }

  // The studio's save writes the COCO keypoints beside the CSV and the .pts files.
  void savingWritesCocoKeypoints() {
    QVERIFY(page_->save());
    const fs::path csv = page_->groundTruthCsv();
    const fs::path coco = cocoKeypointsBeside(csv);
    QVERIFY(fs::exists(csv));
    QVERIFY(fs::exists(csv.parent_path() / "frame_000000.pts"));
    QVERIFY(fs::exists(coco));
    const GroundTruthSet read = loadCocoKeypoints(coco);
    const GroundTruthSet& truth = page_->session().truth();
    QCOMPARE(read.keyframe, truth.keyframe);
    QVERIFY(read.keyframe[kOutlierFrame]);
    QVERIFY(
        (read.table.rows[kOutlierFrame].points - truth.table.rows[kOutlierFrame].points).norm() <
        1e-9);
  }

  void cleanupTestCase() { page_.reset(); }
};

}  // namespace clm3d::ui

QTEST_MAIN(clm3d::ui::ReviewListTest)
#include "review_list_test.moc"
