#include "core/train/train_settings.hpp"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "core/common/error.hpp"
#include "core/train/train_options.hpp"

namespace clm3d {
namespace {

void require(bool ok, const std::string& what) {
  if (!ok) throw InputError("training settings: " + what);
}

std::vector<double> sortedUnique(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  return values;
}

}  // namespace

void TrainSettings::validate() const {
  // Every option's value against its range (core/train/train_options: the ranges of `clm3d
  // train` and of the studio's form); the error names the option.
  checkOptions(trainOptions(), *this, "training settings");
  const AugmentationSettings& a = augmentation;
  require(a.colourJitter >= 0 && a.colourJitter <= AugmentationSettings::kMaxColourJitter,
          "augmentation colour jitter must be 0..0.5");
  require(a.whiteBalance >= 0 && a.whiteBalance <= AugmentationSettings::kMaxWhiteBalance,
          "augmentation white balance must be 0..0.5");
  require(a.blurSigmaMax >= 0 && a.blurSigmaMax <= AugmentationSettings::kMaxBlurSigma,
          "augmentation blur sigma must be 0..5 pixels");
  require(a.noiseSd >= 0 && a.noiseSd <= AugmentationSettings::kMaxNoiseSd,
          "augmentation noise sd must be 0..0.5");
  require(a.jpegQualityMin == 0 || (a.jpegQualityMin >= AugmentationSettings::kMinJpegQuality &&
                                    a.jpegQualityMin <= AugmentationSettings::kMaxJpegQuality),
          "augmentation JPEG quality must be 0 (off) or 5..95");
  require(a.lightAngleMaxDeg >= 0 && a.lightAngleMaxDeg <= AugmentationSettings::kMaxLightAngleDeg,
          "augmentation light angle must be 0..90 degrees");
  require(a.probability >= 0 && a.probability <= 1, "augmentation probability must be 0..1");
}

std::vector<ViewCentre> TrainSettings::views() const {
  if (singleView) return {ViewCentre{0, 0}};
  std::vector<ViewCentre> result;
  for (double pitch : sortedUnique(pitchesDeg)) {
    for (double yaw : sortedUnique(yawsDeg)) result.push_back({pitch, yaw});
  }
  return result;
}

int TrainSettings::renderSize() const {
  // The face spans about 2.4 inter-ocular distances (earlobe to earlobe); 3.4 leaves room for
  // the perturbations and the patches around the outermost landmarks.
  const int size = static_cast<int>(std::ceil(3.4 * interOcularPixels()));
  return (size + 3) / 4 * 4;
}

std::string TrainSettings::toJson() const {
  nlohmann::ordered_json j;
  j["views"] = singleView ? nlohmann::ordered_json::array({{{"pitch", 0.0}, {"yaw", 0.0}}})
                          : nlohmann::ordered_json::array();
  if (!singleView) {
    for (const ViewCentre& v : views())
      j["views"].push_back({{"pitch", v.pitchDeg}, {"yaw", v.yawDeg}});
  }
  j["scales"] = scales;
  j["patch_size"] = patchSize;
  j["patch_ratio"] = patchRatio;
  j["samples_per_view"] = samplesPerView;
  j["perturbation"] = {{"rotation_deg", perturbation.rotationDeg},
                       {"view_coverage", perturbation.viewCoverage},
                       {"scale", perturbation.scale},
                       {"shift_pixels", perturbation.shiftPixels},
                       {"light_direction", perturbation.lightDirection},
                       {"ambient", perturbation.ambient},
                       {"diffuse", perturbation.diffuse}};
  j["texture_variance"] = textureVariance;
  j["texture_max_modes"] = textureMaxModes;
  j["shape"] = {{"variance_kept", shape.varianceKept},
                {"mirror", shape.mirror},
                {"limit_sd", shape.limitSd},
                {"dims", singleView ? 2 : shape.dims},
                {"max_modes", shape.maxModes}};
  j["mirror_right_views"] = mirrorRightViews && !singleView;
  j["single_view"] = singleView;
  j["hidden_share"] = hiddenShare;
  j["supersample"] = supersample;
  if (expertRadius > 0) {  // absent when off, so models trained without experts are unchanged
    j["experts"] = {{"radius", expertRadius}, {"ridge", expertRidge}, {"units", expertUnits}};
  }
  j["photo_jitter"] = photoJitter;
  j["refiner"] = {{"stages", refinerStages}, {"starts", refinerStarts}};
  if (calibrateViews) j["calibrate_views"] = true;  // absent when off, as before format 7
  j["render_size"] = renderSize();
  j["greyscale"] = true;
  if (augmentation.any()) {  // absent when off, so models trained without it are unchanged
    j["augmentation"] = nlohmann::ordered_json::parse(augmentationJson(augmentation));
  }
  j["seed"] = seed;
  return j.dump(2);
}

}  // namespace clm3d
