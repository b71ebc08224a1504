#include "core/model/clm_model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>

#include "core/common/error.hpp"

namespace clm3d {

namespace {

[[noreturn]] void fail(const std::string& field, const std::string& what) {
  throw Error("field " + field + ": " + what);
}

std::string str(Eigen::Index value) {
  return std::to_string(value);
}

template <typename Derived>
void requireFinite(const Eigen::DenseBase<Derived>& values, const std::string& field) {
  if (!values.allFinite()) fail(field, "contains a non-finite value");
}

void validateShape(const ShapeModel& shape, int n) {
  if (shape.dims != 2 && shape.dims != 3) fail("shape.dims", "must be 2 or 3");
  if (shape.meanShape.cols() != n) {
    fail("shape.meanShape", str(shape.meanShape.cols()) + " points, the scheme has " + str(n));
  }
  if (shape.modes.rows() != 3 * Eigen::Index(n)) {
    fail("shape.modes", str(shape.modes.rows()) + " rows, expected " + str(3 * Eigen::Index(n)));
  }
  if (shape.variances.size() != shape.modes.cols()) {
    fail("shape.variances",
         str(shape.variances.size()) + " values for " + str(shape.modes.cols()) + " modes");
  }
  requireFinite(shape.meanShape, "shape.meanShape");
  requireFinite(shape.modes, "shape.modes");
  requireFinite(shape.variances, "shape.variances");
  if ((shape.variances.array() < 0).any()) fail("shape.variances", "negative variance");
  for (Eigen::Index k = 0; k < shape.modes.cols(); ++k) {
    if (std::abs(shape.modes.col(k).norm() - 1.0) > 1e-6) {
      fail("shape.modes", "mode " + str(k) + " is not of unit length");
    }
  }
  if (!std::isfinite(shape.limitSd) || !(shape.limitSd > 0)) {
    fail("shape.limitSd", "must be positive");
  }
}

void validatePatchModel(const PatchModel& patch, const ViewModel& view, int n,
                        const std::string& field) {
  if (patch.patchSize < 1 || patch.patchSize > 1024) fail(field + ".patchSize", "not in 1..1024");
  int visibleCount = 0;
  for (const bool visible : view.visible) visibleCount += visible ? 1 : 0;
  if (static_cast<int>(patch.landmarks.size()) != visibleCount) {
    fail(field + ".landmarks", std::to_string(patch.landmarks.size()) +
                                   " landmarks, the view has " + std::to_string(visibleCount) +
                                   " visible");
  }
  for (std::size_t e = 0; e < patch.landmarks.size(); ++e) {
    const int landmark = patch.landmarks[e];
    if (landmark < 0 || landmark >= n) fail(field + ".landmarks", "index out of range");
    if (e > 0 && landmark <= patch.landmarks[e - 1]) {
      fail(field + ".landmarks", "not ascending and unique");
    }
    if (!view.visible[static_cast<std::size_t>(landmark)]) {
      fail(field + ".landmarks", "landmark " + std::to_string(landmark) + " is not visible");
    }
  }
  const Eigen::Index pixels = Eigen::Index(patch.patchSize) * patch.patchSize;
  const Eigen::Index d = Eigen::Index(patch.landmarks.size()) * pixels;
  const PcaModel& pca = patch.pca;
  if (pca.mean.size() != d) {
    fail(field + ".pca.mean", str(pca.mean.size()) + " values, expected " + str(d));
  }
  if (pca.components.rows() != d) {
    fail(field + ".pca.components", str(pca.components.rows()) + " rows, expected " + str(d));
  }
  if (pca.variances.size() != pca.components.cols()) {
    fail(field + ".pca.variances",
         str(pca.variances.size()) + " values for " + str(pca.components.cols()) + " modes");
  }
  requireFinite(pca.mean, field + ".pca.mean");
  requireFinite(pca.components, field + ".pca.components");
  requireFinite(pca.variances, field + ".pca.variances");
  if ((pca.variances.array() < 0).any()) fail(field + ".pca.variances", "negative variance");
  for (Eigen::Index k = 0; k < pca.components.cols(); ++k) {
    if (std::abs(pca.components.col(k).norm() - 1.0f) > 1e-3f) {
      fail(field + ".pca.components", "component " + str(k) + " is not of unit length");
    }
  }
  if (patch.alpha.size() != patch.landmarks.size()) {
    fail(field + ".alpha", std::to_string(patch.alpha.size()) + " patches for " +
                               std::to_string(patch.landmarks.size()) + " landmarks");
  }
  for (std::size_t e = 0; e < patch.alpha.size(); ++e) {
    const auto& alpha = patch.alpha[e];
    const std::string where = field + ".alpha[" + std::to_string(e) + "]";
    if (alpha.size() != pixels) fail(where, str(alpha.size()) + " values, expected " + str(pixels));
    requireFinite(alpha, where);
    if ((alpha.array() < 0.0f).any() || (alpha.array() > 1.0f).any()) {
      fail(where, "value outside [0, 1]");
    }
  }
  if (!patch.experts.empty() && patch.experts.size() != patch.landmarks.size()) {
    fail(field + ".experts", std::to_string(patch.experts.size()) + " experts for " +
                                 std::to_string(patch.landmarks.size()) + " landmarks");
  }
  for (std::size_t e = 0; e < patch.experts.size(); ++e) {
    const PatchExpert& expert = patch.experts[e];
    const std::string where = field + ".experts[" + std::to_string(e) + "]";
    if (expert.weights.rows() != pixels || expert.units() < 1) {
      fail(where, str(expert.weights.rows()) + " weights per unit, expected " + str(pixels));
    }
    if (expert.bias.size() != expert.units() || expert.alpha.size() != expert.units()) {
      fail(where, "biases or unit weights do not match its " + str(expert.units()) + " units");
    }
    if (expert.units() != patch.experts.front().units()) {
      fail(where, "has " + str(expert.units()) + " units, the scale's first expert " +
                      str(patch.experts.front().units()));
    }
    requireFinite(expert.weights, where);
    if (!expert.bias.allFinite() || !expert.alpha.allFinite()) {
      fail(where, "a bias or unit weight is not finite");
    }
  }
}

}  // namespace

Scheme ClmModel::scheme() const {
  return Scheme::fromJson(schemeJson, "model scheme");
}

void ClmModel::validate() const {
  Scheme parsed;
  try {
    parsed = scheme();
  } catch (const Error& e) {
    fail("scheme", e.what());
  }
  const int n = parsed.size();
  validateShape(shape, n);
  if (views.empty()) fail("views", "no views");
  if (singleView && views.size() != 1) {
    fail("views", "a single-view model has " + std::to_string(views.size()) + " views");
  }
  if (!std::isfinite(patchRatio) || !(patchRatio > 0)) fail("patchRatio", "must be positive");
  if (!settingsJson.empty()) {
    const auto settings = nlohmann::json::parse(settingsJson, nullptr, false);
    if (settings.is_discarded() || !settings.is_object()) {
      fail("settings", "not a JSON object");
    }
  }
  for (std::size_t v = 0; v < views.size(); ++v) {
    const ViewModel& view = views[v];
    const std::string field = "views[" + std::to_string(v) + "]";
    if (!std::isfinite(view.pitchDeg) || std::abs(view.pitchDeg) > 90) {
      fail(field + ".pitch", "not in [-90, 90] degrees");
    }
    if (!std::isfinite(view.yawDeg) || std::abs(view.yawDeg) > 180) {
      fail(field + ".yaw", "not in [-180, 180] degrees");
    }
    if (static_cast<int>(view.visible.size()) != n) {
      fail(field + ".visible", std::to_string(view.visible.size()) + " flags, the scheme has " +
                                   std::to_string(n) + " landmarks");
    }
    if (view.calibration &&
        !(std::isfinite(view.calibration->slope) && std::isfinite(view.calibration->offset))) {
      fail(field + ".calibration", "not finite");
    }
    try {
      view.check.validate(n);
    } catch (const Error& e) {
      fail(field + ".check", e.what());
    }
    if (view.scales.empty()) fail(field + ".scales", "no scales");
    for (std::size_t s = 0; s < view.scales.size(); ++s) {
      validatePatchModel(view.scales[s], view, n, field + ".scales[" + std::to_string(s) + "]");
    }
  }
  try {
    refiner.validate(n);
  } catch (const Error& e) {
    fail("refiner", e.what());
  }
  for (const PhotoFitCurve& curve : refiner.check.photoFitCurves) {
    if (!curve.hasImageTerm()) continue;
    const int layout = photoFitLayoutView(curve.viewYawDeg);
    Eigen::Index seen = -1;
    if (layout >= 0) {
      const std::vector<bool>& visible = views[static_cast<std::size_t>(layout)].visible;
      seen = std::count(visible.begin(), visible.end(), true);
    }
    if (curve.imageWeights.size() != seen * kDescentFeaturesPerPoint) {
      fail("refiner.check.photoFitCurves", "the image term of |yaw| " +
                                               std::to_string(curve.viewYawDeg) +
                                               " does not match the landmarks its views see");
    }
  }
}

int ClmModel::photoFitLayoutView(double absYawDeg) const {
  int best = -1;
  for (std::size_t v = 0; v < views.size(); ++v) {
    const ViewModel& view = views[v];
    if (view.mirrored || std::abs(std::abs(view.yawDeg) - absYawDeg) > 1e-9) continue;
    if (best < 0 ||
        std::abs(view.pitchDeg) < std::abs(views[static_cast<std::size_t>(best)].pitchDeg))
      best = static_cast<int>(v);
  }
  return best;
}

int ClmModel::nearestView(double pitchDeg, double yawDeg) const {
  int best = -1;
  double bestDistance = std::numeric_limits<double>::infinity();
  for (std::size_t v = 0; v < views.size(); ++v) {
    const double distance = std::hypot(views[v].pitchDeg - pitchDeg, views[v].yawDeg - yawDeg);
    if (distance < bestDistance) {
      bestDistance = distance;
      best = static_cast<int>(v);
    }
  }
  return best;
}

}  // namespace clm3d
