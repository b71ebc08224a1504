// The evaluate page's choice of what to compare: one ground truth (the project's ground-truth sets
// or any tracks CSV), one or more predictions (the project's tracks or any CSV, each with a check
// box) and the threshold of a found point / converged frame.
#pragma once

#include <QWidget>
#include <filesystem>
#include <vector>

class QComboBox;
class QDoubleSpinBox;
class QListWidget;
class QPushButton;

namespace clm3d {
struct Project;
}

namespace clm3d::ui {

class EvaluationInputs : public QWidget {
  Q_OBJECT
 public:
  explicit EvaluationInputs(QWidget* parent = nullptr);

  // Lists the project's ground-truth sets and tracks (all checked); nullptr empties the lists.
  void setProject(const Project* project);

  // Selects the file in the ground-truth list, adding it if it is not there.
  void setGroundTruth(const std::filesystem::path& file);
  // Adds a prediction (or just checks it when it is listed already).
  void addPrediction(const std::filesystem::path& file, bool checked = true);

  std::filesystem::path groundTruth() const;  // empty when none is chosen
  std::vector<std::filesystem::path> checkedPredictions() const;
  double threshold() const;
  void setThreshold(double threshold);
  bool isComplete() const { return !groundTruth().empty() && !checkedPredictions().empty(); }

 signals:
  void changed();

 private:
  void browseGroundTruth();
  void browsePredictions();
  void removeSelectedPrediction();

  QComboBox* truth_ = nullptr;
  QListWidget* predictions_ = nullptr;
  QPushButton* remove_ = nullptr;
  QDoubleSpinBox* threshold_ = nullptr;
};

}  // namespace clm3d::ui
