// Where the annotator suggests landmarks: the mirror image of a placed landmark across the face's
// symmetry plane, a first guess of the unplaced ones from a shape model, and points imported from
// another annotation (e.g. 68 iBUG points converted to the scheme). Every suggestion is snapped
// onto the scan's surface with the snap function the caller provides (the studio's annotate page
// passes its view's surface pick; a test can pass core/mesh's nearestSurfacePoint).
#pragma once

#include <Eigen/Geometry>
#include <functional>
#include <optional>

#include "core/model/shape_model.hpp"
#include "core/scheme/landmark_set.hpp"
#include "core/scheme/scheme.hpp"

namespace clm3d {

using SnapToSurface = std::function<Eigen::Vector3d(const Eigen::Vector3d&)>;

// For a missing landmark whose mirror is placed: the placed one reflected across the symmetry
// plane of the placed points and snapped. nullopt when index is placed, is a mid-line point, its
// mirror is missing, or no plane can be estimated. left is the scan's direction of the subject's
// left (the plane's normal when no pair fixes it).
std::optional<Eigen::Vector3d> mirrorSuggestion(const Scheme& scheme, const LandmarkSet& points,
                                                int index, const Eigen::Vector3d& left,
                                                const SnapToSurface& snap);

// The placed points kept, every other one from guessShape (core/model/detail/shape_guess.hpp),
// snapped. Throws Error if the model's point count differs from the scheme's.
LandmarkSet firstGuess(const ShapeModel& model, const LandmarkSet& points,
                       const Eigen::AlignedBox3d& bounds, const SnapToSurface& snap);

// The imported points (snapped) replace the current ones; landmarks the import lacks keep theirs.
LandmarkSet mergeImported(const LandmarkSet& current, const LandmarkSet& imported,
                          const SnapToSurface& snap);

}  // namespace clm3d
