// Reading and writing images with the project's error and atomic-save rules: a bad or missing
// image is an InputError naming the file, and a save never leaves a half-written file.
#pragma once

#include <filesystem>
#include <opencv2/core/mat.hpp>

namespace clm3d {

// Encodes by extension (.png keeps alpha and 16-bit; .tiff also takes 32-bit float; .jpg ...).
void writeImage(const std::filesystem::path& path, const cv::Mat& image);

// Reads an image as 8-bit BGR, or as it is stored with keepAlpha (BGRA when it has alpha).
cv::Mat readImage(const std::filesystem::path& path, bool keepAlpha = false);

}  // namespace clm3d
