// Small videos whose frames say their own number, and damaged copies of them (cut short, or a
// stretch of bytes zeroed), for the tests of unreadable frames (video and track suites).
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <opencv2/core.hpp>
#include <string>

#include "core/video/video_writer.hpp"

namespace clm3d::test {

inline constexpr int kNumberedWidth = 64;
inline constexpr int kNumberedHeight = 48;

// Frame `number`: noise (so that every frame takes many bytes and damage hits few of them) with a
// block at the top left whose grey level is 8 * number.
inline cv::Mat numberedFrame(int number) {
  cv::Mat frame(kNumberedHeight, kNumberedWidth, CV_8UC3);
  cv::RNG random(static_cast<std::uint64_t>(number + 1));
  random.fill(frame, cv::RNG::UNIFORM, 0, 256);
  frame(cv::Rect(0, 0, 16, 16)).setTo(cv::Scalar::all(8 * number));
  return frame;
}

// The number numberedFrame drew into `frame` (exact for lossless files, nearest for .mp4).
inline int numberOf(const cv::Mat& frame) {
  const cv::Scalar mean = cv::mean(frame(cv::Rect(4, 4, 8, 8)));
  return static_cast<int>(std::lround(mean[1] / 8.0));
}

inline void writeNumberedVideo(const std::filesystem::path& path, int frames, double fps = 25.0) {
  VideoWriter writer(path, kNumberedWidth, kNumberedHeight, fps);
  for (int i = 0; i < frames; ++i) writer.write(numberedFrame(i));
  writer.close();
}

inline std::string fileBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

inline void writeBytes(const std::filesystem::path& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

// The first `share` of the file's bytes: a download or copy cut short.
inline void writeTruncatedCopy(const std::filesystem::path& from, const std::filesystem::path& to,
                               double share) {
  const std::string bytes = fileBytes(from);
  writeBytes(to,
             bytes.substr(0, static_cast<std::size_t>(static_cast<double>(bytes.size()) * share)));
}

// The file with `count` bytes zeroed from `at` (a share of its size): a damaged stretch.
inline void writeDamagedCopy(const std::filesystem::path& from, const std::filesystem::path& to,
                             double at, std::size_t count) {
  std::string bytes = fileBytes(from);
  const auto first = static_cast<std::size_t>(static_cast<double>(bytes.size()) * at);
  for (std::size_t k = first; k < first + count && k < bytes.size(); ++k) bytes[k] = 0;
  writeBytes(to, bytes);
}

}  // namespace clm3d::test
