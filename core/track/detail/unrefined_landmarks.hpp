// The landmarks a fit's point refiner does not move (those its photos do not mark exactly: the ear
// lobes, cheeks and chin sides of thesis25), placed on the outline where the model's 3D shape
// fitted to the refined points puts them. The refiner corrects where the search put the inner
// face, its size included; left where the search put them, the outline kept the search's error:
// on AFLW faces the ear lobes sat 0.14 of the face box inside the truth while the inner points
// were within 0.05 (docs/real-faces.md, "The outline follows the refined points"). Photos fitted
// from a detector's box and every tracked frame's row take it; a photo started from marked points
// keeps the outline it was given (from the AFLW truth, the shape's ear lobes were 0.003-0.005 of
// the box worse than the given ones).
#pragma once

#include "core/fit/fitter.hpp"
#include "core/geometry/camera.hpp"
#include "core/model/clm_model.hpp"

namespace clm3d {

// Moves `fit`'s points of the landmarks `model`'s refiner does not refine, where they lie outside
// the refined points' convex hull, to the projection of the state nearest fit.state that
// reproduces the refined ones (stateNearPoints); `camera` is the fitted image's. Inside the hull
// (mid_eyes) the search's point stays. Nothing changes for a fit the refiner did not move or when
// the refined points cannot place the model. fit.state stays the search's.
void placeUnrefinedLandmarks(const ClmModel& model, const Camera& camera, FitResult& fit);

}  // namespace clm3d
