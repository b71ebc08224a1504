#include "core/dataset/model_frame.hpp"

#include "core/common/error.hpp"
#include "core/mesh/mesh_transform.hpp"
#include "core/scheme/ibug68_conversion.hpp"

namespace clm3d {

std::optional<ModelFrame> modelFrame(const LandmarkSet& landmarks, const Scheme& scheme,
                                     const Eigen::Vector3d& up, const Eigen::Vector3d& front,
                                     bool levelEyes, std::string& why) {
  if (landmarks.dims() != 3) {
    why = "expected 3D landmarks (x, y, z)";
    return std::nullopt;
  }
  std::optional<LandmarkSet> thesis;
  if (scheme.name() == "thesis25" && landmarks.size() == 25) thesis = landmarks;
  if (scheme.name() == "ibug68" && landmarks.size() == 68) thesis = ibug68ToThesis25(landmarks);

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
  const auto [left, right] = Scheme::thesis25().normalisationPair();  // the eye centres
  if (!thesis->has(left) || !thesis->has(right)) {
    why =
        "the eye centres are missing, so the head cannot be levelled on them (set level_eyes to "
        "false)";
    return std::nullopt;
  }
  try {
    frame.rotation = eyeLevelRotation(thesis->point(left), thesis->point(right), up);
  } catch (const Error& e) {
    why = e.what();
    return std::nullopt;
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
