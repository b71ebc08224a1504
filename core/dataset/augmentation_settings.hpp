// The appearance augmentation of training renders (the manifest's `augmentation` object, carried
// into TrainSettings): which effects make the synthetic renders look more like camera images
// (cluttered backgrounds, colour and white-balance jitter, blur, sensor noise, JPEG, wider lights
// and cast shadows). A plain struct in its own header so the training stage can hold it without
// the manifest. By default only the cluttered background is on: a flat black background taught the
// contour patches a face-brighter-than-background edge, and a face turned away from the light in
// front of a brighter background lost its contour (docs/experiments.md, section 10). The other
// effects are switched on per manifest (their effect: docs/training-data.md).
#pragma once

#include <string>

namespace clm3d {

enum class AugmentationBackground { None, Clutter };

struct AugmentationSettings {
  // The accepted range of each field (the manifest and TrainSettings::validate check them).
  static constexpr double kMaxColourJitter = 0.5;
  static constexpr double kMaxWhiteBalance = 0.5;
  static constexpr double kMaxBlurSigma = 5.0;
  static constexpr double kMaxNoiseSd = 0.5;
  static constexpr int kMinJpegQuality = 5;
  static constexpr int kMaxJpegQuality = 95;
  static constexpr double kMaxLightAngleDeg = 90.0;

  AugmentationBackground background = AugmentationBackground::Clutter;
  double colourJitter = 0.0;      // brightness, contrast and saturation factors in 1 +- this
  double whiteBalance = 0.0;      // per-channel gains in 1 +- this
  double blurSigmaMax = 0.0;      // Gaussian blur sigma drawn in [0, this] pixels (finest scale)
  double noiseSd = 0.0;           // sensor noise sd at mid-grey, share of full scale
  int jpegQualityMin = 0;         // JPEG re-encode at a quality in [this, 95]; 0 = off
  double lightAngleMaxDeg = 0.0;  // > 0: light drawn within this angle of the view axis
  bool shadows = false;           // the face casts shadows on itself
  double probability = 1.0;       // each switched-on effect is applied to a sample this often

  // Every effect off: training renders on flat black, as before augmentation existed.
  static AugmentationSettings off() {
    AugmentationSettings a;
    a.background = AugmentationBackground::None;
    return a;
  }

  // True if any effect is switched on (probability aside).
  bool any() const {
    return background != AugmentationBackground::None || colourJitter > 0 || whiteBalance > 0 ||
           blurSigmaMax > 0 || noiseSd > 0 || jpegQualityMin > 0 || lightAngleMaxDeg > 0 || shadows;
  }
};

inline std::string backgroundName(AugmentationBackground background) {
  return background == AugmentationBackground::Clutter ? "clutter" : "none";
}

// Every field as a JSON object in the manifest's names ("background", "colour_jitter", ...), in
// declaration order: how the manifest writer and the model's training settings store it.
std::string augmentationJson(const AugmentationSettings& augmentation);

}  // namespace clm3d
