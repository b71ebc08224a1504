// The 3D view of the annotator: the textured scan lit by a headlight, the landmarks as small
// spheres in their region's colour (the current one larger, with optional id labels), and a ghost
// sphere for a suggested point. Also answers the geometric questions the mouse handling asks:
// which surface point is under a pixel, which landmark is near a pixel, the nearest surface point
// to a 3D point, and where a 3D point appears on screen (widget pixels).
#pragma once

#include <QVTKOpenGLNativeWidget.h>
#include <vtkActor.h>
#include <vtkBillboardTextActor3D.h>
#include <vtkCellPicker.h>
#include <vtkImageData.h>
#include <vtkPolyData.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkSphereSource.h>
#include <vtkStaticCellLocator.h>
#include <vtkTexture.h>

#include <Eigen/Core>
#include <QPointF>
#include <optional>
#include <vector>

namespace clm3d::ui {

class AnnotationDocument;

class ScanView : public QVTKOpenGLNativeWidget {
  Q_OBJECT
 public:
  explicit ScanView(QWidget* parent = nullptr);
  ~ScanView() override;

  // Shows the document's landmarks and follows its changes.
  void setDocument(AnnotationDocument* document);
  // A new scan (texture may be empty: then the surface is drawn in a skin colour). up and front
  // are the scan's up and out-of-the-face directions, for the frontal camera.
  void setScan(vtkSmartPointer<vtkPolyData> mesh, vtkSmartPointer<vtkImageData> texture,
               const Eigen::Vector3d& up, const Eigen::Vector3d& front);
  bool hasScan() const { return meshData_ != nullptr; }

  void resetCamera();
  void setTextureVisible(bool visible);
  bool textureVisible() const { return textureVisible_; }
  void setLabelsVisible(bool visible);
  bool labelsVisible() const { return labelsVisible_; }
  void setGhost(const std::optional<Eigen::Vector3d>& point);
  const std::optional<Eigen::Vector3d>& ghost() const { return ghost_; }

  // The scan's surface point under a widget position (logical pixels), if any.
  std::optional<Eigen::Vector3d> pickSurface(const QPointF& widgetPos);
  // The placed landmark whose marker is drawn nearest to widgetPos within radius pixels; -1 if
  // none.
  int landmarkAt(const QPointF& widgetPos, double radius) const;
  // The surface point nearest to p (p itself without a scan).
  Eigen::Vector3d snapToSurface(const Eigen::Vector3d& p) const;
  // Where p appears, in widget (logical) pixels.
  QPointF worldToWidget(const Eigen::Vector3d& p) const;
  vtkRenderer* renderer() const { return renderer_; }
  // Renders now; scheduleRender renders once when control returns to the event loop, so the
  // several changes of one edit (point, current landmark, ghost) cost one frame.
  void render();
  void scheduleRender();

 private:
  void rebuildMarkers();
  void updateMarker(int index);
  double markerRadius() const;

  vtkSmartPointer<vtkRenderer> renderer_;
  vtkSmartPointer<vtkPolyData> meshData_;
  vtkSmartPointer<vtkActor> meshActor_;
  vtkSmartPointer<vtkTexture> texture_;
  vtkSmartPointer<vtkCellPicker> picker_;
  vtkSmartPointer<vtkStaticCellLocator> locator_;
  vtkSmartPointer<vtkSphereSource> sphere_;
  std::vector<vtkSmartPointer<vtkActor>> markers_;
  std::vector<vtkSmartPointer<vtkBillboardTextActor3D>> labels_;
  vtkSmartPointer<vtkActor> ghostActor_;
  AnnotationDocument* document_ = nullptr;
  Eigen::Vector3d up_ = Eigen::Vector3d::UnitY();
  Eigen::Vector3d front_ = Eigen::Vector3d::UnitZ();
  std::optional<Eigen::Vector3d> ghost_;
  bool textureVisible_ = true;
  bool labelsVisible_ = false;  // the current landmark's label is always shown
  bool renderScheduled_ = false;
};

}  // namespace clm3d::ui
