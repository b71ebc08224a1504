#include "ui/track/timeline_widget.hpp"

#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <algorithm>
#include <cmath>

namespace clm3d::ui {
namespace {

constexpr double kLegendHeight = 18.0;
constexpr double kMarkHeight = 10.0;

}  // namespace

TimelineWidget::TimelineWidget(QWidget* parent) : QWidget(parent) {
  setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
  setFixedHeight(110);
  setCursor(Qt::PointingHandCursor);
}

void TimelineWidget::setData(TimelineData timeline) {
  data_ = std::move(timeline);
  update();
}

void TimelineWidget::setCurrentFrame(int frame) {
  current_ = frame;
  update();
}

double TimelineWidget::errorScale() const {
  // At least 0.3 (eq 5.1 units, above the thesis's 0.18 "found" threshold), more if needed.
  double scale = 0.3;
  for (double e : data_.error) {
    if (std::isfinite(e)) scale = std::max(scale, e);
  }
  return scale;
}

QRectF TimelineWidget::plotRect() const {
  return QRectF(6, kMarkHeight + 2, width() - 12, height() - kMarkHeight - kLegendHeight - 4);
}

int TimelineWidget::frameAt(double x) const {
  if (data_.frameCount <= 0) return 0;
  const QRectF plot = plotRect();
  const int frame =
      static_cast<int>(std::floor((x - plot.left()) / plot.width() * data_.frameCount));
  return std::clamp(frame, 0, data_.frameCount - 1);
}

double TimelineWidget::xOf(int frame) const {
  const QRectF plot = plotRect();
  if (data_.frameCount <= 0) return plot.left();
  return plot.left() + (frame + 0.5) * plot.width() / data_.frameCount;
}

void TimelineWidget::paintEvent(QPaintEvent*) {
  QPainter painter(this);
  painter.fillRect(rect(), palette().window());
  const QRectF plot = plotRect();
  painter.fillRect(plot, QColor(245, 245, 245));
  painter.setPen(QColor(200, 200, 200));
  for (double level : {0.25, 0.5, 0.75}) {
    const double y = plot.bottom() - level * plot.height();
    painter.drawLine(QPointF(plot.left(), y), QPointF(plot.right(), y));
  }
  const int n = data_.frameCount;
  if (n > 0) {
    const double step = plot.width() / n;
    const double gap = step > 4 ? 1.0 : 0.0;
    for (int f = 0; f < n && f < static_cast<int>(data_.confidence.size()); ++f) {
      if (std::isnan(data_.confidence[static_cast<std::size_t>(f)])) continue;
      const double c = std::clamp(data_.confidence[static_cast<std::size_t>(f)], 0.0, 1.0);
      const bool ok =
          f < static_cast<int>(data_.success.size()) && data_.success[static_cast<std::size_t>(f)];
      const double h = ok ? c * plot.height() : plot.height();
      const QRectF bar(plot.left() + f * step, plot.bottom() - h, std::max(1.0, step - gap), h);
      painter.fillRect(bar, ok ? QColor(90, 170, 100) : QColor(220, 80, 70, 150));
    }
    const double errorMax = errorScale();
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setPen(QPen(QColor(230, 120, 20), 2));
    painter.setBrush(QColor(230, 120, 20));
    QPainterPath path;
    bool open = false;
    for (int f = 0; f < n && f < static_cast<int>(data_.error.size()); ++f) {
      const double e = data_.error[static_cast<std::size_t>(f)];
      if (!std::isfinite(e)) {
        open = false;
        continue;
      }
      const QPointF p(xOf(f), plot.bottom() - e / errorMax * plot.height());
      if (open) {
        path.lineTo(p);
      } else {
        path.moveTo(p);
        open = true;
      }
      painter.drawEllipse(p, 2.0, 2.0);
    }
    painter.setBrush(Qt::NoBrush);
    painter.drawPath(path);
    // Keyframes: gold triangles above the plot.
    painter.setPen(QPen(QColor(120, 90, 0), 1));
    painter.setBrush(QColor(245, 190, 30));
    for (int f = 0; f < n && f < static_cast<int>(data_.keyframe.size()); ++f) {
      if (!data_.keyframe[static_cast<std::size_t>(f)]) continue;
      const double x = xOf(f);
      const QPointF triangle[3] = {{x - 5, 1}, {x + 5, 1}, {x, kMarkHeight}};
      painter.drawPolygon(triangle, 3);
    }
    // Frames worth a look: magenta ticks in the same strip (keyframes are never listed).
    painter.setRenderHint(QPainter::Antialiasing, false);
    for (const int f : data_.review) {
      if (f < 0 || f >= n) continue;
      painter.fillRect(QRectF(xOf(f) - 1.5, 1, 3, kMarkHeight), QColor(200, 30, 170));
    }
    // Frames the adapted model changed (Adapt): green ticks along the bottom of the plot.
    for (const int f : data_.changed) {
      if (f < 0 || f >= n) continue;
      painter.fillRect(QRectF(xOf(f) - 1.5, plot.bottom() - kMarkHeight, 3, kMarkHeight),
                       QColor(30, 160, 60));
    }
    // Current frame.
    painter.setPen(QPen(QColor(30, 90, 220), 2));
    const double x = xOf(std::clamp(current_, 0, n - 1));
    painter.drawLine(QPointF(x, plot.top()), QPointF(x, plot.bottom()));
  }
  painter.setPen(QColor(150, 150, 150));
  painter.setBrush(Qt::NoBrush);
  painter.drawRect(plot);
  // Legend.
  painter.setPen(palette().windowText().color());
  const double y = height() - kLegendHeight + 13;
  const QString legend =
      tr("bars: confidence 0-1 (red = failed)    orange: error vs ground truth "
         "(top = %1)    gold: keyframes    magenta: worth a look (N)    green: changed by "
         "Adapt    blue: current frame")
          .arg(errorScale(), 0, 'f', 2);
  painter.drawText(QPointF(plot.left(), y), legend);
}

void TimelineWidget::mousePressEvent(QMouseEvent* event) {
  if (event->button() == Qt::LeftButton && data_.frameCount > 0)
    emit frameRequested(frameAt(event->localPos().x()));
}

void TimelineWidget::mouseMoveEvent(QMouseEvent* event) {
  if ((event->buttons() & Qt::LeftButton) && data_.frameCount > 0) {
    const int frame = frameAt(event->localPos().x());
    if (frame != current_) emit frameRequested(frame);
  }
}

}  // namespace clm3d::ui
