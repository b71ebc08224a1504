// Two procedural heads in one video, for the multi-face tracker's tests: head 0 rendered once in
// the top half of a 640x520 frame moving right, the held-out head rendered once in the bottom half
// moving left, so that the two cross (swap sides) half-way, one above the other, never
// overlapping. Each frame's truth is the heads' rendered points moved with them. A head can be
// left out of chosen frames (a face that leaves and comes back).
#pragma once

#include <functional>
#include <opencv2/core.hpp>
#include <vector>

#include "tests/support/fit_fixture.hpp"

namespace clm3d::test {

struct TwoFaceFrame {
  cv::Mat image;
  Eigen::Matrix2Xd top, bottom;  // truth points; empty when that head is not in the frame
};

// `frames` frames; the top head moves `step` pixels right a frame from x = 0, the bottom head
// `step` pixels left from x = 320 (step 0: still). `bottomShown(k)` says whether the bottom head is
// in frame k (default: always).
inline std::vector<TwoFaceFrame> twoFaceFrames(int frames, int step,
                                               const std::function<bool(int)>& bottomShown = {}) {
  const ClmModel& model = fitTestModel();
  const FitScene top = makeFitScene(model, 0.0, 0.0, 0, 60.0);
  const FitScene bottom = makeFitScene(model, 0.0, 0.0, kHeldOutHead, 60.0);
  const cv::Vec3b grey = top.image.at<cv::Vec3b>(0, 0);
  std::vector<TwoFaceFrame> sequence;
  for (int k = 0; k < frames; ++k) {
    TwoFaceFrame frame;
    frame.image = cv::Mat(520, 640, CV_8UC3, cv::Scalar(grey[0], grey[1], grey[2]));
    const int topX = step * k;
    top.image.copyTo(frame.image(cv::Rect(topX, 0, 320, 240)));
    frame.top = top.truthPoints.colwise() + Eigen::Vector2d(topX, 0.0);
    if (!bottomShown || bottomShown(k)) {
      const int bottomX = 320 - step * k;
      bottom.image.copyTo(frame.image(cv::Rect(bottomX, 280, 320, 240)));
      frame.bottom = bottom.truthPoints.colwise() + Eigen::Vector2d(bottomX, 280.0);
    }
    sequence.push_back(std::move(frame));
  }
  return sequence;
}

}  // namespace clm3d::test
