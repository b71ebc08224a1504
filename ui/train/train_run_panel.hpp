// The run part of the training page: the model name, Train and Cancel, a progress bar with the
// stage, elapsed time and ETA, and a log of stage changes and the result. It runs
// trainAndCalibrate (training, then the manifest's photo-fit calibration) and saves the model on
// a JobRunner worker thread (the offscreen renderer runs there, never on the GUI thread), so the
// window stays responsive; a cancelled run leaves no file.
#pragma once

#include <QString>
#include <QWidget>
#include <atomic>
#include <filesystem>
#include <memory>
#include <string>

#include "core/model/clm_model.hpp"
#include "core/train/train_settings.hpp"

namespace clm3d {
struct CalibratedTraining;  // core/eval/calibrated_training.hpp
}

class QLabel;
class QLineEdit;
class QPlainTextEdit;
class QProgressBar;
class QPushButton;
class QTimer;

namespace clm3d::ui {

class JobRunner;

struct TrainJob {
  std::filesystem::path manifest;  // absolute
  std::filesystem::path output;    // the .clm3d to write (must not exist yet)
  TrainSettings settings;
  std::string toolVersion;  // recorded in the model's provenance
};

class TrainRunPanel : public QWidget {
  Q_OBJECT
 public:
  explicit TrainRunPanel(QWidget* parent = nullptr);

  QString modelName() const;
  void setModelName(const QString& name);
  void setTrainEnabled(bool enabled, const QString& whyNot = {});

  // Starts the run; false if one is running already.
  bool start(const TrainJob& job);
  void cancel();
  bool isRunning() const;
  void appendLog(const QString& line);

  // The model of the last finished run (null before one).
  std::shared_ptr<const ClmModel> trainedModel() const { return trained_; }
  JobRunner* runner() const { return runner_; }
  QPushButton* trainButton() const { return train_; }
  QPushButton* cancelButton() const { return cancel_; }
  QProgressBar* progressBar() const { return progress_; }
  QPlainTextEdit* log() const { return log_; }

 signals:
  void trainClicked();
  // A run finished and its model was written to `file` (the model is trainedModel()).
  void modelSaved(const QString& file);
  // A run ended, whichever way.
  void ended();

 private:
  void onProgress(double fraction, const QString& stage);
  void onFinished();
  void onCancelled();
  void onFailed(const QString& message);
  void refreshStatus();
  QString stamp() const;

  JobRunner* runner_;
  QLineEdit* name_;
  QPushButton* train_;
  QPushButton* cancel_;
  QProgressBar* progress_;
  QLabel* status_;
  QPlainTextEdit* log_;
  QTimer* clock_;
  bool trainAllowed_ = false;
  bool busy_ = false;  // from start until the runner's ended signal

  TrainJob job_;
  QString stage_;
  std::shared_ptr<std::shared_ptr<CalibratedTraining>> result_;
  std::shared_ptr<std::atomic<bool>> saved_;
  std::shared_ptr<const ClmModel> trained_;
};

// "2 min 05 s", "12.3 s".
QString formatSeconds(double seconds);
// One line per view: "pitch +0 yaw -30: 21 landmarks, texture modes 3 2" and the shape modes.
QString modelSummary(const ClmModel& model);

}  // namespace clm3d::ui
