// Registering a template mesh onto a target surface: a similarity transform from corresponding
// landmarks, then non-rigid ICP (per-vertex translations kept smooth by an edge term whose
// stiffness is annealed from stiff to loose, pulled to the target by closest points that pass a
// distance and normal test, and to the target landmarks). Used to lay the ICT-FaceKit topology
// over a textured scan so the scan's texture can be baked into ICT's UV layout.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/common/progress.hpp"
#include "core/geometry/procrustes.hpp"
#include "core/mesh/textured_mesh.hpp"
#include "core/scheme/landmark_set.hpp"

namespace clm3d {

struct NonRigidIcpOptions {
  // Weight of the edge (membrane) term per stage, relative to a data point of weight 1; each
  // stage runs iterationsPerStage closest-point / solve rounds.
  std::vector<double> stiffness{100.0, 30.0, 10.0, 3.0, 1.0};
  int iterationsPerStage = 3;
  double landmarkWeight = 10.0;  // per landmark, against a data point of weight 1
  // Closest-point matches farther than this are rejected; annealed geometrically from the first
  // to the last value over the stages (mm).
  double maxDistanceFirst = 20.0;
  double maxDistanceLast = 6.0;
  double minNormalDot = 0.5;  // cosine between template vertex and target triangle normals
  bool allowScale = true;     // the landmark similarity may scale the template
};

struct NonRigidIcpResult {
  std::vector<Eigen::Vector3f> positions;  // registered template positions (target frame)
  std::vector<Eigen::Vector3f> rest;       // template positions after the similarity alone
  Similarity3 similarity;                  // template -> target from the landmarks
  // Over the data vertices, after registration: distance to the nearest target surface point for
  // those that have one within maxDistanceLast (mm), and their share of the data vertices.
  double meanDistance = 0.0, maxDistance = 0.0, matchedFraction = 0.0;
  // Per landmark, distance between the template landmark and the target landmark (mm; NaN where
  // either is missing), after the similarity and after the registration.
  std::vector<double> landmarkResidualsRigid, landmarkResiduals;
};

// Registers `templ` onto `target`. `templLandmarks` are points on the template surface (each is
// bound to its nearest template triangle), `targetLandmarks` the same scheme's points on the
// target; points missing in either are skipped (at least 3 common ones needed). `dataVertices`
// selects the template vertices pulled towards the target surface (empty = all); the others
// follow the edge term. Template vertices at the same position (UV seams) move as one. Throws
// InputError for empty meshes, mismatched landmark counts or too few common landmarks; Cancelled.
NonRigidIcpResult registerNonRigid(const TexturedMesh& templ, const LandmarkSet& templLandmarks,
                                   const TexturedMesh& target, const LandmarkSet& targetLandmarks,
                                   const std::vector<bool>& dataVertices = {},
                                   const NonRigidIcpOptions& options = {},
                                   const ProgressCallback& progress = {},
                                   const CancelToken* cancel = nullptr);

// Carries a registration over to points that were not registered (e.g. eyeballs inside a
// registered face): each point moves by the similarity plus the inverse-distance weighted
// displacement (positions - rest) of its `neighbours` nearest registered vertices in `rest`.
std::vector<Eigen::Vector3f> followRegistration(const NonRigidIcpResult& registration,
                                                const std::vector<Eigen::Vector3f>& points,
                                                int neighbours = 8);

}  // namespace clm3d
