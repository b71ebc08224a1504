// The first run (issue 13, item 1): the project `clm3d demo` writes opens in the studio with its
// video tracked (the demo's track loaded on the Track page, not tracked again), compared with its
// exact ground truth, and its evaluation shown on the Evaluate page without pressing Evaluate.
// Runs the real `clm3d demo` at a small size.
#include <QApplication>
#include <QProcess>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTest>
#include <cmath>

#include "core/eval/landmark_error.hpp"
#include "core/project/project.hpp"
#include "tests/gui/project/isolated_settings.hpp"
#include "tests/gui/support/gui_test_main.hpp"
#include "tests/gui/support/gui_test_support.hpp"
#include "ui/common/job_runner.hpp"
#include "ui/evaluate/evaluate_page.hpp"
#include "ui/evaluate/evaluation_inputs.hpp"
#include "ui/shell/main_window.hpp"
#include "ui/track/track_page.hpp"

namespace clm3d::ui {

namespace fs = std::filesystem;

class DemoProjectTest : public QObject {
  Q_OBJECT
 private:
  template <typename P>
  static P* pageOf(MainWindow& window) {
    for (Page* page : window.pages()) {
      if (auto* found = qobject_cast<P*>(page)) return found;
    }
    return nullptr;
  }

 private slots:
  void theDemoProjectOpensTrackedWithItsEvaluation() {
    test::IsolatedSettings settings;
    test::TempDir temp;
    const fs::path out = temp.path() / "demo-out";
    QProcess demo;
    demo.setProcessChannelMode(QProcess::MergedChannels);
    demo.start(QString::fromStdString((test::binaryDir() / "bin" / "clm3d").string()),
               {"demo", "--heads", "2", "--samples", "1", "--size", "64", "--sequence-step", "15",
                "--out", QString::fromStdString(out.string())});
    QVERIFY(demo.waitForFinished(300000));
    QVERIFY2(demo.exitCode() == 0, demo.readAll().constData());
    Project written = loadProject(out);
    // As after `clm3d demo --real`: another video with its own track (a copy of the demo's), which
    // must not be scored against the test sequence's truth.
    const fs::path otherTrack = out / "tracks" / "franck-real.csv";
    fs::copy_file(written.tracks.at(0), otherTrack);
    written.videos.push_back(temp.path() / "videos" / "franck.mp4");
    written.tracks.push_back(otherTrack);
    saveProject(written);

    MainWindow window;
    QVERIFY(test::showForTest(window, {1280, 800}));
    auto* track = pageOf<TrackPage>(window);
    auto* evaluate = pageOf<EvaluatePage>(window);
    QVERIFY(track && evaluate);
    QSignalSpy tracking(track->jobRunner(), &JobRunner::started);
    QVERIFY(window.openProject(QString::fromStdString(out.string())));

    // Track page: the demo's video with the demo's track, compared with the exact truth.
    QCOMPARE(track->session().video().path, written.videos.at(0));
    QCOMPARE(track->tracksCsv(), written.tracks.at(0));
    QCOMPARE(track->comparedCsv(), written.groundTruth.at(0));
    const int frames = track->session().video().frameCount;
    QVERIFY(frames > 0);
    QCOMPARE(static_cast<int>(track->session().track().rows.size()), frames);
    int scored = 0;
    for (double e : track->session().errors()) scored += std::isfinite(e) ? 1 : 0;
    QVERIFY2(scored > frames / 2, qPrintable(QString("%1 of %2 scored").arg(scored).arg(frames)));
    QCOMPARE(tracking.count(), 0);
    QVERIFY(!window.hasUnsavedChanges());

    // Evaluate page: the evaluation runs by itself and is shown.
    QVERIFY(test::waitUntil([&] { return evaluate->report() != nullptr; }, 60000));
    QCOMPARE(evaluate->inputs().checkedPredictions().size(), std::size_t{1});
    QCOMPARE(evaluate->inputs().checkedPredictions()[0], written.tracks.at(0));
    QCOMPARE(evaluate->report()->sequences.size(), std::size_t{1});
    // The demo's track as the page scored it: mean error 0.0910, 85.9% of the points within 0.18
    // (measured; tests/cli/demo_cli_test.cpp bounds the same run's report.json alike).
    const ErrorSummary& quality = evaluate->report()->sequences[0].summary;
    QVERIFY2(quality.mean < 0.100, qPrintable(QString("mean error %1").arg(quality.mean)));
    QVERIFY2(quality.withinThreshold > 0.82,
             qPrintable(QString("within 0.18: %1").arg(quality.withinThreshold)));
    QVERIFY(evaluate->summaryTable()->rowCount() > 0);
  }
};

}  // namespace clm3d::ui

CLM3D_GUI_TEST_MAIN(clm3d::ui::DemoProjectTest)

#include "demo_project_test.moc"
