#include "ui/common/mat_image.hpp"

#include <opencv2/imgproc.hpp>

#include "core/common/error.hpp"

namespace clm3d::ui {

QImage toQImage(const cv::Mat& image) {
  if (image.empty()) return {};
  cv::Mat rgba;
  switch (image.type()) {
    case CV_8UC1:
      cv::cvtColor(image, rgba, cv::COLOR_GRAY2RGBA);
      break;
    case CV_8UC3:
      cv::cvtColor(image, rgba, cv::COLOR_BGR2RGBA);
      break;
    case CV_8UC4:
      cv::cvtColor(image, rgba, cv::COLOR_BGRA2RGBA);
      break;
    default:
      throw InputError("toQImage: unsupported image type " + std::to_string(image.type()));
  }
  return QImage(rgba.data, rgba.cols, rgba.rows, static_cast<int>(rgba.step),
                QImage::Format_RGBA8888)
      .copy();
}

QImage floatToQImage(const cv::Mat& image, double lo, double hi) {
  cv::Mat grey;
  const double range = hi > lo ? hi - lo : 1.0;
  image.convertTo(grey, CV_8U, 255.0 / range, -lo * 255.0 / range);
  return toQImage(grey);
}

cv::Mat toMat(const QImage& image) {
  const QImage rgb = image.convertToFormat(QImage::Format_RGB888);
  const cv::Mat view(rgb.height(), rgb.width(), CV_8UC3, const_cast<uchar*>(rgb.constBits()),
                     static_cast<std::size_t>(rgb.bytesPerLine()));
  cv::Mat bgr;
  cv::cvtColor(view, bgr, cv::COLOR_RGB2BGR);
  return bgr;
}

}  // namespace clm3d::ui
