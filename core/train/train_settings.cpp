#include "core/train/train_settings.hpp"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "core/common/error.hpp"

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
  require(!yawsDeg.empty() && !pitchesDeg.empty(),
          "the view grid needs at least one yaw and pitch");
  for (double yaw : yawsDeg) require(std::abs(yaw) <= 90, "view yaw must be within +-90 degrees");
  for (double pitch : pitchesDeg) {
    require(std::abs(pitch) <= 60, "view pitch must be within +-60 degrees");
  }
  require(scales >= 1 && scales <= 5, "scales must be 1..5");
  require(patchSize >= 4 && patchSize <= 64, "patch size must be 4..64 pixels");
  require(patchRatio >= 0.05 && patchRatio <= 1.0, "patch ratio must be 0.05..1");
  require(samplesPerView >= 1 && samplesPerView <= 100, "samples per view must be 1..100");
  require(textureVariance > 0 && textureVariance <= 1, "texture variance must be in (0, 1]");
  require(shape.varianceKept > 0 && shape.varianceKept <= 1, "shape variance must be in (0, 1]");
  require(textureMaxModes >= 0, "texture max modes must be >= 0");
  require(hiddenShare >= 0 && hiddenShare <= 1,
          "hidden share must be in [0, 1] (1 keeps every landmark)");
  require(supersample >= 1 && supersample <= 4, "supersample must be 1..4");
  require(expertRadius >= 0 && expertRadius <= 16, "expert radius must be 0..16 pixels");
  require(expertRidge > 0 && expertRidge <= 100, "expert ridge must be in (0, 100]");
  require(expertUnits >= 1 && expertUnits <= 16, "expert units must be 1..16");
  require(photoJitter >= 0 && photoJitter <= 20, "photo jitter must be 0..20");
  require(threads >= 0 && threads <= 64, "threads must be 0..64");
  const PerturbationSettings& p = perturbation;
  require(p.rotationDeg >= 0 && p.rotationDeg <= 20, "rotation jitter must be 0..20 degrees");
  require(p.viewCoverage >= 0 && p.viewCoverage <= 1.5, "view coverage must be 0..1.5");
  require(p.scale >= 0 && p.scale <= 0.3, "scale jitter must be 0..0.3");
  require(p.shiftPixels >= 0 && p.shiftPixels <= 4, "shift jitter must be 0..4 pixels");
  require(p.lightDirection >= 0 && p.lightDirection <= 1, "light jitter must be 0..1");
  require(p.ambient >= 0 && p.ambient <= 0.4 && p.diffuse >= 0 && p.diffuse <= 0.6,
          "ambient/diffuse jitter must be 0..0.4 / 0..0.6");
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
  j["render_size"] = renderSize();
  j["greyscale"] = true;
  if (augmentation.any()) {  // absent when off, so models trained without it are unchanged
    j["augmentation"] = nlohmann::ordered_json::parse(augmentationJson(augmentation));
  }
  j["seed"] = seed;
  return j.dump(2);
}

}  // namespace clm3d
