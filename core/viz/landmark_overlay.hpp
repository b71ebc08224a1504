// Drawing landmarks over an image, the same way everywhere (render overlays, demo contact
// sheets, and later tracking videos): a dot in the colour of the landmark's region, filled when
// visible and hollow when hidden, numbered 1..N as in the thesis and .pts files.
#pragma once

#include <opencv2/core/mat.hpp>
#include <vector>

#include "core/scheme/landmark_set.hpp"
#include "core/scheme/scheme.hpp"

namespace clm3d {

struct OverlayStyle {
  bool numbers = true;
  double scale = 1.0;  // multiplies the size-dependent dot radius and font
};

// Draws the present points of `points` (pixels, 2D or 3D with z ignored) on a BGR or BGRA image.
// `visible` may be empty (all visible); colours come from the scheme's regions.
void drawLandmarks(cv::Mat& image, const LandmarkSet& points, const std::vector<bool>& visible,
                   const Scheme& scheme, const OverlayStyle& style = {});

}  // namespace clm3d
