// A dense morphable face for photo profiling: one mesh topology whose vertex positions are
// neutral + sum_k w_k mode_k (weights a priori N(0, 1)), with the scheme's landmarks at known
// positions of the same linear model. Made from the ICT-FaceKit model (identity components and a
// few expressions) for real photos, or from any textured mesh with its landmarks (no modes unless
// the caller adds them), which is how the always-run tests profile a procedural head.
// A DenseFace is a plain value: nothing else needs to stay alive.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/dataset/ict_textured.hpp"
#include "core/mesh/textured_mesh.hpp"
#include "core/scheme/landmark_set.hpp"

namespace clm3d {

struct DenseFace {
  // Topology: triangles over mesh vertices; mesh vertex v sits at column column[v]. The mesh's
  // positions are the neutral's; its UVs and texture are not used (profiling textures it anew).
  TexturedMesh mesh;
  std::vector<int> column;
  // Model coordinates (pose.hpp: mm, +x the subject's left, +y up, +z out of the face, landmark 1
  // at the origin). Columns may include points that no triangle uses (a landmark off the vertices).
  Eigen::Matrix3Xd neutral;
  std::vector<Eigen::Matrix3Xd> modes;  // displacement of every column per unit weight
  std::vector<std::string> modeNames;
  std::vector<int> landmarkColumns;  // per scheme point (thesis25): its column, -1 = missing
  // Triangles beyond the face (the back of the head and the neck): not part of the face region
  // the background replaces, and where the photo does not show them (the back of the head, for a
  // frontal photo) they wear the filled background's colours. Empty = none.
  std::vector<bool> outerTriangle;
  // Per column: the column nearest to its mirror image (x -> -x), where a side the photo does not
  // show takes its texture from; empty = no mirror filling.
  std::vector<int> mirrorColumn;

  int columnCount() const { return static_cast<int>(neutral.cols()); }
  // neutral + sum_k weights[k] * modes[k]; weights must have modes.size() entries.
  Eigen::Matrix3Xd at(const Eigen::VectorXd& weights) const;
  // The scheme's landmarks of those positions (3D; missing where the column is -1).
  LandmarkSet landmarksAt(const Eigen::Matrix3Xd& columns) const;
  // The mesh with each vertex at its column's position (normals recomputed; UVs and texture as
  // given to the caller's later steps: copied from `mesh`).
  TexturedMesh meshAt(const Eigen::Matrix3Xd& columns) const;
};

// What of the ICT model a profile fits.
struct IctDenseSettings {
  int identityModes = 40;  // the first N identity components (the model has 100)
  // Expression blendshapes fitted too (names of the model's OBJ files); each weight's prior
  // standard deviation is expressionSd (the blendshapes span 0..1).
  std::vector<std::string> expressions{"jawOpen", "mouthSmile_L", "mouthSmile_R", "eyeBlink_L",
                                       "eyeBlink_R"};
  double expressionSd = 0.5;
};

// The ICT model read by loadIctMeshModel (its kept regions: face, head and neck, mouth and eye
// sockets, eyeballs), moved so that landmark 1 is at the origin. The head-and-neck triangles are
// outer ones; mirror columns found on the neutral's surface.
// Throws InputError naming the model for an unknown expression or landmark 1 missing.
DenseFace denseFaceFromIct(const IctMeshModel& model, const IctDenseSettings& settings = {});

// A mesh with its 3D landmarks (model coordinates) as a dense face without modes: one column per
// mesh vertex, then one per present landmark; mirror columns found on the mesh's surface. Throws
// InputError for an invalid mesh.
DenseFace denseFaceFromMesh(const TexturedMesh& mesh, const LandmarkSet& landmarks);

// Per column, the column of the mesh vertex nearest to its mirror image (x -> -x) on the
// neutral's surface (the nearest corner of the nearest triangle within maxDistanceMm; itself when
// none is that near).
std::vector<int> mirrorColumns(const DenseFace& face, double maxDistanceMm = 10.0);

}  // namespace clm3d
