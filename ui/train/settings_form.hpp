// The training settings as a form: every field of TrainSettings (views, scales, patch size, PCA
// variances, perturbations, mirroring, seed, threads) with the CLI's ranges and a tooltip saying
// what it does, so a run from the studio can be made exactly like one from `clm3d train`.
#pragma once

#include <QWidget>

#include "core/train/train_settings.hpp"

class QCheckBox;
class QDoubleSpinBox;
class QLineEdit;
class QSpinBox;

namespace clm3d::ui {

class SettingsForm : public QWidget {
  Q_OBJECT
 public:
  explicit SettingsForm(QWidget* parent = nullptr);

  // The settings as entered; throws InputError naming the field when a view list does not parse
  // or the settings are out of range (TrainSettings::validate).
  TrainSettings settings() const;
  void setSettings(const TrainSettings& settings);

 private:
  QLineEdit* yaws_;
  QLineEdit* pitches_;
  QCheckBox* singleView_;
  QCheckBox* mirrorRightViews_;
  QSpinBox* scales_;
  QSpinBox* patchSize_;
  QDoubleSpinBox* patchRatio_;
  QSpinBox* samplesPerView_;
  QDoubleSpinBox* hiddenShare_;
  QSpinBox* supersample_;
  QDoubleSpinBox* textureVariance_;
  QSpinBox* textureMaxModes_;
  QDoubleSpinBox* shapeVariance_;
  QSpinBox* shapeMaxModes_;
  QDoubleSpinBox* shapeLimit_;
  QCheckBox* mirrorShapes_;
  QDoubleSpinBox* rotation_;
  QDoubleSpinBox* viewCoverage_;
  QDoubleSpinBox* scaleJitter_;
  QDoubleSpinBox* shift_;
  QDoubleSpinBox* light_;
  QDoubleSpinBox* ambient_;
  QDoubleSpinBox* diffuse_;
  QLineEdit* seed_;
  QSpinBox* threads_;
};

// "-60, -30, 0" -> {-60, -30, 0}; throws InputError "training settings: FIELD: ..." for an empty
// list or an entry that is not a number.
std::vector<double> parseAngleList(const QString& text, const std::string& field);
QString formatAngleList(const std::vector<double>& values);

}  // namespace clm3d::ui
