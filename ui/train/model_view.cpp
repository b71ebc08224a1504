#include "ui/train/model_view.hpp"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QScrollBar>
#include <QSplitter>
#include <QVBoxLayout>

#include "core/model/model_file.hpp"
#include "ui/common/error_dialog.hpp"
#include "ui/common/job_runner.hpp"
#include "ui/train/mean_patch_grid.hpp"
#include "ui/train/shape_mode_explorer.hpp"
#include "ui/train/train_run_panel.hpp"

namespace clm3d::ui {

ModelView::ModelView(QWidget* parent) : QWidget(parent), loader_(new JobRunner(this)) {
  choice_ = new QComboBox;
  choice_->setObjectName("modelChoice");
  choice_->setToolTip(tr("A model of the project to look at"));
  choice_->setSizeAdjustPolicy(QComboBox::AdjustToContents);
  summary_ = new QLabel;
  summary_->setObjectName("modelSummary");
  summary_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  patches_ = new MeanPatchGrid;
  shapes_ = new ShapeModeExplorer;

  auto* top = new QHBoxLayout;
  top->addWidget(new QLabel(tr("Model")));
  top->addWidget(choice_);
  top->addWidget(summary_, 1);

  auto* patchBox = new QWidget;
  auto* patchColumn = new QVBoxLayout(patchBox);
  patchColumn->setContentsMargins(0, 0, 0, 0);
  patchColumn->addWidget(
      new QLabel(tr("<b>Mean patches</b> (finest scale; rows: views, "
                    "columns: landmarks)")));
  patchColumn->addWidget(patches_, 1);
  auto* shapeBox = new QWidget;
  auto* shapeColumn = new QVBoxLayout(shapeBox);
  shapeColumn->setContentsMargins(0, 0, 0, 0);
  shapeColumn->addWidget(
      new QLabel(tr("<b>Shape modes</b> (mean shape; drag a slider to add "
                    "a mode, in standard deviations)")));
  shapeColumn->addWidget(shapes_, 1);
  split_ = new QSplitter(Qt::Vertical);
  split_->setObjectName(QStringLiteral("modelViewSplitter"));  // remembered (studio_settings)
  split_->addWidget(patchBox);
  split_->addWidget(shapeBox);
  split_->setStretchFactor(0, 0);  // a larger page gives the room to the shape view
  split_->setStretchFactor(1, 1);

  auto* column = new QVBoxLayout(this);
  column->addLayout(top);
  column->addWidget(split_, 1);

  connect(choice_, qOverload<int>(&QComboBox::activated), this, [this](int index) {
    const QString file = choice_->itemData(index).toString();
    if (!file.isEmpty()) openModel(file.toStdString());
  });
  connect(loader_, &JobRunner::failed, this, [this](const QString& message) {
    summary_->setText(tr("Could not open the model."));
    showError(this, tr("Cannot open the model"), message);
  });
  connect(loader_, &JobRunner::finished, this, [this] {
    if (*loading_) showModel(*loading_, loadingFile_);
  });
  connect(loader_, &JobRunner::ended, this, [this] {
    loadBusy_ = false;
    if (!pending_.empty()) startLoading();
  });
  clear();
}

void ModelView::clear() {
  // A read still running delivers into the old slot and shows nothing.
  pending_.clear();
  loading_ = std::make_shared<std::shared_ptr<ClmModel>>();
  model_.reset();
  file_.clear();
  patches_->clear();
  shapes_->clear();
  summary_->setText(tr("Train a model, or choose one of the project's models."));
}

void ModelView::setModels(const std::vector<std::filesystem::path>& models) {
  const QSignalBlocker block(choice_);
  choice_->clear();
  choice_->addItem(tr("(choose a model)"), QString());
  for (const auto& file : models) {
    choice_->addItem(QString::fromStdString(file.filename().string()),
                     QString::fromStdString(file.string()));
    choice_->setItemData(choice_->count() - 1, QString::fromStdString(file.string()),
                         Qt::ToolTipRole);
  }
  selectFile(file_);
}

void ModelView::selectFile(const std::filesystem::path& file) {
  const QSignalBlocker block(choice_);
  const int index = file.empty() ? -1 : choice_->findData(QString::fromStdString(file.string()));
  choice_->setCurrentIndex(index < 0 ? 0 : index);
}

void ModelView::showModel(std::shared_ptr<const ClmModel> model,
                          const std::filesystem::path& file) {
  const bool shown = runReportingErrors(this, tr("Cannot show the model"), [&] {
    const Scheme scheme = model->scheme();
    patches_->setModel(*model);
    shapes_->setShapeModel(model->shape, scheme);
  });
  if (!shown) {
    clear();
    return;
  }
  model_ = std::move(model);
  file_ = file;
  // The whole grid if it fits in 60 % of the height, the rest for the shape explorer.
  const int total = split_->height();
  const int wanted = patches_->widget()->sizeHint().height() + 2 * patches_->frameWidth() +
                     patches_->horizontalScrollBar()->sizeHint().height() + 30;
  const int top = std::min(wanted, total * 3 / 5);
  split_->setSizes({top, std::max(0, total - top)});
  summary_->setText(QString::fromStdString(file.filename().string()) + ": " +
                    modelSummary(*model_).section('\n', 0, 0));
  summary_->setToolTip(modelSummary(*model_));
  selectFile(file);
  emit modelShown(QString::fromStdString(file.string()));
}

void ModelView::openModel(const std::filesystem::path& file) {
  pending_ = file;
  if (!loadBusy_) startLoading();
}

void ModelView::startLoading() {
  const std::filesystem::path file = pending_;
  pending_.clear();
  summary_->setText(tr("Reading %1...").arg(QString::fromStdString(file.filename().string())));
  loading_ = std::make_shared<std::shared_ptr<ClmModel>>();
  loadingFile_ = file;
  loadBusy_ = true;
  // The previous load has ended (its thread is returning): wait for it so start() accepts.
  loader_->wait();
  auto slot = loading_;
  loader_->start("load model", [slot, file](const ProgressCallback&, CancelToken&) {
    *slot = std::make_shared<ClmModel>(loadModel(file));
  });
}

}  // namespace clm3d::ui
