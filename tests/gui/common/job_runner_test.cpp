// JobRunner: progress reaches the GUI thread while the event loop keeps running, and a job ends
// as finished, cancelled or failed with its message.
#include "ui/common/job_runner.hpp"

#include <QSignalSpy>
#include <QTest>
#include <chrono>
#include <thread>

#include "core/common/error.hpp"
#include "tests/gui/support/gui_test_support.hpp"

namespace clm3d::ui {

class JobRunnerTest : public QObject {
  Q_OBJECT
 private slots:
  void progressReachesOneWithoutStallingTheEventLoop() {
    JobRunner runner;
    QSignalSpy progressed(&runner, &JobRunner::progressed);
    QSignalSpy finished(&runner, &JobRunner::finished);
    test::StallWatchdog watchdog;
    watchdog.start();
    QVERIFY(runner.start("busy", [](const ProgressCallback& progress, CancelToken& cancel) {
      for (int i = 1; i <= 40; ++i) {
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
        cancel.throwIfCancelled();
        progress(i / 40.0, "working");
      }
    }));
    QVERIFY(!runner.start("second", [](const ProgressCallback&, CancelToken&) {}));
    QVERIFY(test::waitUntil([&] { return finished.count() == 1; }, 10000));
    watchdog.stop();
    QVERIFY(progressed.count() >= 2);
    QCOMPARE(progressed.last().at(0).toDouble(), 1.0);
    QVERIFY(watchdog.ticks() > 20);
    qInfo("job runner: %s", qPrintable(watchdog.summary()));
    QVERIFY2(watchdog.withinBudget(), qPrintable(watchdog.summary()));
    QVERIFY(!runner.isRunning() || runner.wait(1000));
  }

  void cancelEndsTheJobAsCancelled() {
    JobRunner runner;
    QSignalSpy cancelled(&runner, &JobRunner::cancelled);
    QSignalSpy finished(&runner, &JobRunner::finished);
    runner.start("endless", [](const ProgressCallback&, CancelToken& cancel) {
      for (;;) {
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
        cancel.throwIfCancelled();
      }
    });
    QTest::qWait(30);
    runner.cancel();
    QVERIFY(test::waitUntil([&] { return cancelled.count() == 1; }, 5000));
    QCOMPARE(finished.count(), 0);
  }

  void anExceptionEndsTheJobAsFailedWithItsMessage() {
    JobRunner runner;
    QSignalSpy failed(&runner, &JobRunner::failed);
    QSignalSpy ended(&runner, &JobRunner::ended);
    runner.start("broken", [](const ProgressCallback&, CancelToken&) {
      throw InputError("model.clm3d: truncated");
    });
    QVERIFY(test::waitUntil([&] { return ended.count() == 1; }, 5000));
    QCOMPARE(failed.count(), 1);
    QCOMPARE(failed.first().at(0).toString(), QString("model.clm3d: truncated"));
  }
};

}  // namespace clm3d::ui

QTEST_MAIN(clm3d::ui::JobRunnerTest)
#include "job_runner_test.moc"
