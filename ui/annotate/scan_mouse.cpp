#include "ui/annotate/scan_mouse.hpp"

#include <QMouseEvent>
#include <cmath>

#include "ui/annotate/scan_view.hpp"

namespace clm3d::ui {

ScanMouse::ScanMouse(ScanView* view) : QObject(view), view_(view) {
  view->installEventFilter(this);
}

bool ScanMouse::eventFilter(QObject* watched, QEvent* event) {
  if (watched != view_) return false;
  switch (event->type()) {
    case QEvent::KeyPress:
    case QEvent::KeyRelease:
      // VTK's default keys (wireframe, stereo, exit...) would fight the page's shortcuts.
      return true;
    case QEvent::MouseButtonPress: {
      auto* mouse = static_cast<QMouseEvent*>(event);
      if (mouse->button() != Qt::LeftButton) return false;
      pressPos_ = mouse->localPos();
      pressed_ = true;
      dragging_ = view_->landmarkAt(pressPos_, kGrabRadiusPixels);
      if (dragging_ >= 0) {
        ++dragSerial_;
        dragMoved_ = false;
        return true;  // the camera stays still while a landmark moves
      }
      return false;
    }
    case QEvent::MouseMove: {
      if (dragging_ < 0) return false;
      auto* mouse = static_cast<QMouseEvent*>(event);
      if (const auto point = view_->pickSurface(mouse->localPos())) {
        dragMoved_ = true;
        emit landmarkDragged(dragging_, *point, dragSerial_);
      }
      return true;
    }
    case QEvent::MouseButtonRelease: {
      auto* mouse = static_cast<QMouseEvent*>(event);
      if (mouse->button() != Qt::LeftButton || !pressed_) return false;
      pressed_ = false;
      const QPointF moved = mouse->localPos() - pressPos_;
      if (dragging_ >= 0) {
        const int index = dragging_;
        dragging_ = -1;
        if (dragMoved_) {
          emit dragFinished(index);
        } else {
          emit markerClicked(index);
        }
        return true;
      }
      if (std::hypot(moved.x(), moved.y()) <= kClickSlopPixels) {
        if (const auto point = view_->pickSurface(mouse->localPos())) emit surfaceClicked(*point);
      }
      return false;  // VTK ends its (empty) rotation
    }
    default:
      return false;
  }
}

}  // namespace clm3d::ui
