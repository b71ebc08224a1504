// Helpers for the QTest GUI tests: a watchdog that measures the stalls of the GUI thread's event
// loop against the studio's target (no stall over 100 ms during training or tracking), waiting on a
// condition while events run, and closing the modal dialogs a test expects. Temporary folders,
// paths and files come from tests/support/test_files.hpp, as for the GoogleTest suites.
#pragma once

#include <QElapsedTimer>
#include <QMessageBox>
#include <QObject>
#include <QString>
#include <QTimer>
#include <QWidget>
#include <exception>
#include <filesystem>
#include <functional>
#include <thread>

#include "tests/support/test_files.hpp"

namespace clm3d::test {

// The studio's target: no stall of the GUI thread's event loop over 100 ms (docs/studio.md).
inline constexpr double kStallTargetMs = 100.0;
// How many blocked intervals a GUI test allows while it measures: a stall counts one interval per
// full kStallTargetMs it lasts (a 250 ms stall counts 2), summed over the measurement. Generous on
// purpose: the GUI tests run alone (RUN_SERIAL) but the machine is shared, and a preempted process
// misses a tick now and then; work that belongs on a worker thread (a training step or a video
// decode on the GUI thread) blocks the loop in every step and spends the budget at once, as does a
// single stall of half a second. The measured worst stall of each test is printed (qInfo) and
// listed per page in docs/testing.md.
inline constexpr int kStallBudget = 4;

// Ticks every 5 ms on the thread it lives on; each gap between ticks, minus the period, is how long
// the event loop could not run (a stall).
class StallWatchdog : public QObject {
  Q_OBJECT
 public:
  explicit StallWatchdog(QObject* parent = nullptr);
  void start();
  void stop();
  double longestStallMs() const { return longestMs_; }
  int ticks() const { return ticks_; }
  // Blocked intervals over the target: sum over stalls of floor(stall / kStallTargetMs).
  int blockedIntervals() const { return blocked_; }
  // Whether blockedIntervals() is within kStallBudget.
  bool withinBudget() const { return blocked_ <= kStallBudget; }
  // "longest stall X ms, N blocked intervals of 100 ms (budget B) over T ticks", for messages.
  QString summary() const;

 private:
  QTimer timer_;
  QElapsedTimer clock_;
  qint64 lastMs_ = -1;
  double longestMs_ = 0.0;
  int ticks_ = 0;
  int blocked_ = 0;
};

// Runs the event loop until done() is true or timeoutMs passes; returns done().
bool waitUntil(const std::function<bool()>& done, int timeoutMs);

// Arms a poll (every 20 ms, until timeoutMs) that calls action on the next visible message box
// whose object name is objectName: how tests answer the modal dialogs the pages open.
void onNextMessageBox(const QString& objectName, std::function<void(QMessageBox*)> action,
                      int timeoutMs = 10000);

// Presses `button` in the next visible message box named `objectName`; ++*seen when it does.
void answerNextMessageBox(const QString& objectName, QMessageBox::StandardButton button, int* seen,
                          int timeoutMs = 10000);

// Arms a check that closes the next modal error dialog (object name "errorDialog") and stores its
// informative text in *message. Call before the action that should fail.
void expectErrorDialog(QString* message, int timeoutMs = 10000);

// Resizes and shows `widget`, then waits until the window system exposes it; with `activate`, also
// makes it the active window with the keyboard focus (for tests that type shortcuts). False when
// that did not happen within QTest's default wait.
bool showForTest(QWidget& widget, QSize size, bool activate = false);

// Runs `work` on a worker thread and waits, rethrowing what it threw: training and rendering use
// the offscreen renderer, which must not run on the GUI thread.
template <typename Work>
void runOffGuiThread(Work&& work) {
  std::exception_ptr error;
  std::thread worker([&] {
    try {
      work();
    } catch (...) {
      error = std::current_exception();
    }
  });
  worker.join();
  if (error) std::rethrow_exception(error);
}

}  // namespace clm3d::test
