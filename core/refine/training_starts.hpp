// Random misplacements of a face's true points, the starts the point refiner and its check learn
// from: the points moved together by a similarity (shift, scale, roll), as a search misplaces a
// whole face, and each by a small offset of its own; and how far such points end from the truth
// (what labels the check's training samples right or wrong).
#pragma once

#include <Eigen/Core>
#include <random>

namespace clm3d {

struct StartPerturbation {
  double shift = 0.08;   // SD of the shift, eye distances
  double scale = 0.06;   // SD of the log of the scale
  double roll = 0.1;     // SD of the roll, radians
  double jitter = 0.03;  // SD of each point's own offset, eye distances
};

// `truth` (2 x N) moved by a draw of `perturbation`; the scale and roll turn about the points'
// centroid.
Eigen::Matrix2Xd perturbedPoints(const Eigen::Matrix2Xd& truth, double eyeDistance,
                                 const StartPerturbation& perturbation, std::mt19937_64& random);

// The mean distance between matching columns of `points` and `truth`, over `eyeDistance`.
double meanPointError(const Eigen::Matrix2Xd& points, const Eigen::Matrix2Xd& truth,
                      double eyeDistance);

}  // namespace clm3d
