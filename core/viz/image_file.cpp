#include "core/viz/image_file.hpp"

#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

#include "core/common/atomic_file.hpp"
#include "core/common/error.hpp"

namespace clm3d {

void writeImage(const std::filesystem::path& path, const cv::Mat& image) {
  const std::string extension = path.extension().string();
  if (extension.empty()) throwInputError(path, "needs an image extension such as .png");
  if (image.empty()) throwInputError(path, "nothing to write: the image is empty");
  std::vector<unsigned char> bytes;
  bool encoded = false;
  try {
    encoded = cv::imencode(extension, image, bytes);
  } catch (const cv::Exception&) {
    encoded = false;
  }
  if (!encoded) throwInputError(path, "cannot encode an image of this type ('" + extension + "')");
  writeBytesAtomically(path, bytes);
}

cv::Mat readImage(const std::filesystem::path& path, bool keepAlpha) {
  const std::string bytes = readTextFile(path);
  const cv::Mat buffer(1, static_cast<int>(bytes.size()), CV_8UC1, const_cast<char*>(bytes.data()));
  cv::Mat image;
  try {
    image = cv::imdecode(buffer, keepAlpha ? cv::IMREAD_UNCHANGED : cv::IMREAD_COLOR);
  } catch (const cv::Exception&) {
    image.release();
  }
  if (image.empty()) throwInputError(path, "not a readable image (unknown format or corrupt)");
  return image;
}

}  // namespace clm3d
