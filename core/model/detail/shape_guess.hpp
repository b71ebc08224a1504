// A first guess of every landmark of a scan from a shape model: the annotator places a few points
// by hand and the model fills in the rest (each then snapped to the surface by the caller), so
// annotating a scan becomes correcting a guess instead of placing 25 points from nothing.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/model/shape_model.hpp"
#include "core/scheme/landmark_set.hpp"

namespace clm3d {

struct ShapeGuess {
  Eigen::Matrix3Xd points;        // 3 x n, in the scan's coordinates
  bool fromPlacedPoints = false;  // false: the frontal guess from the bounds
};

// With >= 3 placed points (not all on one line): the model shape (mean plus the modes that best
// explain the placed points, kept within the model's limits) aligned to them by a similarity.
// Otherwise a frontal guess: the mean shape at its own scale, centred on the bounds across
// (x) and up (y), its most forward point at the front of the bounds (the scan is expected in
// model axes: +y up, +z out of the face). Throws Error if placed's size differs from the model's.
ShapeGuess guessShape(const ShapeModel& model, const LandmarkSet& placed,
                      const Eigen::AlignedBox3d& bounds);

}  // namespace clm3d
