#include "ui/train/shape_mode_explorer.hpp"

#include <QVTKOpenGLNativeWidget.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>

#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSlider>
#include <QTimer>
#include <QVBoxLayout>
#include <cmath>

#include "ui/train/count_text.hpp"
#include "ui/train/shape_scene.hpp"

namespace clm3d::ui {

ShapeModeExplorer::ShapeModeExplorer(QWidget* parent)
    : QWidget(parent), scene_(std::make_unique<ShapeScene>()) {
  view_ = new QVTKOpenGLNativeWidget;
  view_->setObjectName("shapeView");
  view_->setMinimumSize(320, 320);
  vtkNew<vtkGenericOpenGLRenderWindow> window;
  view_->setRenderWindow(window);
  window->AddRenderer(scene_->renderer());
  vtkNew<vtkInteractorStyleTrackballCamera> turn;  // drag turns the shape, wheel zooms
  view_->interactor()->SetInteractorStyle(turn);

  summary_ = new QLabel;
  summary_->setWordWrap(true);
  reset_ = new QPushButton(tr("Reset"));
  reset_->setObjectName("shapeReset");
  reset_->setToolTip(tr("Set every shape parameter back to 0 (the mean shape)"));
  connect(reset_, &QPushButton::clicked, this, &ShapeModeExplorer::reset);

  auto* controls = new QWidget;
  sliderColumn_ = new QVBoxLayout(controls);
  sliderColumn_->setContentsMargins(0, 0, 0, 0);
  sliderColumn_->addWidget(summary_);
  sliderColumn_->addStretch(1);
  sliderColumn_->addWidget(reset_);
  controls->setMinimumWidth(230);

  auto* row = new QHBoxLayout(this);
  row->setContentsMargins(0, 0, 0, 0);
  row->addWidget(view_, 1);
  row->addWidget(controls);
  clear();
}

ShapeModeExplorer::~ShapeModeExplorer() = default;

void ShapeModeExplorer::clear() {
  for (QWidget* row : rows_) delete row;
  rows_.clear();
  sliders_.clear();
  values_.clear();
  shape_ = ShapeModel{};
  summary_->setText(tr("No model."));
  reset_->setEnabled(false);
}

void ShapeModeExplorer::setShapeModel(const ShapeModel& shape, const Scheme& scheme) {
  clear();
  shape_ = shape;
  const int count = std::min(kMaxSliders, shape.modeCount());
  const double total = shape.variances.sum();
  summary_->setText(tr("%1D shape model, %2; sliders set b_s in standard deviations (the "
                       "fitter allows +-%3 SD).")
                        .arg(shape.dims)
                        .arg(countText(shape.modeCount(), "mode", "modes"))
                        .arg(shape.limitSd));
  for (int k = 0; k < count; ++k) {
    auto* rowWidget = new QWidget;
    auto* layout = new QHBoxLayout(rowWidget);
    layout->setContentsMargins(0, 0, 0, 0);
    const double share = total > 0 ? shape.variances[k] / total : 0.0;
    auto* name = new QLabel(QString("b%1").arg(k + 1));
    name->setToolTip(tr("Mode %1: %2 % of the shape variance, SD %3 mm")
                         .arg(k + 1)
                         .arg(100 * share, 0, 'f', 1)
                         .arg(std::sqrt(shape.variances[k]), 0, 'f', 2));
    auto* slider = new QSlider(Qt::Horizontal);
    slider->setObjectName(QString("shapeMode%1").arg(k + 1));
    slider->setRange(-3 * kStepsPerSd, 3 * kStepsPerSd);
    slider->setSingleStep(10);
    slider->setPageStep(kStepsPerSd / 2);
    slider->setToolTip(name->toolTip());
    auto* value = new QLabel;
    value->setMinimumWidth(64);
    layout->addWidget(name);
    layout->addWidget(slider, 1);
    layout->addWidget(value);
    sliderColumn_->insertWidget(1 + k, rowWidget);
    rows_.push_back(rowWidget);
    sliders_.push_back(slider);
    values_.push_back(value);
    connect(slider, &QSlider::valueChanged, this, &ShapeModeExplorer::updateShape);
  }
  // Spheres of ~1/25 of the face width.
  const Eigen::Vector3d extent =
      shape.meanShape.rowwise().maxCoeff() - shape.meanShape.rowwise().minCoeff();
  const double radius = std::max(0.5, extent.maxCoeff() / 40.0);
  scene_->build(shape.meanShape, scheme, radius);
  cameraPending_ = true;
  reset_->setEnabled(count > 0);
  updateShape();
}

Eigen::VectorXd ShapeModeExplorer::parameters() const {
  Eigen::VectorXd b = Eigen::VectorXd::Zero(shape_.modeCount());
  for (std::size_t k = 0; k < sliders_.size(); ++k) {
    const auto mode = static_cast<Eigen::Index>(k);
    b[mode] =
        sliders_[k]->value() / static_cast<double>(kStepsPerSd) * std::sqrt(shape_.variances[mode]);
  }
  return b;
}

Eigen::Matrix3Xd ShapeModeExplorer::displayedPoints() const {
  return scene_->points();
}

void ShapeModeExplorer::reset() {
  cameraPending_ = true;
  for (QSlider* slider : sliders_) {
    const QSignalBlocker block(slider);
    slider->setValue(0);
  }
  updateShape();
}

void ShapeModeExplorer::updateShape() {
  if (shape_.pointCount() == 0) return;
  for (std::size_t k = 0; k < sliders_.size(); ++k) {
    values_[k]->setText(
        QString("%1 SD").arg(sliders_[k]->value() / static_cast<double>(kStepsPerSd), 0, 'f', 2));
  }
  scene_->update(shape_.shape(parameters()));
  render();
}

void ShapeModeExplorer::render() {
  if (!view_->isVisible() || view_->width() <= 0 || view_->height() <= 0) return;
  if (cameraPending_) {
    // The camera fits the shape to the view's aspect, which is only known once it is shown.
    const qreal ratio = view_->devicePixelRatioF();
    view_->renderWindow()->SetSize(static_cast<int>(view_->width() * ratio),
                                   static_cast<int>(view_->height() * ratio));
    scene_->resetCamera();
    cameraPending_ = false;
  }
  view_->renderWindow()->Render();
}

void ShapeModeExplorer::showEvent(QShowEvent* event) {
  QWidget::showEvent(event);
  QTimer::singleShot(0, this, &ShapeModeExplorer::render);
}

}  // namespace clm3d::ui
