#include "ui/track/frame_view.hpp"

#include <QMouseEvent>
#include <QPainter>
#include <algorithm>
#include <cmath>
#include <limits>

namespace clm3d::ui {
namespace {

constexpr double kGrabRadius = 9.0;  // widget pixels around a landmark that start a drag
// A press within this many widget pixels of another face's landmarks (or inside their box) picks
// that face.
constexpr double kFaceRadius = 3.0 * kGrabRadius;

}  // namespace

FrameView::FrameView(QWidget* parent) : QWidget(parent) {
  setMinimumSize(320, 240);
  setMouseTracking(false);
  setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
}

void FrameView::setImage(const QImage& image) {
  image_ = image;
  update();
}

void FrameView::setLandmarks(const Eigen::Matrix2Xd& points, const std::vector<QColor>& colours,
                             const std::vector<LandmarkMark>& marks) {
  if (dragged_ >= 0) return;  // the drag in progress owns the points until release
  points_ = points;
  colours_ = colours;
  marks_ = marks;
  update();
}

void FrameView::setFaces(std::vector<FaceOverlay> others, const QString& selectedLabel,
                         const QColor& selectedColour) {
  others_ = std::move(others);
  selectedLabel_ = selectedLabel;
  selectedColour_ = selectedColour;
  update();
}

int FrameView::faceAt(const QPointF& widgetPoint) const {
  int best = -1;
  double bestDistance = kFaceRadius;
  for (const FaceOverlay& face : others_) {
    // Distance to the face: 0 inside the box of its points, else to its nearest point.
    constexpr double kInf = std::numeric_limits<double>::infinity();
    double distance = kInf;
    double left = kInf, top = kInf, right = -kInf, bottom = -kInf;
    for (Eigen::Index i = 0; i < face.points.cols(); ++i) {
      if (!face.points.col(i).allFinite()) continue;
      const QPointF p = toWidget({face.points(0, i), face.points(1, i)});
      left = std::min(left, p.x());
      right = std::max(right, p.x());
      top = std::min(top, p.y());
      bottom = std::max(bottom, p.y());
      distance = std::min(distance, std::hypot(p.x() - widgetPoint.x(), p.y() - widgetPoint.y()));
    }
    if (widgetPoint.x() >= left && widgetPoint.x() <= right && widgetPoint.y() >= top &&
        widgetPoint.y() <= bottom) {
      distance = 0.0;
    }
    if (distance <= bestDistance) {
      bestDistance = distance;
      best = face.face;
    }
  }
  return best;
}

void FrameView::drawFaceLabel(QPainter& painter, const Eigen::Matrix2Xd& points,
                              const QString& text, const QColor& colour) const {
  double left = 1e300;
  double top = 1e300;
  for (Eigen::Index i = 0; i < points.cols(); ++i) {
    if (!points.col(i).allFinite()) continue;
    const QPointF p = toWidget({points(0, i), points(1, i)});
    left = std::min(left, p.x());
    top = std::min(top, p.y());
  }
  if (left > 1e299) return;
  QFont font = painter.font();
  font.setBold(true);
  painter.setFont(font);
  const QRectF box = painter.boundingRect(QRectF(left, top - 22, 200, 20), Qt::AlignLeft, text);
  painter.fillRect(box.adjusted(-3, -1, 3, 1), QColor(0, 0, 0, 170));
  painter.setPen(colour);
  painter.drawText(box, Qt::AlignLeft, text);
}

double FrameView::landmarkRadius() const {
  return std::clamp(imageRect().width() / 160.0, 3.0, 6.0);
}

void FrameView::setLabel(const QString& text, bool keyframe) {
  label_ = text;
  keyframe_ = keyframe;
  update();
}

QRectF FrameView::imageRect() const {
  if (image_.isNull()) return {};
  const double scale = std::min(width() / static_cast<double>(image_.width()),
                                height() / static_cast<double>(image_.height()));
  const double w = image_.width() * scale;
  const double h = image_.height() * scale;
  return {(width() - w) / 2.0, (height() - h) / 2.0, w, h};
}

QPointF FrameView::toWidget(const QPointF& framePoint) const {
  const QRectF rect = imageRect();
  if (rect.isEmpty()) return framePoint;
  const double scale = rect.width() / image_.width();
  // Pixel centres are at integers (OpenCV): pixel i spans [i - 0.5, i + 0.5].
  return {rect.left() + (framePoint.x() + 0.5) * scale,
          rect.top() + (framePoint.y() + 0.5) * scale};
}

QPointF FrameView::toFrame(const QPointF& widgetPoint) const {
  const QRectF rect = imageRect();
  if (rect.isEmpty()) return widgetPoint;
  const double scale = rect.width() / image_.width();
  return {(widgetPoint.x() - rect.left()) / scale - 0.5,
          (widgetPoint.y() - rect.top()) / scale - 0.5};
}

int FrameView::landmarkAt(const QPointF& widgetPoint) const {
  int best = -1;
  double bestDistance = kGrabRadius;
  for (int i = 0; i < points_.cols(); ++i) {
    if (!points_.col(i).allFinite()) continue;
    const QPointF p = toWidget({points_(0, i), points_(1, i)});
    const double distance = std::hypot(p.x() - widgetPoint.x(), p.y() - widgetPoint.y());
    if (distance <= bestDistance) {
      bestDistance = distance;
      best = i;
    }
  }
  return best;
}

void FrameView::paintEvent(QPaintEvent*) {
  QPainter painter(this);
  painter.fillRect(rect(), QColor(32, 32, 36));
  if (image_.isNull()) {
    painter.setPen(QColor(200, 200, 200));
    painter.drawText(rect(), Qt::AlignCenter, tr("Open a video and a model, then Track."));
    return;
  }
  painter.setRenderHint(QPainter::SmoothPixmapTransform);
  painter.drawImage(imageRect(), image_);
  painter.setRenderHint(QPainter::Antialiasing);
  const double radius = landmarkRadius();
  for (const FaceOverlay& face : others_) {
    painter.setPen(QPen(Qt::black, 1.0));
    painter.setBrush(face.colour);
    for (Eigen::Index i = 0; i < face.points.cols(); ++i) {
      if (!face.points.col(i).allFinite()) continue;
      painter.drawEllipse(toWidget({face.points(0, i), face.points(1, i)}), radius * 0.8,
                          radius * 0.8);
    }
    drawFaceLabel(painter, face.points, tr("face %1").arg(face.face), face.colour);
  }
  if (!selectedLabel_.isEmpty()) drawFaceLabel(painter, points_, selectedLabel_, selectedColour_);
  for (int i = 0; i < points_.cols(); ++i) {
    if (!points_.col(i).allFinite()) continue;
    const QPointF p = toWidget({points_(0, i), points_(1, i)});
    const QColor colour =
        i < static_cast<int>(colours_.size()) ? colours_[static_cast<std::size_t>(i)] : Qt::green;
    const LandmarkMark mark =
        i < static_cast<int>(marks_.size()) ? marks_[static_cast<std::size_t>(i)] : LandmarkMark{};
    const double r = i == dragged_ ? radius * 1.6 : radius;
    if (mark.lowConfidence) {
      painter.setPen(QPen(QColor(230, 40, 40), 2.0));
      painter.setBrush(Qt::NoBrush);
      painter.drawEllipse(p, radius * kLowConfidenceRing, radius * kLowConfidenceRing);
    }
    if (mark.hidden) {
      // Hollow: the region colour as a ring on a dark outline, the frame showing through.
      painter.setBrush(Qt::NoBrush);
      painter.setPen(QPen(Qt::black, 3.5));
      painter.drawEllipse(p, r, r);
      painter.setPen(QPen(colour, 2.0));
      painter.drawEllipse(p, r, r);
    } else {
      painter.setPen(QPen(Qt::black, 1.5));
      painter.setBrush(colour);
      painter.drawEllipse(p, r, r);
    }
  }
  if (!label_.isEmpty()) {
    QFont font = painter.font();
    font.setBold(true);
    painter.setFont(font);
    const QRectF box = painter.boundingRect(QRectF(8, 8, width() - 16, 40), Qt::AlignLeft, label_);
    painter.fillRect(box.adjusted(-4, -2, 4, 2), QColor(0, 0, 0, 160));
    painter.setPen(keyframe_ ? QColor(255, 210, 60) : QColor(230, 230, 230));
    painter.drawText(box, Qt::AlignLeft, label_);
  }
}

void FrameView::mousePressEvent(QMouseEvent* event) {
  if (event->button() != Qt::LeftButton) return;
  const int own = landmarkAt(event->localPos());
  if (own < 0 && !others_.empty()) {
    if (const int face = faceAt(event->localPos()); face >= 0) {
      emit faceClicked(face);
      return;
    }
  }
  if (!editable_) return;
  dragged_ = own;
  if (dragged_ >= 0) {
    dragStart_ = {points_(0, dragged_), points_(1, dragged_)};
    setCursor(Qt::ClosedHandCursor);
    update();
  }
}

void FrameView::mouseMoveEvent(QMouseEvent* event) {
  if (dragged_ < 0) return;
  const QPointF p = toFrame(event->localPos());
  points_(0, dragged_) = p.x();
  points_(1, dragged_) = p.y();
  update();
}

void FrameView::mouseReleaseEvent(QMouseEvent* event) {
  if (dragged_ < 0 || event->button() != Qt::LeftButton) return;
  const int index = dragged_;
  const QPointF to = toFrame(event->localPos());
  points_(0, index) = to.x();
  points_(1, index) = to.y();
  dragged_ = -1;
  unsetCursor();
  update();
  if (to != dragStart_) emit landmarkMoved(index, dragStart_, to);
}

}  // namespace clm3d::ui
