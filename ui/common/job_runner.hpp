// Runs one long core operation (training, tracking, evaluating) on a worker QThread, so the GUI
// stays responsive: the job gets a ProgressCallback and a CancelToken like every long core call,
// progress reaches the GUI thread as queued signals (at most every 50 ms, so a fast job cannot
// flood the event loop), and the end is one of finished / cancelled / failed. One job at a time.
#pragma once

#include <QElapsedTimer>
#include <QObject>
#include <QString>
#include <QThread>
#include <functional>
#include <memory>
#include <mutex>

#include "core/common/progress.hpp"

namespace clm3d::ui {

class JobRunner : public QObject {
  Q_OBJECT
 public:
  // Runs on the worker thread. Throwing Cancelled (CancelToken::throwIfCancelled) ends the job as
  // cancelled, any other exception as failed with its message.
  using Job = std::function<void(const ProgressCallback& progress, CancelToken& cancel)>;

  explicit JobRunner(QObject* parent = nullptr);
  ~JobRunner() override;  // cancels a running job and waits for it

  // Starts the job; returns false (and does nothing) while another runs.
  bool start(const QString& name, Job job);
  void cancel();
  bool isRunning() const;
  // Blocks until the job has ended (for tests and shutdown); false on timeout.
  bool wait(int milliseconds = -1);
  // Seconds since start, and the remaining time extrapolated from the progress so far (negative
  // while unknown).
  double elapsedSeconds() const;
  double remainingSeconds() const;

 signals:
  void started(const QString& name);
  void progressed(double fraction, const QString& stage);
  void finished();
  void cancelled();
  void failed(const QString& message);
  void ended();  // after any of finished, cancelled, failed

 private:
  void report(double fraction, std::string_view stage);

  QThread* thread_ = nullptr;
  std::shared_ptr<CancelToken> token_;
  QElapsedTimer clock_;
  mutable std::mutex mutex_;
  double lastFraction_ = 0.0;
  qint64 lastEmitMs_ = -1;
};

}  // namespace clm3d::ui
