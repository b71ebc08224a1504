#include "ui/evaluate/evaluation_inputs.hpp"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QListWidget>
#include <QPushButton>
#include <QVBoxLayout>

#include "core/project/project.hpp"
#include "core/project/project_layout.hpp"

namespace clm3d::ui {
namespace {

constexpr const char* kCsvFilter = "Tracks CSV (*.csv);;All files (*)";

QString pathText(const std::filesystem::path& file) {
  return QString::fromStdString(file.string());
}

std::filesystem::path pathOf(const QVariant& data) {
  return std::filesystem::path(data.toString().toStdString());
}

// The folder a file dialog opens in: the one of the current choice (else Qt's default).
QString startFolder(const std::filesystem::path& current) {
  return current.empty() ? QString() : pathText(current.parent_path());
}

}  // namespace

EvaluationInputs::EvaluationInputs(QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);

  auto* truthBox = new QGroupBox("Ground truth", this);
  auto* truthRow = new QHBoxLayout(truthBox);
  truth_ = new QComboBox(truthBox);
  truth_->setObjectName("groundTruthCombo");
  truth_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  truth_->setMinimumContentsLength(16);
  auto* browse = new QPushButton("Browse…", truthBox);
  browse->setObjectName("browseGroundTruthButton");
  truthRow->addWidget(truth_, 1);
  truthRow->addWidget(browse);
  layout->addWidget(truthBox);

  auto* predictionBox = new QGroupBox("Predictions (tracker outputs)", this);
  auto* predictionLayout = new QVBoxLayout(predictionBox);
  predictions_ = new QListWidget(predictionBox);
  predictions_->setObjectName("predictionList");
  predictions_->setToolTip("Checked files are compared with the ground truth");
  predictionLayout->addWidget(predictions_);
  auto* buttons = new QHBoxLayout();
  auto* add = new QPushButton("Add…", predictionBox);
  add->setObjectName("addPredictionButton");
  remove_ = new QPushButton("Remove", predictionBox);
  remove_->setObjectName("removePredictionButton");
  remove_->setEnabled(false);
  buttons->addWidget(add);
  buttons->addWidget(remove_);
  buttons->addStretch(1);
  predictionLayout->addLayout(buttons);
  layout->addWidget(predictionBox, 1);

  auto* form = new QFormLayout();
  threshold_ = new QDoubleSpinBox(this);
  threshold_->setObjectName("thresholdSpin");
  threshold_->setDecimals(3);
  threshold_->setRange(0.001, 2.0);
  threshold_->setSingleStep(0.01);
  threshold_->setValue(0.18);
  threshold_->setToolTip(
      "A point within this normalised error is found; a frame whose mean error is below it has "
      "converged (thesis figure 5.12: 0.18)");
  form->addRow("Threshold:", threshold_);
  layout->addLayout(form);

  connect(browse, &QPushButton::clicked, this, &EvaluationInputs::browseGroundTruth);
  connect(add, &QPushButton::clicked, this, &EvaluationInputs::browsePredictions);
  connect(remove_, &QPushButton::clicked, this, &EvaluationInputs::removeSelectedPrediction);
  connect(truth_, qOverload<int>(&QComboBox::currentIndexChanged), this,
          &EvaluationInputs::changed);
  connect(predictions_, &QListWidget::itemChanged, this, &EvaluationInputs::changed);
  connect(predictions_, &QListWidget::currentRowChanged, this,
          [this](int row) { remove_->setEnabled(row >= 0); });
  connect(threshold_, qOverload<double>(&QDoubleSpinBox::valueChanged), this,
          &EvaluationInputs::changed);
}

void EvaluationInputs::setProject(const Project* project) {
  {
    const QSignalBlocker blockTruth(truth_);
    const QSignalBlocker blockPredictions(predictions_);
    truth_->clear();
    predictions_->clear();
  }
  if (project != nullptr) {
    for (const auto& file : project->groundTruth) setGroundTruth(project->resolve(file));
    if (!project->groundTruth.empty()) truth_->setCurrentIndex(0);
    // Checked: the tracks of the video the ground truth is of (core/project/project_layout.hpp),
    // so another video's track (the demo's franck.mp4) is not scored against this truth.
    const std::filesystem::path truthVideo = project->groundTruth.empty()
                                                 ? std::filesystem::path()
                                                 : videoOf(*project, project->groundTruth.front());
    for (const auto& file : project->tracks) {
      const std::filesystem::path video = videoOf(*project, file);
      addPrediction(project->resolve(file),
                    truthVideo.empty() || video.empty() || video == truthVideo);
    }
  }
  emit changed();
}

void EvaluationInputs::setGroundTruth(const std::filesystem::path& file) {
  int index = truth_->findData(pathText(file));
  if (index < 0) {
    truth_->addItem(QString::fromStdString(file.filename().string()), pathText(file));
    index = truth_->count() - 1;
    truth_->setItemData(index, pathText(file), Qt::ToolTipRole);
  }
  truth_->setCurrentIndex(index);
}

void EvaluationInputs::addPrediction(const std::filesystem::path& file, bool checked) {
  const auto state = checked ? Qt::Checked : Qt::Unchecked;
  for (int row = 0; row < predictions_->count(); ++row) {
    auto* item = predictions_->item(row);
    if (pathOf(item->data(Qt::UserRole)) == file) {
      item->setCheckState(state);
      return;
    }
  }
  auto* item = new QListWidgetItem(QString::fromStdString(file.filename().string()));
  item->setData(Qt::UserRole, pathText(file));
  item->setToolTip(pathText(file));
  item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsUserCheckable);
  item->setCheckState(state);
  predictions_->addItem(item);  // set up before joining the list: no itemChanged
  emit changed();
}

std::filesystem::path EvaluationInputs::groundTruth() const {
  return truth_->currentIndex() < 0 ? std::filesystem::path() : pathOf(truth_->currentData());
}

std::vector<std::filesystem::path> EvaluationInputs::checkedPredictions() const {
  std::vector<std::filesystem::path> files;
  for (int row = 0; row < predictions_->count(); ++row) {
    const auto* item = predictions_->item(row);
    if (item->checkState() == Qt::Checked) files.push_back(pathOf(item->data(Qt::UserRole)));
  }
  return files;
}

double EvaluationInputs::threshold() const {
  return threshold_->value();
}

void EvaluationInputs::setThreshold(double threshold) {
  threshold_->setValue(threshold);
}

void EvaluationInputs::browseGroundTruth() {
  const QString file = QFileDialog::getOpenFileName(this, "Choose the ground truth",
                                                    startFolder(groundTruth()), kCsvFilter);
  if (!file.isEmpty()) setGroundTruth(file.toStdString());
}

void EvaluationInputs::browsePredictions() {
  const auto current = checkedPredictions();
  const QStringList files = QFileDialog::getOpenFileNames(
      this, "Add tracker outputs", startFolder(current.empty() ? groundTruth() : current.back()),
      kCsvFilter);
  for (const auto& file : files) addPrediction(file.toStdString(), true);
}

void EvaluationInputs::removeSelectedPrediction() {
  delete predictions_->takeItem(predictions_->currentRow());
  remove_->setEnabled(predictions_->currentRow() >= 0);
  emit changed();
}

}  // namespace clm3d::ui
