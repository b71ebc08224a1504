#include "core/detect/detail/dlib_hog.hpp"

#include "core/common/error.hpp"

#ifdef CLM3D_HAVE_DLIB
#include <dlib/image_processing/frontal_face_detector.h>
#include <dlib/image_transforms/interpolation.h>

#include <sstream>
#include <string_view>

namespace clm3d::embedded {
// dlib::serialize of get_frontal_face_detector(), written at build time
// (build_tools/embed_dlib_detector.cpp).
std::string_view dlibFrontalFaceDetector();
}  // namespace clm3d::embedded
#endif

namespace clm3d::detail {

#ifdef CLM3D_HAVE_DLIB

namespace {
// dlib's frontal detector scans an 80 x 80 pixel window; smaller faces need the image enlarged.
constexpr int kDlibWindow = 80;

// The detector from the copy serialized at build time (about 4 ms; dlib's own compressed copy
// takes about 500 ms to decode), dlib's own if that copy does not read.
dlib::frontal_face_detector loadFrontalFaceDetector() {
  const std::string_view bytes = embedded::dlibFrontalFaceDetector();
  try {
    std::istringstream in{std::string(bytes)};
    dlib::frontal_face_detector detector;
    dlib::deserialize(detector, in);
    if (detector.num_detectors() > 0) return detector;
  } catch (const dlib::serialization_error&) {
  }
  return dlib::get_frontal_face_detector();
}
}  // namespace

struct DlibHogDetector::Impl {
  dlib::frontal_face_detector hog = loadFrontalFaceDetector();
};

bool dlibAvailable() {
  return true;
}

DlibHogDetector::DlibHogDetector() : impl_(std::make_unique<Impl>()) {}

void DlibHogDetector::detect(const cv::Mat& grey, int minFaceSize, double threshold,
                             std::vector<FaceBox>& out) {
  dlib::array2d<unsigned char> image(grey.rows, grey.cols);
  for (int r = 0; r < grey.rows; ++r) {
    const unsigned char* row = grey.ptr<unsigned char>(r);
    for (int c = 0; c < grey.cols; ++c) image[r][c] = row[c];
  }
  int doublings = 0;
  // kDlibSmallestUnenlarged = kDlibWindow / 1.25.
  while ((kDlibWindow >> doublings) > minFaceSize * 1.25 && doublings < 2) ++doublings;
  for (int d = 0; d < doublings; ++d) dlib::pyramid_up(image);
  const double shrink = 1.0 / static_cast<double>(1 << doublings);
  std::vector<dlib::rect_detection> detections;
  impl_->hog(image, detections, threshold);
  for (const dlib::rect_detection& detection : detections) {
    FaceBox face;
    const dlib::rectangle& r = detection.rect;
    // dlib rectangles are inclusive pixel ranges.
    face.box = cv::Rect2d(
        static_cast<double>(r.left()) * shrink, static_cast<double>(r.top()) * shrink,
        static_cast<double>(r.width()) * shrink, static_cast<double>(r.height()) * shrink);
    if (face.box.width < minFaceSize) continue;
    face.score = detection.detection_confidence;
    face.detector = DetectorKind::DlibHog;
    // Filters 1 and 2 are dlib's side views: 1 finds heads turned towards the image's left
    // (negative yaw), 2 towards its right (measured on renders, docs/initialisation.md).
    face.profile = detection.weight_index == 1 || detection.weight_index == 2;
    face.mirrored = detection.weight_index == 2;
    out.push_back(face);
  }
}

#else

struct DlibHogDetector::Impl {};

bool dlibAvailable() {
  return false;
}

DlibHogDetector::DlibHogDetector() {
  throw Error(
      "the dlib face detector is not available: clm3d was built without dlib (install "
      "libdlib-dev and rebuild, or use the cascade detector)");
}

void DlibHogDetector::detect(const cv::Mat&, int, double, std::vector<FaceBox>&) {}

#endif

DlibHogDetector::~DlibHogDetector() = default;

}  // namespace clm3d::detail
