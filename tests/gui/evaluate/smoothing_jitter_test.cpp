// Smoothing on and off as a user sees it on the Evaluate page: a held-out procedural head turning
// one degree a frame is tracked twice with the test fixture's small model (core's trackVideo, as
// `clm3d track` and `clm3d track --smooth` do), both tracks are evaluated against the sequence's
// truth on the page, and its Jitter column must fall with smoothing on while its Lag column rises,
// each cell the figure `clm3d eval` prints.
#include <QSignalSpy>
#include <QTableWidget>
#include <QTest>

#include "core/detect/initialisation.hpp"
#include "core/eval/eval_report.hpp"
#include "core/eval/synthetic_sequence.hpp"
#include "core/track/tracker.hpp"
#include "tests/gui/support/gui_test_support.hpp"
#include "tests/support/fit_fixture.hpp"
#include "ui/evaluate/evaluate_page.hpp"
#include "ui/evaluate/evaluation_inputs.hpp"
#include "ui/evaluate/summary_table.hpp"

namespace clm3d::ui {

namespace fs = std::filesystem;

class SmoothingJitterTest : public QObject {
  Q_OBJECT
 private slots:
  void smoothingLowersTheJitterThePageShows() {
    test::TempDir folder;
    const SequenceFiles sequence = SequenceFiles::inFolder(folder.path() / "turn");
    const fs::path raw = folder.path() / "raw.csv";
    const fs::path smooth = folder.path() / "smooth.csv";
    test::runOffGuiThread([&] {
      SequenceSettings settings;
      settings.yawFromDeg = 0.0;
      settings.yawToDeg = 30.0;
      settings.stepDeg = 1.0;
      settings.width = 320;
      settings.height = 240;
      settings.interOcularPixels = 56.0;
      settings.supersample = 1;
      const SynthHead& head = test::fitTestHead(test::kHeldOutHead);
      writeSyntheticSequence(head.mesh, head.landmarks, Scheme::thesis25(), settings,
                             SequenceSubject{}, sequence);
      const ClmModel& model = test::fitTestModel();
      const FitState start = stateFromPoints(
          model, Camera::fromVerticalFov(320, 240, kDefaultVerticalFovDeg),
          readTrackTable(sequence.truth).rows[0].points, std::vector<bool>(25, true));
      for (const bool on : {false, true}) {
        TrackerSettings tracker;
        tracker.smoothing.enabled = on;
        TrackTable table;
        trackVideo(sequence.video, model, tracker, table, {}, {}, nullptr, start);
        writeTrackTable(on ? smooth : raw, table);
      }
    });

    EvaluatePage page;
    page.resize(1400, 900);
    page.show();
    page.inputs().setGroundTruth(sequence.truth);
    page.inputs().addPrediction(raw);
    page.inputs().addPrediction(smooth);
    QSignalSpy finished(&page, &EvaluatePage::evaluationFinished);
    QVERIFY(page.evaluate());
    QVERIFY(test::waitUntil([&] { return finished.count() == 1 && !page.isBusy(); }, 60000));

    const QTableWidget* table = page.summaryTable();
    QCOMPARE(table->rowCount(), 2);
    QCOMPARE(table->horizontalHeaderItem(kJitterColumn)->text(), QString("Jitter"));
    const auto number = [&](int row, int column) {
      bool ok = false;
      const double value = table->item(row, column)->text().toDouble(&ok);
      if (!ok) qWarning("not a number: %s", qPrintable(table->item(row, column)->text()));
      return value;
    };
    const double rawJitter = number(0, kJitterColumn);
    const double smoothJitter = number(1, kJitterColumn);
    qInfo("jitter off %.4f on %.4f; lag off %s on %s frames", rawJitter, smoothJitter,
          qPrintable(table->item(0, kLagColumn)->text()),
          qPrintable(table->item(1, kLagColumn)->text()));
    QVERIFY(rawJitter > 0.0);
    QVERIFY2(smoothJitter < 0.8 * rawJitter, "smoothing must lower the jitter");
    QVERIFY(number(1, kLagColumn) > number(0, kLagColumn));
    // The page's figures are core's, as `clm3d eval` prints them.
    const EvaluationReport core =
        evaluateTrackFiles(sequence.truth, {raw, smooth}, {"raw", "smooth"}, Scheme::thesis25());
    for (int row = 0; row < 2; ++row) {
      QCOMPARE(table->item(row, kJitterColumn)->text().toStdString(),
               formatErrorValue(core.sequences[static_cast<std::size_t>(row)].summary.jitter));
    }
    QVERIFY(formatReportText(core).find("jitter " +
                                        table->item(1, kJitterColumn)->text().toStdString()) !=
            std::string::npos);
  }
};

}  // namespace clm3d::ui

QTEST_MAIN(clm3d::ui::SmoothingJitterTest)
#include "smoothing_jitter_test.moc"
