// dlib's HOG face detector behind a small interface, in its own translation unit: dlib is
// optional at build time (CLM3D_HAVE_DLIB), and its templates run 10-50x slower unoptimised, so
// core/detect/CMakeLists.txt compiles this one file optimised even in Debug and sanitizer builds.
// Internal to core/detect; use FaceDetector.
#pragma once

#include <memory>
#include <opencv2/core/mat.hpp>
#include <vector>

#include "core/detect/face_detector.hpp"

namespace clm3d::detail {

// The smallest minFaceSize at which dlib searches the image as it is (not enlarged).
constexpr int kDlibSmallestUnenlarged = 64;

// Whether this build has dlib.
bool dlibAvailable();

class DlibHogDetector {
 public:
  // Loads dlib::get_frontal_face_detector(). Throws Error when the build has no dlib.
  DlibHogDetector();
  ~DlibHogDetector();
  DlibHogDetector(const DlibHogDetector&) = delete;
  DlibHogDetector& operator=(const DlibHogDetector&) = delete;

  // Appends the faces in `grey` (CV_8UC1) with boxes of at least minFaceSize pixels; the image
  // is doubled first (up to twice) while dlib's 80-pixel window exceeds 1.25 x minFaceSize.
  // Side-view filters' boxes are marked profile, the right-turned one mirrored.
  void detect(const cv::Mat& grey, int minFaceSize, double threshold, std::vector<FaceBox>& out);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace clm3d::detail
