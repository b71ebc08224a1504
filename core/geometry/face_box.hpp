// The face size that errors at large pose are normalised by: sqrt(width x height) of the box
// around a face's present points (papers on AFLW2000-3D do the same, because the eye distance
// shrinks as the head turns). One definition for clm3d eval's NMJ and eval-points' box error.
#pragma once

#include <Eigen/Core>

namespace clm3d {

// Columns with a non-finite coordinate are missing and left out; 0 for fewer than two present
// points or a box without width or height.
double faceBoxSize(const Eigen::Matrix2Xd& points);

}  // namespace clm3d
