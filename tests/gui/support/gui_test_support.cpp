#include "tests/gui/support/gui_test_support.hpp"

#include <QAbstractButton>
#include <QApplication>
#include <QCoreApplication>
#include <QMessageBox>
#include <QTest>

namespace clm3d::test {

StallWatchdog::StallWatchdog(QObject* parent) : QObject(parent) {
  timer_.setInterval(5);
  timer_.setTimerType(Qt::PreciseTimer);
  connect(&timer_, &QTimer::timeout, this, [this] {
    const qint64 now = clock_.elapsed();
    if (lastMs_ >= 0) {
      const double stall = static_cast<double>(now - lastMs_) - timer_.interval();
      if (stall > longestMs_) longestMs_ = stall;
      if (stall >= kStallTargetMs) blocked_ += static_cast<int>(stall / kStallTargetMs);
    }
    lastMs_ = now;
    ++ticks_;
  });
}

void StallWatchdog::start() {
  longestMs_ = 0.0;
  ticks_ = 0;
  blocked_ = 0;
  lastMs_ = -1;
  clock_.start();
  timer_.start();
}

void StallWatchdog::stop() {
  timer_.stop();
}

QString StallWatchdog::summary() const {
  return QString("longest stall %1 ms, %2 blocked intervals of %3 ms (budget %4) over %5 ticks")
      .arg(longestMs_, 0, 'f', 1)
      .arg(blocked_)
      .arg(kStallTargetMs)
      .arg(kStallBudget)
      .arg(ticks_);
}

bool waitUntil(const std::function<bool()>& done, int timeoutMs) {
  QElapsedTimer clock;
  clock.start();
  while (!done() && clock.elapsed() < timeoutMs) {
    QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
    QTest::qWait(5);
  }
  return done();
}

void onNextMessageBox(const QString& objectName, std::function<void(QMessageBox*)> action,
                      int timeoutMs) {
  auto* poll = new QTimer(qApp);
  poll->setInterval(20);
  QObject::connect(poll, &QTimer::timeout, poll, [poll, objectName, action = std::move(action)] {
    for (QWidget* widget : QApplication::topLevelWidgets()) {
      auto* box = qobject_cast<QMessageBox*>(widget);
      if (box != nullptr && box->objectName() == objectName && box->isVisible()) {
        poll->stop();
        poll->deleteLater();
        action(box);
        return;
      }
    }
  });
  poll->start();
  QTimer::singleShot(timeoutMs, poll, [poll] {
    poll->stop();
    poll->deleteLater();
  });
}

void answerNextMessageBox(const QString& objectName, QMessageBox::StandardButton button, int* seen,
                          int timeoutMs) {
  onNextMessageBox(
      objectName,
      [button, seen](QMessageBox* box) {
        if (seen != nullptr) ++*seen;
        box->button(button)->click();
      },
      timeoutMs);
}

void expectErrorDialog(QString* message, int timeoutMs) {
  onNextMessageBox(
      "errorDialog",
      [message](QMessageBox* box) {
        if (message != nullptr) *message = box->informativeText();
        box->accept();
      },
      timeoutMs);
}

bool showForTest(QWidget& widget, QSize size, bool activate) {
  widget.resize(size);
  widget.show();
  if (!QTest::qWaitForWindowExposed(&widget)) return false;
  if (!activate) return true;
  widget.activateWindow();
  if (!QTest::qWaitForWindowActive(&widget)) return false;
  widget.setFocus();
  return true;
}

}  // namespace clm3d::test
