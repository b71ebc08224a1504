// The 3D shape model (point distribution model): s = s_mean + P_s b_s, in model coordinates
// (millimetres, landmark 1 at the origin, +y up, +z out of the face). Built from landmark sets by
// generalised similarity Procrustes and PCA (thesis section 3.2); the fitter keeps b_s within
// +-limitSd standard deviations. dims = 2 gives the single-view 2D baseline (z = 0 everywhere).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/scheme/landmark_set.hpp"
#include "core/scheme/scheme.hpp"

namespace clm3d {

struct ShapeModel {
  Eigen::Matrix3Xd meanShape;  // 3 x n
  Eigen::MatrixXd modes;       // 3n x K, orthonormal columns, point-major (x1,y1,z1,x2,...)
  Eigen::VectorXd variances;   // K, descending
  double limitSd = 3.0;        // |b_k| <= limitSd * sqrt(variances[k])
  int dims = 3;                // 3, or 2 for the single-view baseline (z = 0 everywhere)

  int pointCount() const { return static_cast<int>(meanShape.cols()); }
  int modeCount() const { return static_cast<int>(modes.cols()); }
  // meanShape + modes * b, as 3 x n. b must have modeCount() entries.
  Eigen::Matrix3Xd shape(const Eigen::VectorXd& b) const;
  // Clamps each b_k into [-limitSd sqrt(variances[k]), +limitSd sqrt(variances[k])].
  void clamp(Eigen::VectorXd& b) const;
};

struct ShapeModelSettings {
  double varianceKept = 0.98;  // share of the total variance the kept modes explain
  bool mirror = false;         // also train on each shape mirrored (x -> -x, left/right swapped)
  double limitSd = 3.0;
  int dims = 3;      // 2: use x, y only (z = 0) of frontal shapes, for the 2D baseline
  int maxModes = 0;  // > 0: keep at most this many modes
};

// shapes: landmark sets of the scheme (any may miss points; a shape needs >= 3 present points to be
// used; missing points are imputed from the model iteratively, EM-style). Generalised Procrustes
// aligns every shape to the running mean on its present points; the mean is re-centred on
// landmark 1 (index 0; the centroid if no shape has it), its size is the mean size (RMS distance
// to the centroid) of the training shapes, and its orientation is that of the first usable shape
// (which is expected in model coordinates: +y up, +z out of the face). Throws Error if fewer than
// 2 shapes are usable or a shape's size does not match the scheme.
ShapeModel buildShapeModel(const std::vector<LandmarkSet>& shapes, const Scheme& scheme,
                           const ShapeModelSettings& settings = {});

}  // namespace clm3d
