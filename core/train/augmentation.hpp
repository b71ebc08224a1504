// Appearance augmentation of one training render (docs/training.md, "Appearance augmentation"):
// what a sample's effects are (drawn once, from the sample's own random stream) and the image
// effects applied after rendering, in camera order: composite over a background using the
// render's alpha -> brightness/contrast/saturation -> white balance -> blur -> sensor noise ->
// JPEG. The light and the cast shadows act during rendering (drawAugmentation widens the light,
// core/train/cast_shadow darkens what the light cannot reach). Alpha masks stay the render's own.
#pragma once

#include <cstdint>
#include <opencv2/core/mat.hpp>

#include "core/dataset/augmentation_settings.hpp"
#include "core/render/offscreen_renderer.hpp"

namespace clm3d {

// The effects of one sample, with their drawn strengths; default = no effect.
struct AugmentationDraw {
  bool clutterBackground = false;
  bool shadows = false;
  double brightness = 1.0, contrast = 1.0, saturation = 1.0;  // factors
  double gains[3] = {1.0, 1.0, 1.0};                          // white balance, B G R (mean 1)
  double blurSigma = 0.0;                                     // pixels
  double noiseSd = 0.0;                                       // share of full scale at mid-grey
  int jpegQuality = 0;                                        // 0 = no JPEG round trip
  std::uint64_t pixelSeed = 0;                                // background and noise pixels

  // True if any effect after rendering changes the image (augmentImage is not the identity).
  bool changesImage() const;
};

// Draws a sample's effects from the stream `key`: each switched-on effect is applied with
// settings.probability, its strength uniform in its range. A wider light (lightAngleMaxDeg > 0)
// replaces `lighting`: direction uniform over the cap within that angle of the view axis,
// ambient in [0.2, 0.55], diffuse in [0.5, 1.0].
AugmentationDraw drawAugmentation(const AugmentationSettings& settings, std::uint64_t key,
                                  Lighting& lighting);

// The effects after rendering, on a premultiplied BGRA render (alpha = coverage, background
// transparent black, as OffscreenRenderer draws it). Returns an 8-bit BGR image of the same size.
cv::Mat augmentImage(const cv::Mat& renderBgra, const AugmentationDraw& draw);

}  // namespace clm3d
