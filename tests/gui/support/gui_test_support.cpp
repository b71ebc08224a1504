#include "tests/gui/support/gui_test_support.hpp"

#include <QApplication>
#include <QCoreApplication>
#include <QMessageBox>
#include <QTest>
#include <random>

namespace clm3d::test {

StallWatchdog::StallWatchdog(QObject* parent) : QObject(parent) {
  timer_.setInterval(5);
  timer_.setTimerType(Qt::PreciseTimer);
  connect(&timer_, &QTimer::timeout, this, [this] {
    const qint64 now = clock_.elapsed();
    if (lastMs_ >= 0) {
      const double stall = static_cast<double>(now - lastMs_) - timer_.interval();
      if (stall > longestMs_) longestMs_ = stall;
    }
    lastMs_ = now;
    ++ticks_;
  });
}

void StallWatchdog::start() {
  longestMs_ = 0.0;
  ticks_ = 0;
  lastMs_ = -1;
  clock_.start();
  timer_.start();
}

void StallWatchdog::stop() {
  timer_.stop();
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

void expectErrorDialog(QString* message, int timeoutMs) {
  auto* poll = new QTimer(qApp);
  auto* clock = new QElapsedTimer();
  clock->start();
  poll->setInterval(20);
  QObject::connect(poll, &QTimer::timeout, poll, [poll, clock, message, timeoutMs] {
    for (QWidget* widget : QApplication::topLevelWidgets()) {
      auto* box = qobject_cast<QMessageBox*>(widget);
      if (box != nullptr && box->objectName() == "errorDialog" && box->isVisible()) {
        if (message != nullptr) *message = box->informativeText();
        box->accept();
        poll->stop();
        poll->deleteLater();
        delete clock;
        return;
      }
    }
    if (clock->elapsed() > timeoutMs) {
      poll->stop();
      poll->deleteLater();
      delete clock;
    }
  });
  poll->start();
}

std::filesystem::path fixturePath(const std::string& relative) {
  return std::filesystem::path(CLM3D_TEST_FIXTURES) / relative;
}

std::filesystem::path binaryDir() {
  return CLM3D_BINARY_DIR;
}

TempFolder::TempFolder() {
  std::random_device device;
  path_ = std::filesystem::temp_directory_path() /
          ("clm3d-gui-" + std::to_string(device()) + "-" + std::to_string(device()));
  std::filesystem::create_directories(path_);
}

TempFolder::~TempFolder() {
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
}

}  // namespace clm3d::test
