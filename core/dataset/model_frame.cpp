#include "core/dataset/detail/model_frame.hpp"

#include "core/common/error.hpp"
#include "core/mesh/mesh_transform.hpp"
#include "core/scheme/ibug68_conversion.hpp"

namespace clm3d {

std::optional<std::pair<Eigen::Vector3d, Eigen::Vector3d>> eyeLevelPoints(
    const LandmarkSet& thesis) {
  // thesis25 indices (0-based): eye centres, outer and inner eye corners, subject's left first.
  constexpr int kLeftCentre = 7, kRightCentre = 10;
  constexpr int kLeftOuter = 1, kRightOuter = 2, kLeftInner = 8, kRightInner = 9;
  const auto both = [&](int left, int right) { return thesis.has(left) && thesis.has(right); };
  if (both(kLeftCentre, kRightCentre)) {
    return std::pair{thesis.point(kLeftCentre), thesis.point(kRightCentre)};
  }
  if (both(kLeftOuter, kRightOuter) && both(kLeftInner, kRightInner)) {
    return std::pair{0.5 * (thesis.point(kLeftOuter) + thesis.point(kLeftInner)),
                     0.5 * (thesis.point(kRightOuter) + thesis.point(kRightInner))};
  }
  if (both(kLeftOuter, kRightOuter)) {
    return std::pair{thesis.point(kLeftOuter), thesis.point(kRightOuter)};
  }
  if (both(kLeftInner, kRightInner)) {
    return std::pair{thesis.point(kLeftInner), thesis.point(kRightInner)};
  }
  return std::nullopt;
}

namespace {

// The landmarks in thesis25 order when the scheme has its points (thesis25 or ibug68).
std::optional<LandmarkSet> inThesisOrder(const LandmarkSet& landmarks, const Scheme& scheme) {
  if (scheme.name() == "thesis25" && landmarks.size() == 25) return landmarks;
  if (scheme.name() == "ibug68" && landmarks.size() == 68) return ibug68ToThesis25(landmarks);
  return std::nullopt;
}

}  // namespace

std::optional<ModelFrame> modelFrame(const LandmarkSet& landmarks, const Scheme& scheme,
                                     const Eigen::Vector3d& up, const Eigen::Vector3d& front,
                                     bool levelEyes, std::string& why) {
  if (landmarks.dims() != 3) {
    why = "expected 3D landmarks (x, y, z)";
    return std::nullopt;
  }
  const std::optional<LandmarkSet> thesis = inThesisOrder(landmarks, scheme);

  ModelFrame frame;
  const LandmarkSet& reference = thesis ? *thesis : landmarks;
  if (reference.size() == 0 || !reference.has(0)) {
    why = "landmark 1 (between the eyes), the model's origin, is missing";
    return std::nullopt;
  }
  frame.origin = reference.point(0);
  if (!levelEyes) {
    frame.rotation = axesToModelRotation(up, front);
    return frame;
  }
  if (!thesis) {
    why = "levelling on the eyes needs the thesis25 or ibug68 scheme (set level_eyes to false)";
    return std::nullopt;
  }
  const auto eyes = eyeLevelPoints(*thesis);
  if (!eyes) {
    why =
        "the eye centres and both pairs of eye corners are missing, so the head cannot be levelled "
        "on the eyes (set level_eyes to false)";
    return std::nullopt;
  }
  try {
    frame.rotation = eyeLevelRotation(eyes->first, eyes->second, up);
  } catch (const Error& e) {
    why = e.what();
    return std::nullopt;
  }
  return frame;
}

ModelFrame viewingFrame(const LandmarkSet* landmarks, const Scheme* scheme,
                        const Eigen::Vector3d& up, const Eigen::Vector3d& front, bool levelEyes,
                        const Eigen::Vector3d& fallbackOrigin, bool& levelled) {
  ModelFrame frame;
  frame.rotation = axesToModelRotation(up, front);
  frame.origin = fallbackOrigin;
  levelled = false;
  if (landmarks == nullptr || scheme == nullptr || landmarks->dims() != 3) return frame;
  const std::optional<LandmarkSet> thesis = inThesisOrder(*landmarks, *scheme);
  const LandmarkSet& reference = thesis ? *thesis : *landmarks;
  if (reference.size() > 0 && reference.has(0)) frame.origin = reference.point(0);
  if (!levelEyes || !thesis) return frame;
  if (const auto eyes = eyeLevelPoints(*thesis)) {
    frame.rotation = eyeLevelRotation(eyes->first, eyes->second, up);
    levelled = true;
  }
  return frame;
}

LandmarkSet applyFrame(const ModelFrame& frame, const LandmarkSet& landmarks) {
  LandmarkSet out(landmarks.size(), 3);
  for (int i = 0; i < landmarks.size(); ++i) {
    if (landmarks.has(i)) out.set(i, frame.apply(landmarks.point(i)));
  }
  return out;
}

}  // namespace clm3d
