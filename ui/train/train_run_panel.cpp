#include "ui/train/train_run_panel.hpp"

#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QTimer>
#include <QVBoxLayout>
#include <cmath>

#include "core/eval/calibrated_training.hpp"
#include "core/model/model_file.hpp"
#include "ui/common/error_dialog.hpp"
#include "ui/common/job_runner.hpp"
#include "ui/train/count_text.hpp"

namespace clm3d::ui {

QString formatSeconds(double seconds) {
  if (seconds < 60) return QString("%1 s").arg(seconds, 0, 'f', 1);
  const int whole = static_cast<int>(std::lround(seconds));
  return QString("%1 min %2 s").arg(whole / 60).arg(whole % 60, 2, 10, QChar('0'));
}

QString modelSummary(const ClmModel& model) {
  QStringList lines;
  lines << QObject::tr("%1, %2D shape model with %3, %4")
               .arg(model.singleView ? "single-view 2D baseline" : "multi-view 3D CLM")
               .arg(model.shape.dims)
               .arg(countText(model.shape.modeCount(), "mode", "modes"))
               .arg(countText(static_cast<long long>(model.views.size()), "view", "views"));
  for (const ViewModel& view : model.views) {
    QStringList modes;
    for (const PatchModel& scale : view.scales) modes << QString::number(scale.pca.modeCount());
    const auto landmarks = view.scales.empty() ? std::size_t{0} : view.scales[0].landmarks.size();
    lines << QObject::tr("  pitch %1 yaw %2: %3 landmarks, texture modes per scale %4%5")
                 .arg(view.pitchDeg, 0, 'g', 4)
                 .arg(view.yawDeg, 0, 'g', 4)
                 .arg(landmarks)
                 .arg(modes.join(' '))
                 .arg(view.mirrored ? QObject::tr(" (mirrored)") : QString());
  }
  return lines.join('\n');
}

TrainRunPanel::TrainRunPanel(QWidget* parent)
    : QWidget(parent), runner_(new JobRunner(this)), clock_(new QTimer(this)) {
  name_ = new QLineEdit;
  name_->setObjectName("modelName");
  name_->setToolTip(
      tr("File name of the model, saved as models/<name>.clm3d in the project; an "
         "existing model is never replaced."));
  train_ = new QPushButton(tr("Train"));
  train_->setObjectName("trainButton");
  train_->setToolTip(
      tr("Train a model from the manifest with these settings (runs in the "
         "background)"));
  cancel_ = new QPushButton(tr("Cancel"));
  cancel_->setObjectName("cancelButton");
  cancel_->setToolTip(tr("Stop the run; no model file is written"));
  cancel_->setEnabled(false);
  progress_ = new QProgressBar;
  progress_->setObjectName("trainProgress");
  progress_->setRange(0, 100);
  progress_->setValue(0);
  status_ = new QLabel(tr("Idle"));
  status_->setObjectName("trainStatus");
  log_ = new QPlainTextEdit;
  log_->setObjectName("trainLog");
  log_->setReadOnly(true);
  log_->setMaximumBlockCount(5000);

  auto* row = new QHBoxLayout;
  row->addWidget(new QLabel(tr("Model name")));
  row->addWidget(name_, 1);
  row->addWidget(train_);
  row->addWidget(cancel_);
  auto* column = new QVBoxLayout(this);
  column->setContentsMargins(0, 0, 0, 0);
  column->addLayout(row);
  column->addWidget(progress_);
  column->addWidget(status_);
  column->addWidget(log_, 1);

  clock_->setInterval(250);
  connect(clock_, &QTimer::timeout, this, &TrainRunPanel::refreshStatus);
  connect(train_, &QPushButton::clicked, this, &TrainRunPanel::trainClicked);
  connect(cancel_, &QPushButton::clicked, this, &TrainRunPanel::cancel);
  connect(runner_, &JobRunner::progressed, this, &TrainRunPanel::onProgress);
  connect(runner_, &JobRunner::finished, this, &TrainRunPanel::onFinished);
  connect(runner_, &JobRunner::cancelled, this, &TrainRunPanel::onCancelled);
  connect(runner_, &JobRunner::failed, this, &TrainRunPanel::onFailed);
  connect(runner_, &JobRunner::ended, this, [this] {
    busy_ = false;
    clock_->stop();
    cancel_->setEnabled(false);
    train_->setEnabled(trainAllowed_);
    name_->setEnabled(true);
    emit ended();
  });
}

QString TrainRunPanel::modelName() const {
  return name_->text();
}

void TrainRunPanel::setModelName(const QString& name) {
  name_->setText(name);
}

void TrainRunPanel::setTrainEnabled(bool enabled, const QString& whyNot) {
  trainAllowed_ = enabled;
  train_->setEnabled(enabled && !isRunning());
  train_->setToolTip(enabled ? tr("Train a model from the manifest with these settings (runs in "
                                  "the background)")
                             : whyNot);
}

bool TrainRunPanel::isRunning() const {
  return busy_;
}

QString TrainRunPanel::stamp() const {
  return QString("[%1] ").arg(formatSeconds(runner_->elapsedSeconds()));
}

void TrainRunPanel::appendLog(const QString& line) {
  log_->appendPlainText(line);
}

bool TrainRunPanel::start(const TrainJob& job) {
  if (isRunning()) return false;
  runner_->wait();  // a previous run has ended; its thread may still be returning
  job_ = job;
  stage_.clear();
  result_ = std::make_shared<std::shared_ptr<CalibratedTraining>>();
  saved_ = std::make_shared<std::atomic<bool>>(false);
  auto result = result_;
  auto saved = saved_;
  const bool started = runner_->start(
      "train", [job, result, saved](const ProgressCallback& progress, CancelToken& cancel) {
        auto trained = std::make_shared<CalibratedTraining>(
            trainAndCalibrate(job.manifest, job.settings, job.toolVersion, progress, &cancel));
        cancel.throwIfCancelled();
        progress(0.995, "saving");
        std::filesystem::create_directories(job.output.parent_path());
        saveModel(trained->model, job.output);
        saved->store(true);
        *result = std::move(trained);
      });
  if (!started) return false;
  busy_ = true;
  const TrainSettings& s = job.settings;
  appendLog(tr("Training %1 from %2: %3, %4, patch %5 px, %6 per subject and view")
                .arg(QString::fromStdString(job.output.filename().string()))
                .arg(QString::fromStdString(job.manifest.filename().string()))
                .arg(countText(static_cast<long long>(s.views().size()), "view", "views"))
                .arg(countText(s.scales, "scale", "scales"))
                .arg(s.patchSize)
                .arg(countText(s.samplesPerView, "sample", "samples")));
  progress_->setValue(0);
  status_->setText(tr("Starting"));
  train_->setEnabled(false);
  name_->setEnabled(false);
  cancel_->setEnabled(true);
  clock_->start();
  return true;
}

void TrainRunPanel::cancel() {
  if (!isRunning()) return;
  appendLog(stamp() + tr("cancelling..."));
  cancel_->setEnabled(false);
  runner_->cancel();
}

void TrainRunPanel::onProgress(double fraction, const QString& stage) {
  progress_->setValue(static_cast<int>(std::lround(fraction * 100)));
  if (!stage.isEmpty() && stage != stage_) {
    stage_ = stage;
    appendLog(stamp() + stage);
  }
  refreshStatus();
}

void TrainRunPanel::refreshStatus() {
  if (!isRunning()) return;
  QString text = tr("%1 - %2 elapsed")
                     .arg(stage_.isEmpty() ? tr("starting") : stage_,
                          formatSeconds(runner_->elapsedSeconds()));
  const double left = runner_->remainingSeconds();
  text += left >= 0 ? tr(", about %1 left").arg(formatSeconds(left)) : tr(", estimating time left");
  status_->setText(text);
}

void TrainRunPanel::onFinished() {
  const std::shared_ptr<CalibratedTraining> trained = *result_;
  // The model inside the result, shared with it (no copy of a model of tens of megabytes).
  if (trained) trained_ = std::shared_ptr<const ClmModel>(trained, &trained->model);
  const double seconds = runner_->elapsedSeconds();
  progress_->setValue(100);
  const QString file = QString::fromStdString(job_.output.string());
  double megabytes = 0;
  std::error_code ignored;
  const auto bytes = std::filesystem::file_size(job_.output, ignored);
  if (!ignored) megabytes = static_cast<double>(bytes) / 1e6;
  status_->setText(tr("Finished in %1").arg(formatSeconds(seconds)));
  appendLog(stamp() +
            tr("finished: model saved to %1 (%2 MB)").arg(file).arg(megabytes, 0, 'f', 2));
  if (trained && trained->calibration) {
    appendLog(tr("the point check calibrated on the photo pipeline's fits of %1")
                  .arg(QString::fromStdString(formatPhotoFitCalibration(
                      *trained->calibration, trained->calibrationSettings))));
  } else if (trained && !trained->calibrationSkipped.empty()) {
    appendLog(tr("calibration photos not used: %1")
                  .arg(QString::fromStdString(trained->calibrationSkipped)));
  }
  if (trained_) {
    appendLog(modelSummary(*trained_));
    emit modelSaved(file);
  }
}

void TrainRunPanel::onCancelled() {
  // A cancel that arrived after the file was written still means "no model": remove it.
  if (saved_ && saved_->load()) {
    std::error_code ignored;
    std::filesystem::remove(job_.output, ignored);
  }
  status_->setText(tr("Cancelled after %1").arg(formatSeconds(runner_->elapsedSeconds())));
  appendLog(stamp() + tr("cancelled; no model written"));
}

void TrainRunPanel::onFailed(const QString& message) {
  status_->setText(tr("Failed after %1").arg(formatSeconds(runner_->elapsedSeconds())));
  appendLog(stamp() + tr("failed: %1").arg(message));
  showError(this, tr("Training failed"), message);
}

}  // namespace clm3d::ui
