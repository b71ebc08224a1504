#include "ui/train/train_page.hpp"

#include <QCoreApplication>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QScrollArea>
#include <QSplitter>
#include <QTabWidget>
#include <QVBoxLayout>

#include "core/common/error.hpp"
#include "core/project/project.hpp"
#include "ui/common/error_dialog.hpp"
#include "ui/train/model_naming.hpp"
#include "ui/train/model_view.hpp"
#include "ui/train/settings_form.hpp"
#include "ui/train/sources_table.hpp"
#include "ui/train/train_run_panel.hpp"

namespace clm3d::ui {
namespace {

QWidget* inGroup(const QString& title, QWidget* content) {
  auto* group = new QGroupBox(title);
  auto* layout = new QVBoxLayout(group);
  layout->addWidget(content);
  return group;
}

std::string toolVersion() {
  const QString version = QCoreApplication::applicationVersion();
  return ("clm3d-studio " + (version.isEmpty() ? QStringLiteral("(unversioned)") : version))
      .toStdString();
}

}  // namespace

TrainPage::TrainPage(QWidget* parent) : Page(parent) {
  setObjectName("trainPage");
  sources_ = new SourcesTable;
  settings_ = new SettingsForm;
  run_ = new TrainRunPanel;
  models_ = new ModelView;

  auto* settingsScroll = new QScrollArea;
  settingsScroll->setWidget(settings_);
  settingsScroll->setWidgetResizable(true);
  settingsScroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  settingsScroll->setMinimumWidth(settings_->sizeHint().width() + 24);

  auto* left = new QSplitter(Qt::Vertical);
  left->setObjectName(QStringLiteral("trainSplitter"));  // remembered (studio_settings)
  left->addWidget(inGroup(tr("Training sources (dataset manifest)"), sources_));
  left->addWidget(inGroup(tr("Run"), run_));
  left->setStretchFactor(0, 2);
  left->setStretchFactor(1, 3);
  auto* trainingTab = new QWidget;
  auto* row = new QHBoxLayout(trainingTab);
  row->addWidget(left, 1);
  row->addWidget(inGroup(tr("Settings"), settingsScroll));

  tabs_ = new QTabWidget;
  tabs_->setObjectName("trainTabs");
  tabs_->addTab(trainingTab, tr("Training"));
  tabs_->addTab(models_, tr("Model"));
  auto* column = new QVBoxLayout(this);
  column->setContentsMargins(0, 0, 0, 0);
  column->addWidget(tabs_);

  connect(run_, &TrainRunPanel::trainClicked, this, &TrainPage::startTraining);
  connect(run_, &TrainRunPanel::modelSaved, this, &TrainPage::onModelSaved);
  connect(run_, &TrainRunPanel::ended, this, [this] {
    if (project_ != nullptr && !run_->isRunning()) {
      run_->setModelName(defaultModelName(project_->folder, QDateTime::currentDateTime()));
    }
  });
  setProject(nullptr);
}

void TrainPage::setProject(Project* project) {
  if (run_->isRunning() && project != project_) {
    // The run's model belongs to the project it started in, which is going away: stop it (a
    // cancelled run leaves no file) rather than add the model to another project.
    run_->appendLog(tr("The project was closed."));
    run_->cancel();
  }
  project_ = project;
  models_->clear();
  refreshProject();
  if (project_ != nullptr) {
    run_->setModelName(defaultModelName(project_->folder, QDateTime::currentDateTime()));
  }
}

void TrainPage::refreshProject() {
  if (project_ == nullptr) {
    sources_->setManifest({});
    models_->setModels({});
    run_->setTrainEnabled(false, tr("Open a project first"));
    return;
  }
  const bool usable = sources_->setManifest(project_->manifest);
  models_->setModels(project_->models);
  run_->setTrainEnabled(usable, tr("The project's dataset manifest is missing or broken (see the "
                                   "sources table)"));
}

bool TrainPage::isBusy() const {
  return run_->isRunning();
}

bool TrainPage::startTraining() {
  if (run_->isRunning()) return false;
  if (project_ == nullptr) return false;
  TrainJob job;
  const bool ready = runReportingErrors(this, tr("Cannot start training"), [&] {
    if (project_->manifest.empty()) {
      throw InputError(project_->file().string() + ": the project has no dataset manifest");
    }
    job.manifest = project_->resolve(project_->manifest);
    job.settings = settings_->settings();
    job.output = modelPathFor(project_->folder, run_->modelName());
    if (std::filesystem::exists(job.output)) {
      throw InputError(job.output.string() +
                       ": a model with this name exists already; choose another name (models "
                       "are never replaced)");
    }
    job.toolVersion = toolVersion();
  });
  if (!ready) return false;
  emit statusMessage(tr("Training %1...").arg(run_->modelName()));
  return run_->start(job);
}

void TrainPage::onModelSaved(const QString& file) {
  const std::filesystem::path path = file.toStdString();
  if (project_ != nullptr) {
    project_->addUnique(project_->models, path);
    models_->setModels(project_->models);
    emit projectModified();
  }
  if (auto model = run_->trainedModel()) models_->showModel(model, path);
  emit statusMessage(tr("Model saved: %1").arg(file));
}

}  // namespace clm3d::ui
