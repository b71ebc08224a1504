#include "ui/annotate/scan_view.hpp"

#include <vtkActor.h>
#include <vtkBillboardTextActor3D.h>
#include <vtkCamera.h>
#include <vtkCellPicker.h>
#include <vtkGenericCell.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>
#include <vtkStaticCellLocator.h>
#include <vtkTextProperty.h>
#include <vtkTexture.h>

#include <QTimer>
#include <cmath>
#include <limits>

#include "ui/annotate/annotation_document.hpp"

namespace clm3d::ui {

namespace {

constexpr double kSkin[3] = {0.85, 0.7, 0.6};
constexpr double kCurrentScale = 1.8;

void regionColour(const Scheme& scheme, int index, double rgb[3]) {
  const int region = scheme.regionOf(index);
  if (region < 0) {
    rgb[0] = rgb[1] = rgb[2] = 0.9;
    return;
  }
  const RgbColour& c = scheme.regions()[static_cast<std::size_t>(region)].colour;
  rgb[0] = c.r / 255.0;
  rgb[1] = c.g / 255.0;
  rgb[2] = c.b / 255.0;
}

}  // namespace

ScanView::ScanView(QWidget* parent)
    : QVTKOpenGLNativeWidget(parent),
      renderer_(vtkSmartPointer<vtkRenderer>::New()),
      picker_(vtkSmartPointer<vtkCellPicker>::New()),
      sphere_(vtkSmartPointer<vtkSphereSource>::New()) {
  auto window = vtkSmartPointer<vtkGenericOpenGLRenderWindow>::New();
  setRenderWindow(window);
  renderer_->SetBackground(0.16, 0.17, 0.2);
  renderer_->SetBackground2(0.32, 0.34, 0.4);
  renderer_->GradientBackgroundOn();
  renderer_->LightFollowCameraOn();
  window->AddRenderer(renderer_);
  sphere_->SetThetaResolution(16);
  sphere_->SetPhiResolution(12);
  picker_->PickFromListOn();
  picker_->SetTolerance(0.0005);

  ghostActor_ = vtkSmartPointer<vtkActor>::New();
  auto ghostMapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  ghostMapper->SetInputConnection(sphere_->GetOutputPort());
  ghostActor_->SetMapper(ghostMapper);
  ghostActor_->GetProperty()->SetColor(1.0, 1.0, 1.0);
  ghostActor_->GetProperty()->SetOpacity(0.55);
  ghostActor_->PickableOff();
  ghostActor_->VisibilityOff();
  renderer_->AddActor(ghostActor_);
}

ScanView::~ScanView() = default;

void ScanView::render() {
  renderer_->ResetCameraClippingRange();
  renderWindow()->Render();
  update();
}

void ScanView::scheduleRender() {
  if (renderScheduled_) return;
  renderScheduled_ = true;
  QTimer::singleShot(0, this, [this] {
    renderScheduled_ = false;
    render();
  });
}

void ScanView::setDocument(AnnotationDocument* document) {
  document_ = document;
  connect(document, &AnnotationDocument::pointsReset, this, [this] {
    rebuildMarkers();
    scheduleRender();
  });
  connect(document, &AnnotationDocument::pointChanged, this, [this](int index) {
    updateMarker(index);
    scheduleRender();
  });
  connect(document, &AnnotationDocument::currentChanged, this, [this] {
    for (int i = 0; i < static_cast<int>(markers_.size()); ++i) updateMarker(i);
    scheduleRender();
  });
  rebuildMarkers();
}

void ScanView::setScan(vtkSmartPointer<vtkPolyData> mesh, vtkSmartPointer<vtkImageData> texture,
                       const Eigen::Vector3d& up, const Eigen::Vector3d& front) {
  if (meshActor_) renderer_->RemoveActor(meshActor_);
  meshData_ = std::move(mesh);
  up_ = up;
  front_ = front;
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(meshData_);
  mapper->ScalarVisibilityOff();
  meshActor_ = vtkSmartPointer<vtkActor>::New();
  meshActor_->SetMapper(mapper);
  meshActor_->GetProperty()->SetColor(kSkin[0], kSkin[1], kSkin[2]);
  meshActor_->GetProperty()->SetSpecular(0.08);
  meshActor_->GetProperty()->SetSpecularPower(20);
  texture_ = nullptr;
  if (texture && texture->GetPointData()->GetScalars() != nullptr) {
    texture_ = vtkSmartPointer<vtkTexture>::New();
    texture_->SetInputData(texture);
    texture_->InterpolateOn();
    texture_->MipmapOn();
  }
  meshActor_->SetTexture(textureVisible_ ? texture_ : nullptr);
  renderer_->AddActor(meshActor_);

  locator_ = vtkSmartPointer<vtkStaticCellLocator>::New();
  locator_->SetDataSet(meshData_);
  locator_->BuildLocator();
  picker_->InitializePickList();
  picker_->AddPickList(meshActor_);
  picker_->RemoveAllLocators();
  picker_->AddLocator(locator_);

  rebuildMarkers();
  resetCamera();
}

void ScanView::resetCamera() {
  if (!meshData_) {
    render();
    return;
  }
  double bounds[6];
  meshData_->GetBounds(bounds);
  const Eigen::Vector3d centre(0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
                               0.5 * (bounds[4] + bounds[5]));
  vtkCamera* camera = renderer_->GetActiveCamera();
  camera->SetFocalPoint(centre.data());
  const Eigen::Vector3d eye = centre + front_.normalized() * 1000.0;
  camera->SetPosition(eye.data());
  camera->SetViewUp(up_.data());
  camera->SetViewAngle(30.0);
  renderer_->ResetCamera(bounds);
  camera->Zoom(1.35);
  render();
}

void ScanView::setTextureVisible(bool visible) {
  textureVisible_ = visible;
  if (meshActor_) meshActor_->SetTexture(visible ? texture_ : nullptr);
  scheduleRender();
}

void ScanView::setLabelsVisible(bool visible) {
  labelsVisible_ = visible;
  for (int i = 0; i < static_cast<int>(markers_.size()); ++i) updateMarker(i);
  scheduleRender();
}

void ScanView::setGhost(const std::optional<Eigen::Vector3d>& point) {
  ghost_ = point;
  if (point) {
    ghostActor_->SetPosition(point->x(), point->y(), point->z());
    ghostActor_->SetScale(markerRadius() * 1.4);
  }
  ghostActor_->SetVisibility(point.has_value());
  scheduleRender();
}

double ScanView::markerRadius() const {
  if (!meshData_) return 1.5;
  return std::clamp(0.005 * meshData_->GetLength(), 0.3, 10.0);
}

void ScanView::rebuildMarkers() {
  for (auto& marker : markers_) renderer_->RemoveActor(marker);
  for (auto& label : labels_) renderer_->RemoveActor(label);
  markers_.clear();
  labels_.clear();
  if (document_ == nullptr) return;
  const int n = document_->points().size();
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputConnection(sphere_->GetOutputPort());  // unit sphere, scaled per actor
  sphere_->SetRadius(1.0);
  for (int i = 0; i < n; ++i) {
    auto marker = vtkSmartPointer<vtkActor>::New();
    marker->SetMapper(mapper);
    marker->PickableOff();
    double rgb[3];
    regionColour(document_->scheme(), i, rgb);
    marker->GetProperty()->SetColor(rgb);
    marker->GetProperty()->SetAmbient(0.3);
    renderer_->AddActor(marker);
    markers_.push_back(marker);

    auto label = vtkSmartPointer<vtkBillboardTextActor3D>::New();
    label->SetInput(document_->scheme().id(i).c_str());
    label->GetTextProperty()->SetFontSize(13);
    label->GetTextProperty()->SetColor(1.0, 1.0, 1.0);
    label->GetTextProperty()->SetBackgroundColor(rgb);
    label->GetTextProperty()->SetBackgroundOpacity(0.75);
    label->SetDisplayOffset(8, 6);
    label->PickableOff();
    renderer_->AddActor(label);
    labels_.push_back(label);
    updateMarker(i);
  }
}

void ScanView::updateMarker(int index) {
  if (document_ == nullptr || index < 0 || index >= static_cast<int>(markers_.size())) return;
  const auto p = document_->point(index);
  const bool current = index == document_->current();
  vtkActor* marker = markers_[static_cast<std::size_t>(index)];
  vtkBillboardTextActor3D* label = labels_[static_cast<std::size_t>(index)];
  marker->SetVisibility(p.has_value());
  label->SetVisibility(p.has_value() && (labelsVisible_ || current));
  if (!p) return;
  marker->SetPosition(p->x(), p->y(), p->z());
  marker->SetScale(markerRadius() * (current ? kCurrentScale : 1.0));
  marker->GetProperty()->SetAmbient(current ? 0.7 : 0.3);
  label->SetPosition(p->x(), p->y(), p->z());
  label->GetTextProperty()->SetBold(current);
}

std::optional<Eigen::Vector3d> ScanView::pickSurface(const QPointF& widgetPos) {
  if (!meshActor_) return std::nullopt;
  const double ratio = devicePixelRatioF();
  const int* size = renderWindow()->GetSize();
  const double x = widgetPos.x() * ratio;
  const double y = size[1] - 1 - widgetPos.y() * ratio;
  if (picker_->Pick(x, y, 0.0, renderer_) == 0 || picker_->GetActor() != meshActor_) {
    return std::nullopt;
  }
  double p[3];
  picker_->GetPickPosition(p);
  return Eigen::Vector3d(p[0], p[1], p[2]);
}

QPointF ScanView::worldToWidget(const Eigen::Vector3d& p) const {
  renderer_->SetWorldPoint(p.x(), p.y(), p.z(), 1.0);
  renderer_->WorldToDisplay();
  double display[3];
  renderer_->GetDisplayPoint(display);
  const double ratio = devicePixelRatioF();
  const int* size = renderWindow()->GetSize();
  return {display[0] / ratio, (size[1] - 1 - display[1]) / ratio};
}

int ScanView::landmarkAt(const QPointF& widgetPos, double radius) const {
  if (document_ == nullptr) return -1;
  int best = -1;
  double bestDistance = radius;
  for (int i = 0; i < document_->points().size(); ++i) {
    const auto p = document_->point(i);
    if (!p) continue;
    const QPointF shown = worldToWidget(*p);
    const double distance = std::hypot(shown.x() - widgetPos.x(), shown.y() - widgetPos.y());
    if (distance <= bestDistance) {
      best = i;
      bestDistance = distance;
    }
  }
  return best;
}

Eigen::Vector3d ScanView::snapToSurface(const Eigen::Vector3d& p) const {
  if (!locator_) return p;
  double query[3] = {p.x(), p.y(), p.z()};
  double closest[3];
  vtkIdType cell = -1;
  int subId = 0;
  double distance2 = 0.0;
  auto scratch = vtkSmartPointer<vtkGenericCell>::New();
  locator_->FindClosestPoint(query, closest, scratch, cell, subId, distance2);
  if (cell < 0) return p;
  return {closest[0], closest[1], closest[2]};
}

}  // namespace clm3d::ui
