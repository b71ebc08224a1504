// Bringing landmark-annotated 3D data into model coordinates the same way for every source (a
// scan, an ICT-FaceKit sample): the rotation from the file's axes, optionally levelled on the eye
// centres, and the translation that puts landmark 1 at the origin.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <utility>

#include "core/scheme/landmark_set.hpp"
#include "core/scheme/scheme.hpp"

namespace clm3d {

struct ModelFrame {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  // file coordinates of the new origin
  Eigen::Vector3d apply(const Eigen::Vector3d& p) const { return rotation * (p - origin); }
};

// The left and right points the head is levelled on, from thesis25-ordered landmarks: the eye
// centres (thesis 8 and 11); when either is missing (a scan with closed eyes) the midpoints of
// each eye's outer and inner corners, then the outer corners (2, 3), then the inner corners
// (9, 10). nullopt when none of these pairs is complete.
std::optional<std::pair<Eigen::Vector3d, Eigen::Vector3d>> eyeLevelPoints(
    const LandmarkSet& thesis);

// The frame for 3D landmarks of `scheme` (thesis25 or ibug68 give the eye centres and landmark 1;
// for other schemes the origin is point 0 and levelling is not available). On failure returns
// nullopt and sets `why` to the reason (the caller names the file).
std::optional<ModelFrame> modelFrame(const LandmarkSet& landmarks, const Scheme& scheme,
                                     const Eigen::Vector3d& up, const Eigen::Vector3d& front,
                                     bool levelEyes, std::string& why);

// The frame for looking at any mesh (clm3d render), which never fails for want of landmarks:
// levelled on the eyes (eyeLevelPoints) when `levelEyes` and the landmarks give them, else the
// file's axes; the origin at landmark 1 when present, else `fallbackOrigin` (e.g. the centre of the
// mesh's bounding box). `landmarks` and `scheme` may be null (a mesh without landmarks). Sets
// `levelled` to whether the eyes were used. Throws Error if the eyes lie along `up`.
ModelFrame viewingFrame(const LandmarkSet* landmarks, const Scheme* scheme,
                        const Eigen::Vector3d& up, const Eigen::Vector3d& front, bool levelEyes,
                        const Eigen::Vector3d& fallbackOrigin, bool& levelled);

// Every present point through frame.apply.
LandmarkSet applyFrame(const ModelFrame& frame, const LandmarkSet& landmarks);

}  // namespace clm3d
