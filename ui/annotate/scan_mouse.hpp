// What the mouse does in the scan view, decided before VTK's camera interaction sees the event:
// a left click (press and release without moving) on the surface places the current landmark;
// a left click on a marker makes that landmark current; a left press on a marker starts dragging it
// along the surface (the surface point under the mouse at every move) until release; every other
// press, drag and wheel goes to VTK's trackball camera (left-drag rotates, right-drag or wheel
// zooms, middle-drag pans).
#pragma once

#include <Eigen/Core>
#include <QObject>
#include <QPointF>

namespace clm3d::ui {

class ScanView;

class ScanMouse : public QObject {
  Q_OBJECT
 public:
  // Watches view's mouse events (an event filter on it).
  explicit ScanMouse(ScanView* view);

  bool eventFilter(QObject* watched, QEvent* event) override;

 signals:
  void surfaceClicked(const Eigen::Vector3d& point);
  // serial numbers the drags, so the moves of one drag merge into one undo step.
  void landmarkDragged(int index, const Eigen::Vector3d& point, int serial);
  void dragFinished(int index);
  // A press and release on a marker without moving: that landmark becomes the current one.
  void markerClicked(int index);

 private:
  static constexpr double kClickSlopPixels = 4.0;
  static constexpr double kGrabRadiusPixels = 9.0;

  ScanView* view_;
  QPointF pressPos_;
  bool pressed_ = false;
  int dragging_ = -1;
  int dragSerial_ = 0;
  bool dragMoved_ = false;
};

}  // namespace clm3d::ui
