#include "core/dataset/augmentation_settings.hpp"

#include <nlohmann/json.hpp>

namespace clm3d {

std::string augmentationJson(const AugmentationSettings& a) {
  const nlohmann::ordered_json j = {{"background", backgroundName(a.background)},
                                    {"colour_jitter", a.colourJitter},
                                    {"white_balance", a.whiteBalance},
                                    {"blur_sigma_max", a.blurSigmaMax},
                                    {"noise_sd", a.noiseSd},
                                    {"jpeg_quality_min", a.jpegQualityMin},
                                    {"light_angle_max", a.lightAngleMaxDeg},
                                    {"shadows", a.shadows},
                                    {"probability", a.probability}};
  return j.dump();
}

}  // namespace clm3d
