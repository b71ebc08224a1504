#include "core/viz/contact_sheet.hpp"

#include <algorithm>
#include <opencv2/imgproc.hpp>

#include "core/common/error.hpp"

namespace clm3d {

cv::Mat flattenAlpha(const cv::Mat& image, const cv::Scalar& background) {
  if (image.channels() != 4) return image;
  cv::Mat result(image.size(), CV_8UC3);
  for (int y = 0; y < image.rows; ++y) {
    const auto* src = image.ptr<cv::Vec4b>(y);
    auto* dst = result.ptr<cv::Vec3b>(y);
    for (int x = 0; x < image.cols; ++x) {
      const double a = src[x][3] / 255.0;
      for (int c = 0; c < 3; ++c) {
        dst[x][c] = cv::saturate_cast<uchar>(a * src[x][c] + (1.0 - a) * background[c]);
      }
    }
  }
  return result;
}

cv::Mat makeContactSheet(const std::vector<cv::Mat>& tiles, int columns,
                         const std::vector<std::string>& captions, const cv::Scalar& background) {
  if (tiles.empty()) throw Error("contact sheet: no images");
  if (columns <= 0) throw Error("contact sheet: columns must be positive");
  if (!captions.empty() && captions.size() != tiles.size()) {
    throw Error("contact sheet: one caption per image expected");
  }
  const cv::Size tile = tiles.front().size();
  const int captionHeight = captions.empty() ? 0 : std::max(14, tile.height / 12);
  const int rows = (static_cast<int>(tiles.size()) + columns - 1) / columns;
  const int cellHeight = tile.height + captionHeight;
  cv::Mat sheet(rows * cellHeight, columns * tile.width, CV_8UC3, background);
  // Fit the longest caption to the tile width.
  std::size_t longest = 1;
  for (const auto& caption : captions) longest = std::max(longest, caption.size());
  const double fontScale =
      std::clamp(std::min(captionHeight / 30.0, (tile.width - 8) / (18.0 * longest)), 0.25, 1.0);
  for (std::size_t i = 0; i < tiles.size(); ++i) {
    if (tiles[i].size() != tile) throw Error("contact sheet: images differ in size");
    const int col = static_cast<int>(i) % columns;
    const int row = static_cast<int>(i) / columns;
    const cv::Rect cell(col * tile.width, row * cellHeight, tile.width, tile.height);
    flattenAlpha(tiles[i], background).copyTo(sheet(cell));
    if (!captions.empty()) {
      const cv::Point at(cell.x + 4, cell.y + tile.height + captionHeight - captionHeight / 4);
      cv::putText(sheet, captions[i], at, cv::FONT_HERSHEY_SIMPLEX, fontScale,
                  cv::Scalar(230, 230, 230), 1, cv::LINE_AA);
    }
  }
  return sheet;
}

}  // namespace clm3d
