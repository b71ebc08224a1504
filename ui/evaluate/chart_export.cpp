#include "ui/evaluate/chart_export.hpp"

#include <QBuffer>
#include <QByteArray>
#include <QGraphicsLayout>
#include <QGraphicsScene>
#include <QPainter>
#include <span>

#include "core/common/atomic_file.hpp"
#include "core/common/error.hpp"

namespace clm3d::ui {

QImage renderChart(QtCharts::QChart* chart, QSize size) {
  QGraphicsScene scene;  // owns the chart from here on
  scene.addItem(chart);
  const QRectF area(QPointF(0.0, 0.0), QSizeF(size));
  scene.setSceneRect(area);
  chart->setGeometry(area);
  if (chart->layout() != nullptr) chart->layout()->activate();

  QImage image(size, QImage::Format_ARGB32_Premultiplied);
  image.fill(Qt::white);
  QPainter painter(&image);
  painter.setRenderHint(QPainter::Antialiasing);
  painter.setRenderHint(QPainter::TextAntialiasing);
  scene.render(&painter, area, area);
  painter.end();
  return image;
}

void writePng(const std::filesystem::path& path, const QImage& image) {
  QByteArray bytes;
  QBuffer buffer(&bytes);
  buffer.open(QIODevice::WriteOnly);
  if (image.isNull() || !image.save(&buffer, "PNG")) {
    throwInputError(path, "could not encode the chart as PNG");
  }
  writeBytesAtomically(path, std::span<const unsigned char>(
                                 reinterpret_cast<const unsigned char*>(bytes.constData()),
                                 static_cast<std::size_t>(bytes.size())));
}

}  // namespace clm3d::ui
