// What the frame view draws from the tracker's per-landmark output: marks taken from a track row
// (visible_k = 0 hidden; conf_k below the threshold ringed, unless a person moved the point), and
// the drawing itself on a plain frame: a visible landmark filled in its colour, a hidden one hollow
// (the frame shows through its centre), a low-confidence one with a red ring around it.
#include "ui/track/landmark_marks.hpp"

#include <QTest>
#include <cmath>

#include "tests/gui/support/gui_test_support.hpp"
#include "ui/track/frame_view.hpp"

namespace clm3d::ui {

class LandmarkMarksTest : public QObject {
  Q_OBJECT
 private slots:
  void marksComeFromTheTrackRow() {
    TrackRow row;
    row.points.resize(2, 4);
    row.points << 10, 20, 30, 40, 10, 20, 30, 40;
    row.visibility = {Visibility::Visible, Visibility::Hidden, Visibility::Unknown,
                      Visibility::Visible};
    row.landmarkConfidence = {0.9, 0.1, std::nan(""), 0.2};
    Eigen::Matrix2Xd shown = row.points;
    shown(0, 3) += 5.0;  // a person moved landmark 3: the fit no longer speaks for it
    const auto marks = landmarkMarks(&row, shown, 0.35);
    QCOMPARE(marks.size(), std::size_t{4});
    QVERIFY(!marks[0].hidden && !marks[0].lowConfidence);
    QVERIFY(marks[1].hidden && marks[1].lowConfidence);
    QVERIFY(!marks[2].hidden && !marks[2].lowConfidence);  // unknown is not hidden; NaN not low
    QVERIFY(!marks[3].hidden && !marks[3].lowConfidence);
    QVERIFY(landmarkMarks(nullptr, shown, 0.35).empty());
    // A table without visible_k / conf_k columns (older CSVs, ground truth): nothing marked.
    TrackRow plain;
    plain.points = row.points;
    for (const auto& mark : landmarkMarks(&plain, row.points, 0.35)) {
      QVERIFY(!mark.hidden && !mark.lowConfidence);
    }
  }

  void hiddenIsHollowAndLowConfidenceIsRinged() {
    FrameView view;
    QVERIFY(test::showForTest(view, {640, 480}));
    QImage frame(320, 240, QImage::Format_RGB32);
    frame.fill(QColor(128, 128, 128));
    view.setImage(frame);
    Eigen::Matrix2Xd points(2, 3);
    points << 80, 160, 240, 120, 120, 120;
    const QColor fill(40, 200, 40);
    view.setLandmarks(points, {fill, fill, fill},
                      {LandmarkMark{}, LandmarkMark{true, false}, LandmarkMark{false, true}});
    const QImage shot = view.grab().toImage();
    const auto at = [&](int i, double dx) {
      const QPointF p = view.toWidget({points(0, i), points(1, i)});
      return shot.pixelColor(static_cast<int>(std::lround(p.x() + dx)),
                             static_cast<int>(std::lround(p.y())));
    };
    const auto near = [](const QColor& a, const QColor& b) {
      return std::abs(a.red() - b.red()) + std::abs(a.green() - b.green()) +
                 std::abs(a.blue() - b.blue()) <
             30;
    };
    QVERIFY(near(at(0, 0), fill));                   // visible: filled
    QVERIFY(near(at(1, 0), QColor(128, 128, 128)));  // hidden: the frame shows through
    QVERIFY(!near(at(1, view.landmarkRadius()), QColor(128, 128, 128)));  // ... inside its ring
    QVERIFY(near(at(2, 0), fill));  // low confidence: still filled
    const QColor ring = at(2, view.landmarkRadius() * FrameView::kLowConfidenceRing);
    QVERIFY2(ring.red() > 180 && ring.green() < 90,
             qPrintable(QString("ring pixel %1").arg(ring.name())));
    QVERIFY(near(at(0, view.landmarkRadius() * FrameView::kLowConfidenceRing),
                 QColor(128, 128, 128)));  // no ring around the plain one
  }
};

}  // namespace clm3d::ui

QTEST_MAIN(clm3d::ui::LandmarkMarksTest)
#include "landmark_marks_test.moc"
