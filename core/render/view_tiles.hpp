// Renders of one mesh from a list of head angles, each framed the same way, as square tiles for a
// contact sheet (core/viz/contact_sheet.hpp) a person checks at a glance: the training views of a
// procedural head (clm3d synth-head), a registered sample from the front and turned (clm3d
// ict-texture). One renderer draws every tile.
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <vector>

#include "core/mesh/textured_mesh.hpp"

namespace clm3d {

struct ViewAngles {
  double pitchDeg = 0.0;
  double yawDeg = 0.0;
};

// The thesis's 15 training view centres, rows by pitch (-30, 0, 30), yaw -60..60 in each row.
std::vector<ViewAngles> trainingViewAngles();

// Each tile (size x size, BGRA, 2x supersampled, 20-degree field of view) turns the mesh about
// `pivot` (model coordinates), which stays at the centre, at a distance where the sphere of
// `radius` about it spans 1/1.1 of the tile; radius 0 = the farthest vertex from the pivot.
std::vector<cv::Mat> renderTilesAboutPivot(const TexturedMesh& mesh,
                                           const std::vector<ViewAngles>& angles, int size,
                                           const Eigen::Vector3d& pivot, double radius = 0.0);

// Each tile framed on `frameOn` (e.g. the face's vertices only) as clm3d render frames a mesh
// (frameMesh, spanning `fill` of the tile); `mesh` is what is drawn.
std::vector<cv::Mat> renderTilesFramedOn(const TexturedMesh& mesh, const TexturedMesh& frameOn,
                                         const std::vector<ViewAngles>& angles, int size,
                                         double fill);

}  // namespace clm3d
