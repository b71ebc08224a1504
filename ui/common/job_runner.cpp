#include "ui/common/job_runner.hpp"

#include <QMetaObject>
#include <exception>
#include <string>

#include "core/common/error.hpp"

namespace clm3d::ui {

JobRunner::JobRunner(QObject* parent) : QObject(parent) {}

JobRunner::~JobRunner() {
  cancel();
  wait();
}

bool JobRunner::start(const QString& name, Job job) {
  if (isRunning()) return false;
  if (thread_ != nullptr) {
    thread_->wait();
    delete thread_;
  }
  token_ = std::make_shared<CancelToken>();
  {
    std::lock_guard lock(mutex_);
    lastFraction_ = 0.0;
    lastEmitMs_ = -1;
  }
  clock_.start();
  auto token = token_;
  thread_ = QThread::create([this, job = std::move(job), token] {
    enum class End { Finished, Cancelled, Failed } end = End::Finished;
    QString message;
    try {
      job([this](double fraction, std::string_view stage) { report(fraction, stage); }, *token);
    } catch (const Cancelled&) {
      end = End::Cancelled;
    } catch (const std::exception& e) {
      end = End::Failed;
      message = QString::fromStdString(e.what());
    } catch (...) {
      end = End::Failed;
      message = QStringLiteral("unknown error");
    }
    if (end == End::Finished && token->cancelled()) end = End::Cancelled;
    // Delivered on the GUI thread after the worker's last progress signal.
    QMetaObject::invokeMethod(
        this,
        [this, end, message] {
          if (end == End::Finished) {
            emit progressed(1.0, QString());
            emit finished();
          } else if (end == End::Cancelled) {
            emit cancelled();
          } else {
            emit failed(message);
          }
          emit ended();
        },
        Qt::QueuedConnection);
  });
  thread_->setObjectName(name);
  emit started(name);
  thread_->start();
  return true;
}

void JobRunner::cancel() {
  if (token_) token_->cancel();
}

bool JobRunner::isRunning() const {
  return thread_ != nullptr && thread_->isRunning();
}

bool JobRunner::wait(int milliseconds) {
  if (thread_ == nullptr) return true;
  return milliseconds < 0 ? thread_->wait()
                          : thread_->wait(static_cast<unsigned long>(milliseconds));
}

double JobRunner::elapsedSeconds() const {
  return clock_.isValid() ? clock_.elapsed() / 1000.0 : 0.0;
}

double JobRunner::remainingSeconds() const {
  std::lock_guard lock(mutex_);
  if (lastFraction_ < 0.01 || !clock_.isValid()) return -1.0;
  const double elapsed = clock_.elapsed() / 1000.0;
  return elapsed * (1.0 - lastFraction_) / lastFraction_;
}

void JobRunner::report(double fraction, std::string_view stage) {
  const qint64 now = clock_.elapsed();
  {
    std::lock_guard lock(mutex_);
    lastFraction_ = fraction;
    if (lastEmitMs_ >= 0 && now - lastEmitMs_ < 50 && fraction < 1.0) return;
    lastEmitMs_ = now;
  }
  const QString text = QString::fromUtf8(stage.data(), static_cast<int>(stage.size()));
  QMetaObject::invokeMethod(
      this, [this, fraction, text] { emit progressed(fraction, text); }, Qt::QueuedConnection);
}

}  // namespace clm3d::ui
