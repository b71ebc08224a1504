// OpenCV images to Qt and back, for showing frames, patches and renders in widgets: 8-bit grey,
// BGR and BGRA, and float grey scaled from [lo, hi]. The QImage owns a copy of the pixels.
#pragma once

#include <QImage>
#include <opencv2/core.hpp>

namespace clm3d::ui {

QImage toQImage(const cv::Mat& image);
QImage floatToQImage(const cv::Mat& image, double lo, double hi);
// A BGR 8-bit copy of a QImage.
cv::Mat toMat(const QImage& image);

}  // namespace clm3d::ui
