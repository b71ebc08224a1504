// The Evaluate page against core: a ground truth and predictions with known offsets and noise are
// written as tracks CSVs, the page evaluates them on its worker, and its CDF series, region bars,
// table and p-value must be core's numbers as `clm3d eval` prints them (formatReportText); the
// PNG and CSV exports are checked, and broken or mismatched files show the error dialog while the
// page stays usable. CLM3D_SCREENSHOTS=1 also writes docs/images/studio-evaluate.png.
#include "ui/evaluate/evaluate_page.hpp"

#include <QApplication>
#include <QImage>
#include <QLabel>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTest>
#include <QtCharts/QBarSeries>
#include <QtCharts/QBarSet>
#include <QtCharts/QLineSeries>
#include <cmath>
#include <random>
#include <set>

#include "core/common/atomic_file.hpp"
#include "core/common/error.hpp"
#include "core/eval/eval_report.hpp"
#include "core/scheme/scheme.hpp"
#include "core/track/track_table.hpp"
#include "tests/gui/support/gui_test_support.hpp"
#include "ui/evaluate/evaluation_inputs.hpp"
#include "ui/evaluate/evaluation_job.hpp"
#include "ui/evaluate/report_format.hpp"

using namespace QtCharts;

namespace clm3d::ui {
namespace {

namespace fs = std::filesystem;

// A thesis25 face moving slowly across the image (eye centres 80 pixels apart).
TrackTable truthTable(int frames) {
  TrackTable table;
  table.landmarkCount = 25;
  for (int f = 0; f < frames; ++f) {
    TrackRow row;
    row.frame = f;
    row.timestamp = f / 25.0;
    row.success = true;
    row.confidence = 1.0;
    row.points.resize(2, 25);
    const double cx = 320.0 + 40.0 * std::sin(f / 20.0);
    for (int i = 0; i < 25; ++i) {
      row.points(0, i) = cx - 60.0 + 5.0 * i;
      row.points(1, i) = 240.0 + 3.0 * (i % 7);
    }
    row.points.col(7) = Eigen::Vector2d(cx - 40.0, 200.0);
    row.points.col(10) = Eigen::Vector2d(cx + 40.0, 200.0);
    table.rows.push_back(row);
  }
  return table;
}

// The truth moved by `offset` pixels along x plus Gaussian noise of `noise` pixels (fixed seed).
TrackTable predictionOf(const TrackTable& truth, double offset, double noise, unsigned seed) {
  std::mt19937 random(seed);
  std::normal_distribution<double> gauss(0.0, noise);
  TrackTable table = truth;
  for (auto& row : table.rows) {
    row.confidence = 0.8;
    for (int i = 0; i < table.landmarkCount; ++i) {
      row.points(0, i) += offset + gauss(random);
      row.points(1, i) += gauss(random);
    }
  }
  return table;
}

struct Files {
  test::TempDir folder;
  fs::path truth, close, far, worse;
  explicit Files(int frames = 120) {
    const auto gt = truthTable(frames);
    truth = folder.path() / "truth.csv";
    close = folder.path() / "multi-view.csv";
    far = folder.path() / "single-view.csv";
    worse = folder.path() / "no-alpha.csv";
    writeTrackTable(truth, gt);
    writeTrackTable(close, predictionOf(gt, 1.0, 2.0, 1));
    writeTrackTable(far, predictionOf(gt, 6.0, 4.0, 2));
    writeTrackTable(worse, predictionOf(gt, 12.0, 6.0, 3));
  }
};

EvaluationReport coreReport(const fs::path& truth, const std::vector<fs::path>& predictions) {
  return evaluateTrackFiles(truth, predictions, predictionLabels(predictions), Scheme::thesis25());
}

bool runPage(EvaluatePage& page) {
  QSignalSpy finished(&page, &EvaluatePage::evaluationFinished);
  if (!page.evaluate()) return false;
  return test::waitUntil([&] { return finished.count() == 1 && !page.isBusy(); }, 30000);
}

std::vector<QLineSeries*> lineSeries(QChart* chart) {
  std::vector<QLineSeries*> result;
  for (auto* series : chart->series()) {
    if (auto* line = qobject_cast<QLineSeries*>(series)) result.push_back(line);
  }
  return result;
}

}  // namespace

class EvaluatePageTest : public QObject {
  Q_OBJECT
 private slots:
  void twoPredictionsShowCoresNumbers() {
    Files files;
    EvaluatePage page;
    page.resize(1400, 900);
    page.show();
    page.inputs().setGroundTruth(files.truth);
    page.inputs().addPrediction(files.close);
    page.inputs().addPrediction(files.far);
    QCOMPARE(page.title(), QString("Evaluate"));

    test::StallWatchdog watchdog;
    watchdog.start();
    QVERIFY(runPage(page));
    watchdog.stop();
    qInfo("evaluating 2 predictions: GUI thread %s", qPrintable(watchdog.summary()));
    QVERIFY2(watchdog.withinBudget(), qPrintable(watchdog.summary()));

    const auto core = coreReport(files.truth, {files.close, files.far});
    const std::string printed = formatReportText(core);  // what `clm3d eval` prints
    QVERIFY(page.report() != nullptr);
    QCOMPARE(page.report()->sequences.size(), std::size_t{2});

    // CDF: one line per prediction with core's samples, then the threshold marker at 0.18.
    const auto lines = lineSeries(page.cdfChart());
    QCOMPARE(lines.size(), std::size_t{3});
    for (std::size_t p = 0; p < 2; ++p) {
      const auto& cdf = core.sequences[p].summary.cdf;
      QCOMPARE(lines[p]->name(), QString::fromStdString(core.sequences[p].label));
      QCOMPARE(lines[p]->count(), static_cast<int>(cdf.size()));
      for (std::size_t k = 0; k < cdf.size(); ++k) {
        QCOMPARE(lines[p]->at(static_cast<int>(k)).x(), cdf[k].threshold);
        QCOMPARE(lines[p]->at(static_cast<int>(k)).y(), cdf[k].frames);
      }
    }
    QCOMPARE(lines[2]->objectName(), QString(kThresholdSeriesName));
    QCOMPARE(lines[2]->at(0).x(), 0.18);
    QCOMPARE(lines[2]->at(1).x(), 0.18);
    // The two predictions differ: the close one's curve rises first.
    QVERIFY(lines[0]->at(5).y() > lines[1]->at(5).y());

    page.setCdfOf(CdfOf::Points);
    const auto pointLines = lineSeries(page.cdfChart());
    QCOMPARE(pointLines.size(), std::size_t{3});
    QCOMPARE(pointLines[1]->at(10).y(), core.sequences[1].summary.cdf[10].points);
    page.setCdfOf(CdfOf::Frames);

    // Bars: one set per prediction, core's per-region means, then all points.
    QCOMPARE(page.regionChart()->series().size(), 1);
    auto* bars = qobject_cast<QBarSeries*>(page.regionChart()->series().first());
    QVERIFY(bars != nullptr);
    QCOMPARE(bars->count(), 2);
    for (int p = 0; p < 2; ++p) {
      const auto& s = core.sequences[static_cast<std::size_t>(p)].summary;
      auto* set = bars->barSets().at(p);
      QCOMPARE(set->count(), static_cast<int>(s.regions.size()) + 1);
      QCOMPARE(s.regions.size(), std::size_t{5});  // left eye, right eye, nose, mouth, jaw
      for (std::size_t k = 0; k < s.regions.size(); ++k) {
        QCOMPARE(set->at(static_cast<int>(k)), s.regions[k].mean);
        QVERIFY(s.regions[k].mean > 0.0);
      }
      QCOMPARE(set->at(set->count() - 1), s.meanPointError);
    }

    // Table: core's figures, printed as `clm3d eval` prints them.
    QTableWidget* table = page.summaryTable();
    QCOMPARE(table->rowCount(), 2);
    for (int p = 0; p < 2; ++p) {
      const auto& s = core.sequences[static_cast<std::size_t>(p)].summary;
      QCOMPARE(table->item(p, 0)->text(),
               QString::fromStdString(core.sequences[static_cast<std::size_t>(p)].label));
      QCOMPARE(table->item(p, 1)->text(), formatError(s.mean));
      QVERIFY2(
          test::contains(printed, ("error: mean " + table->item(p, 1)->text() + ", median " +
                                   table->item(p, 2)->text() + ", SD " + table->item(p, 3)->text())
                                      .toStdString()),
          printed.c_str());
      QVERIFY(test::contains(printed, ("convergence rate " + table->item(p, 5)->text() +
                                       ", points within 0.18: " + table->item(p, 4)->text())
                                          .toStdString()));
      QCOMPARE(table->item(p, 6)->text(), QString("%1/120").arg(s.scoredFrames));
    }

    // Welch's t-test under the table, with the CLI's p.
    QCOMPARE(core.comparison.kind, Comparison::Kind::Welch);
    const QString p = "p = " + formatP(core.comparison.welch.p);
    QVERIFY2(page.comparisonText().contains("Welch") && page.comparisonText().contains(p),
             qPrintable(page.comparisonText()));
    QVERIFY(test::contains(printed, p.toStdString()));
    QVERIFY(page.findChild<QLabel*>("comparisonLabel")->isVisible());
  }

  void exportsWritePngAndCsv() {
    Files files;
    EvaluatePage page;
    QVERIFY_EXCEPTION_THROWN(page.exportTableCsv(files.folder.path() / "none.csv"), Error);
    page.inputs().setGroundTruth(files.truth);
    page.inputs().addPrediction(files.close);
    page.inputs().addPrediction(files.far);
    QVERIFY(runPage(page));

    const auto cdf = files.folder.path() / "cdf.png";
    const auto regions = files.folder.path() / "regions.png";
    page.exportCdfPng(cdf);
    page.exportRegionPng(regions);
    for (const auto& file : {cdf, regions}) {
      QImage image(QString::fromStdString(file.string()));
      QVERIFY2(!image.isNull(), file.c_str());
      QVERIFY(image.width() >= 1200 && image.height() >= 800);
      QVERIFY(fs::file_size(file) > 20000);
      // Drawn: more than a handful of colours (axes, text, the series).
      std::set<QRgb> colours;
      for (int y = 0; y < image.height(); y += 4) {
        for (int x = 0; x < image.width(); x += 4) colours.insert(image.pixel(x, y));
      }
      QVERIFY2(colours.size() > 20, qPrintable(QString::number(colours.size())));
    }

    const auto csv = files.folder.path() / "summary.csv";
    page.exportTableCsv(csv);
    const auto text = readTextFile(csv);
    const auto core = coreReport(files.truth, {files.close, files.far});
    QVERIFY(text.rfind("prediction,file,mean,median,sd,within_threshold,convergence_rate,"
                       "scored_frames,normalised_frames,threshold,jitter,lag_frames,nmj\n",
                       0) == 0);
    QCOMPARE(std::count(text.begin(), text.end(), '\n'), 3L);
    const auto secondRow = text.substr(text.find("\nsingle-view,") + 1);
    const auto mean = std::stod(secondRow.substr(secondRow.find(".csv,") + 5));
    QCOMPARE(mean, core.sequences[1].summary.mean);
  }

  void threePredictionsShowAnova() {
    Files files;
    EvaluatePage page;
    page.inputs().setGroundTruth(files.truth);
    for (const auto& file : {files.close, files.far, files.worse})
      page.inputs().addPrediction(file);
    QVERIFY(runPage(page));
    const auto core = coreReport(files.truth, {files.close, files.far, files.worse});
    QCOMPARE(core.comparison.kind, Comparison::Kind::Anova);
    QCOMPARE(lineSeries(page.cdfChart()).size(), std::size_t{4});
    QCOMPARE(page.summaryTable()->rowCount(), 3);
    QVERIFY2(page.comparisonText().contains("ANOVA") &&
                 page.comparisonText().contains("p = " + formatP(core.comparison.anova.p)),
             qPrintable(page.comparisonText()));
  }

  void brokenFilesShowTheErrorDialogAndThePageStaysUsable() {
    Files files;
    const auto broken = files.folder.path() / "broken.csv";
    writeTextAtomically(broken, "frame,success,x_1,y_1\n0,1,abc,2\n");
    EvaluatePage page;
    page.inputs().setGroundTruth(files.truth);
    page.inputs().addPrediction(broken);

    QString message;
    QSignalSpy failed(&page, &EvaluatePage::evaluationFailed);
    test::expectErrorDialog(&message);
    QVERIFY(page.evaluate());
    QVERIFY(test::waitUntil([&] { return failed.count() == 1 && !message.isEmpty(); }, 15000));
    QVERIFY2(message.contains("broken.csv") && message.contains("is not a number"),
             qPrintable(message));
    QVERIFY(page.report() == nullptr);

    // Mismatched landmark counts: a 68-point prediction against the 25-point truth.
    const auto wide = files.folder.path() / "ibug.csv";
    TrackTable table;
    table.landmarkCount = 68;
    table.rows.resize(3);
    for (int f = 0; f < 3; ++f) {
      table.rows[static_cast<std::size_t>(f)].frame = f;
      table.rows[static_cast<std::size_t>(f)].points = Eigen::Matrix2Xd::Constant(2, 68, 100.0);
    }
    writeTrackTable(wide, table);
    page.inputs().addPrediction(broken, false);
    page.inputs().addPrediction(wide);
    message.clear();
    test::expectErrorDialog(&message);
    QVERIFY(page.evaluate());
    QVERIFY(test::waitUntil([&] { return failed.count() == 2 && !message.isEmpty(); }, 15000));
    QVERIFY2(message.contains("ibug.csv"), qPrintable(message));

    // Still usable: with good files it evaluates.
    page.inputs().addPrediction(wide, false);
    page.inputs().addPrediction(files.close);
    QVERIFY(runPage(page));
    QCOMPARE(page.summaryTable()->rowCount(), 1);
    QVERIFY(page.comparisonText().isEmpty());
  }

  void longVideoDoesNotStallTheGui() {
    Files files(6000);
    EvaluatePage page;
    page.show();
    page.inputs().setGroundTruth(files.truth);
    page.inputs().addPrediction(files.close);
    page.inputs().addPrediction(files.far);
    test::StallWatchdog watchdog;
    watchdog.start();
    QVERIFY(runPage(page));
    watchdog.stop();
    qInfo("6000 frames x 2 predictions: GUI thread %s", qPrintable(watchdog.summary()));
    QVERIFY2(watchdog.withinBudget(), qPrintable(watchdog.summary()));
  }

  void screenshot() {
    if (qEnvironmentVariableIsEmpty("CLM3D_SCREENSHOTS")) QSKIP("set CLM3D_SCREENSHOTS=1");
    Files files(300);
    EvaluatePage page;
    page.resize(1400, 900);
    page.show();
    page.inputs().setGroundTruth(files.truth);
    page.inputs().addPrediction(files.close);
    page.inputs().addPrediction(files.far);
    QVERIFY(runPage(page));
    QTest::qWait(300);
    const fs::path images = fs::path(CLM3D_SOURCE_DIR) / "docs/images";
    QVERIFY(page.grab().save(QString::fromStdString((images / "studio-evaluate.png").string())));
    page.exportCdfPng(images / "studio-evaluate-cdf.png");
  }
};

}  // namespace clm3d::ui

QTEST_MAIN(clm3d::ui::EvaluatePageTest)
#include "evaluate_page_test.moc"
