// The Train page of clm3d-studio: the project's training sources (scans with their landmark
// completeness, procedural heads, ICT samples), the training settings, a background training run
// with progress, ETA, log and Cancel that saves the model into the project's models folder, and a
// view of any of the project's models (mean patches per view, shape-mode explorer).
#pragma once

#include <QDateTime>

#include "ui/common/page.hpp"

class QTabWidget;

namespace clm3d::ui {

class ModelView;
class SettingsForm;
class SourcesTable;
class TrainRunPanel;

class TrainPage : public Page {
  Q_OBJECT
 public:
  explicit TrainPage(QWidget* parent = nullptr);

  QString title() const override { return tr("Train"); }
  void setProject(Project* project) override;
  bool isBusy() const override;

  // Starts a run as the Train button does (after checking the settings and the model name);
  // returns whether a run started (an error dialog says why not).
  bool startTraining();

  SourcesTable* sources() const { return sources_; }
  SettingsForm* settingsForm() const { return settings_; }
  TrainRunPanel* runPanel() const { return run_; }
  ModelView* modelView() const { return models_; }
  QTabWidget* tabs() const { return tabs_; }

 private:
  void refreshProject();
  void onModelSaved(const QString& file);

  Project* project_ = nullptr;
  QTabWidget* tabs_;
  SourcesTable* sources_;
  SettingsForm* settings_;
  TrainRunPanel* run_;
  ModelView* models_;
};

}  // namespace clm3d::ui
